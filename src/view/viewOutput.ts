import {
  AgXToneMapping,
  NeutralToneMapping,
  NoToneMapping,
  type ToneMapping as ThreeToneMapping,
  Vector2,
  type WebGLRenderer,
} from 'three';
import { type FilmSettings, type ToneMapping, toneMappingOf } from '../settings/filmSettings.ts';
import { drawingBufferSpace } from './displaySpace.ts';

const SIZE = new Vector2();
const TONE_MAPPINGS: Record<ToneMapping, ThreeToneMapping> = { none: NoToneMapping, agx: AgXToneMapping, neutral: NeutralToneMapping };

/**
 * What a view hands the display: its size, its tone mapping and its drawing buffer's space. Views
 * may share a renderer, so each sets its own on the renderer before it draws.
 */
export class ViewOutput {
  /** Whether the canvas really shows Display P3 (false where the browser cannot). */
  displayIsP3 = false;
  private toneMapping: ThreeToneMapping = NoToneMapping;

  /**
   * Takes the film drawn (`auto` tone mapping follows the environment drawn) and whether the canvas
   * shows Display P3 (the frame's: drawnFrame.ts); returns whether the tone mapping changed, which
   * needs new programs.
   */
  take(s: FilmSettings, displayP3: boolean): boolean {
    this.displayIsP3 = displayP3;
    const toneMapping = TONE_MAPPINGS[toneMappingOf(s)];
    const changed = toneMapping !== this.toneMapping;
    this.toneMapping = toneMapping;
    return changed;
  }

  /** Sizes `renderer`'s canvas to the view (CSS pixels) and its pixel ratio, where they differ. */
  fit(renderer: WebGLRenderer, size: { readonly width: number; readonly height: number; readonly pixelRatio: number }): void {
    if (renderer.getPixelRatio() !== size.pixelRatio) renderer.setPixelRatio(size.pixelRatio);
    const drawn = renderer.getSize(SIZE);
    if (drawn.x !== size.width || drawn.y !== size.height) renderer.setSize(size.width, size.height, false);
  }

  /** Sets the tone mapping on `renderer` (cheap: three keys programs by it). */
  toneMap(renderer: WebGLRenderer): void {
    renderer.toneMapping = this.toneMapping;
  }

  /** Sets the drawing buffer's space on `renderer`: only on a change, as a new space reallocates the buffer, which waits for the GPU's queued work. */
  setSpace(renderer: WebGLRenderer): void {
    const space = drawingBufferSpace(this.displayIsP3);
    if (renderer.outputColorSpace !== space) renderer.outputColorSpace = space;
  }

  /** What of the output picks a program (besides the materials' defines): the tone mapping. */
  get programKey(): number {
    return this.toneMapping;
  }
}
