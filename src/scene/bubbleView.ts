import {
  BackSide,
  ColorManagement,
  Mesh,
  PerspectiveCamera,
  Scene,
  ShaderMaterial,
  SphereGeometry,
  SRGBColorSpace,
  Vector2,
  WebGLRenderer,
} from 'three';
import { DisplayP3ColorSpace, DisplayP3ColorSpaceImpl } from 'three/addons/math/ColorSpaces.js';
import { createBubbleMaterial, releaseFilmColorTextures, updateBubbleUniforms } from '../render/bubbleMaterial.ts';
import { DEFAULT_FILM_QUALITY, type FilmQuality } from '../render/filmQuality.ts';
import { FilmTable } from '../render/filmTable.ts';
import { type FilmSettings } from '../render/filmSettings.ts';
import { shaderSource } from '../render/shaderSource.ts';
import { FilmProbe, type ProbeReading } from './probe.ts';

ColorManagement.define({ [DisplayP3ColorSpace]: DisplayP3ColorSpaceImpl });

/** The camera sits on +z; the unit bubble (seen under 2·asin(1/4) = 29°) fills ~83 % of the 35° view's height. */
const CAMERA_DISTANCE = 4;
const FOV_DEG = 35;
const SIZE = new Vector2();

/** A WebGL2 renderer for bubbles on a canvas (the drawing buffer is kept for screenshots and reads). */
export const createBubbleRenderer = (canvas: HTMLCanvasElement): WebGLRenderer =>
  new WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });

/**
 * A bubble: camera, environment, the film material and its table, drawn by a renderer that may
 * be its own or shared by several views (then programs and spectral textures are compiled and
 * uploaded once). Renders on demand: `render()` draws one frame; the caller loops only while
 * animating.
 */
export class BubbleView {
  readonly camera = new PerspectiveCamera(FOV_DEG, 1, 0.1, 100);
  readonly scene = new Scene();
  readonly table: FilmTable;
  readonly bubble: Mesh<SphereGeometry, ShaderMaterial>;
  private readonly sky: Mesh<SphereGeometry, ShaderMaterial>;
  private readonly filmProbe = new FilmProbe();
  /** The view's size in CSS pixels and its pixel ratio. */
  private size = { width: 1, height: 1, pixelRatio: 1 };
  /** Whether the canvas really shows Display P3 (false where the browser cannot). */
  displayIsP3 = false;
  private settings: FilmSettings;

  constructor(
    readonly renderer: WebGLRenderer,
    settings: FilmSettings,
    readonly quality: FilmQuality = DEFAULT_FILM_QUALITY,
  ) {
    this.settings = settings;
    this.table = new FilmTable(quality);
    this.camera.position.set(0, 0, CAMERA_DISTANCE);
    this.bubble = new Mesh(new SphereGeometry(1, 128, 64), createBubbleMaterial(settings, quality));
    this.sky = new Mesh(
      new SphereGeometry(50, 32, 16),
      new ShaderMaterial({
        side: BackSide,
        defines: { TFC_ENVIRONMENT: 1 },
        vertexShader:
          'varying vec3 vDirection; void main() { vDirection = position; gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0); }',
        fragmentShader: `${shaderSource('environment.glsl')}
varying vec3 vDirection;
void main() { gl_FragColor = vec4(environmentRadiance(vDirection), 1.0);
#include <colorspace_fragment>
}`,
      }),
    );
    this.scene.add(this.sky, this.bubble);
    // After a lost context comes back, three re-creates programs and re-uploads textures by
    // itself; the table, drawn on the GPU, is gone and must be drawn again.
    renderer.domElement.addEventListener('webglcontextrestored', this.rebuildTable);
    this.apply(settings);
  }

  private readonly rebuildTable = () => this.table.invalidate();

  get current(): FilmSettings {
    return this.settings;
  }

  /** Takes new settings (already validated). Cheap: the table is brought up to date when drawn. */
  apply(s: FilmSettings): void {
    this.settings = s;
    const wantP3 = s.space === 'display-p3' || s.space === 'wide-gamut';
    this.renderer.outputColorSpace = wantP3 ? DisplayP3ColorSpace : SRGBColorSpace;
    const gl = this.renderer.getContext();
    this.displayIsP3 = wantP3 && 'drawingBufferColorSpace' in gl && gl.drawingBufferColorSpace === 'display-p3';
    if (wantP3 && !this.displayIsP3) this.renderer.outputColorSpace = SRGBColorSpace;
    this.sky.visible = s.env === 'sky';
    updateBubbleUniforms(this.bubble.material, s, this.quality, s.mode === 'table' ? this.table : null, this.displayIsP3);
  }

  /** Rebuilds the table if a parameter it depends on changed since it was drawn (coarsely first if `quick`). */
  private syncTable(quick = false): void {
    if (this.settings.mode !== 'table' || !this.table.update(this.renderer, this.settings, quick)) return;
    this.table.bind(this.bubble.material.uniforms);
  }

  /** Whether the last frame was drawn from a coarse table (FilmTable): the next one will be full. */
  get coarse(): boolean {
    return this.settings.mode === 'table' && this.table.coarse;
  }

  /** Whether the renderer's WebGL context is lost (nothing can be drawn or read until it is restored). */
  get contextLost(): boolean {
    return this.renderer.getContext().isContextLost();
  }

  /** Sets the view's size (CSS pixels) and pixel ratio. */
  resize(width: number, height: number, pixelRatio = 1): void {
    this.size = { width: Math.max(1, width), height: Math.max(1, height), pixelRatio };
    this.camera.aspect = this.size.width / this.size.height;
    this.camera.updateProjectionMatrix();
  }

  /**
   * Draws one frame into the renderer's canvas, sized to this view first. `quick` (the app's
   * frames): a table that has to be rebuilt is drawn coarsely first, so a change shows in the next
   * frame; the frame after completes it.
   */
  render(quick = false): void {
    const { width, height, pixelRatio } = this.size;
    const r = this.renderer;
    if (r.getPixelRatio() !== pixelRatio) r.setPixelRatio(pixelRatio);
    const drawn = r.getSize(SIZE);
    if (drawn.x !== width || drawn.y !== height) r.setSize(width, height, false);
    if (this.contextLost) return;
    this.syncTable(quick);
    r.render(this.scene, this.camera);
  }

  /** The film at a point of the view (fractions from the top left), or null off the bubble. */
  probe(fx: number, fy: number): ProbeReading | null {
    this.syncTable();
    return this.filmProbe.read(this.renderer, this.camera, this.bubble, this.size, fx, fy);
  }

  /** Frees this view's GPU resources (not the renderer, which may be shared). */
  dispose(): void {
    this.renderer.domElement.removeEventListener('webglcontextrestored', this.rebuildTable);
    this.filmProbe.dispose();
    this.table.dispose();
    this.bubble.geometry.dispose();
    releaseFilmColorTextures(this.bubble.material);
    this.bubble.material.dispose();
    this.sky.geometry.dispose();
    this.sky.material.dispose();
  }
}
