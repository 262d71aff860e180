import type { Mesh, PerspectiveCamera, Scene, ShaderMaterial, SphereGeometry, WebGLRenderer } from 'three';
import type { FilmTable } from '../film/filmTable.ts';
import type { FilmSettings } from '../settings/filmSettings.ts';
import { compileFramePrograms } from './framePrograms.ts';
import type { FilmProbe } from './probe.ts';
import { ProgramsInParallel } from './programsInParallel.ts';

/** What of a view picks and compiles its frame's programs. */
interface ProgramsOf {
  readonly renderer: WebGLRenderer;
  readonly camera: PerspectiveCamera;
  readonly scene: Scene;
  readonly bubble: Mesh<SphereGeometry, ShaderMaterial>;
  readonly backgroundShown: Mesh<SphereGeometry, ShaderMaterial> | null;
  readonly table: FilmTable;
  readonly drawsTable: boolean;
  readonly filmDrawn: FilmSettings;
}

/**
 * The programs a view's next frame draws with (ProgramsInParallel): the bubble's, the background's
 * where it is drawn, the table pass's where the method reads a table, and the probe's that follows.
 */
export class ViewPrograms {
  private readonly inParallel = new ProgramsInParallel();

  constructor(private readonly view: ProgramsOf) {}

  /** Whether the programs of the next frame are ready; if not, starts compiling them (once). `outputKey`: the tone mapping's part (ViewOutput.programKey). */
  ready(outputKey: number, probe: FilmProbe): boolean {
    return this.inParallel.ready(this.key(outputKey), () => this.compileAll(probe));
  }

  /** Compiles the programs of the next frame unless they are ready; resolves when they are. */
  compile(outputKey: number, probe: FilmProbe): Promise<void> {
    return this.inParallel.compile(this.key(outputKey), () => this.compileAll(probe));
  }

  /** Whether programs are being compiled for a frame not yet drawn. */
  get busy(): boolean {
    return this.inParallel.busy;
  }

  /** Forgets what was compiled (a restored context has none of it). */
  forget(): void {
    this.inParallel.forget();
  }

  /**
   * What picks the programs a frame draws with: the materials' defines and the tone mapping. Not the
   * drawing buffer's space, which three keys them by too: setting it reallocates the buffer, so the
   * frame shown could not be kept; a change of space compiles in its own frame.
   */
  private key(outputKey: number): string {
    const v = this.view;
    const table = v.drawsTable ? v.table.passKey(v.filmDrawn) : null;
    return JSON.stringify([v.bubble.material.defines, v.backgroundShown?.material.defines ?? null, table, outputKey]);
  }

  private compileAll(probe: FilmProbe): Promise<void> {
    const v = this.view;
    return compileFramePrograms(
      v.renderer,
      v.camera,
      v.scene,
      [v.bubble, ...(v.backgroundShown ? [v.backgroundShown] : [])],
      [probe.compileAsync(v.renderer, v.camera, v.bubble), v.drawsTable ? v.table.prepare(v.renderer, v.filmDrawn) : null],
    );
  }
}
