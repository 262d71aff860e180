import {
  AgXToneMapping,
  ColorManagement,
  Mesh,
  NeutralToneMapping,
  NoToneMapping,
  PerspectiveCamera,
  Raycaster,
  Scene,
  ShaderMaterial,
  Sphere,
  SphereGeometry,
  SRGBColorSpace,
  type ToneMapping as ThreeToneMapping,
  Vector2,
  Vector3,
  WebGLRenderer,
} from 'three';
import { DisplayP3ColorSpace, DisplayP3ColorSpaceImpl } from 'three/addons/math/ColorSpaces.js';
import { createBubbleMaterial, updateBubbleUniforms } from '../bubble/bubbleMaterial.ts';
import { createFieldState } from '../bubble/fieldStates.ts';
import type { FieldName } from '../fields/fields.ts';
import type { FieldState } from '../fields/thicknessField.ts';
import { releaseFilmColorTextures } from '../film/filmColor.ts';
import { createBackgroundMaterial, updateBackgroundMaterial } from '../bubble/environmentMaterial.ts';
import { environmentTexture, loadEnvironmentPixels, releaseEnvironmentTexture } from '../bubble/environmentMaps.ts';
import { DEFAULT_FILM_QUALITY, type FilmQuality } from '../settings/filmQuality.ts';
import { FilmTable } from '../film/filmTable.ts';
import { spectralTransformReady } from '../film/spectralTransformTexture.ts';
import { type FilmSettings, type HdrEnvironment, type ToneMapping, isHdrEnvironment, toneMappingOf } from '../settings/filmSettings.ts';
import { FilmProbe, type ProbeReading } from './probe.ts';
import { ProgramsInParallel } from './programsInParallel.ts';
import { linkFailures } from '../gpu/linkFailures.ts';
import { FLOW_PARAMETERS } from '../physics/flow/flowParameters.ts';

ColorManagement.define({ [DisplayP3ColorSpace]: DisplayP3ColorSpaceImpl });

/** The camera sits on +z; the unit bubble (seen under 2·asin(1/4) = 29°) fills ~83 % of the 35° view's height. */
const CAMERA_DISTANCE = 4;
const FOV_DEG = 35;
const SIZE = new Vector2();
const UNIT_SPHERE = new Sphere(new Vector3(), 1);
/** The fastest blow: the wind's upper end. */
const BLOW_MAX_MPS = FLOW_PARAMETERS.find((r) => r.key === 'windMps')!.domain.max;
const TONE_MAPPINGS: Record<ToneMapping, ThreeToneMapping> = { none: NoToneMapping, agx: AgXToneMapping, neutral: NeutralToneMapping };

/** Where the view's HDR environment stands: shown, on its way (`sky` meanwhile), or failed (`sky` instead). */
export type EnvironmentStatus =
  | { readonly state: 'shown' }
  | { readonly state: 'loading'; readonly env: HdrEnvironment }
  | { readonly state: 'failed'; readonly env: HdrEnvironment; readonly reason: string };

/** Whether each renderer's canvas can show Display P3, once asked. */
const displayP3Support = new WeakMap<WebGLRenderer, boolean>();

/**
 * Whether `renderer`'s canvas can show Display P3: whether its drawing buffer takes the space
 * (browsers without the attribute, or that ignore the value, stay sRGB). Asked once per renderer,
 * as setting the space reallocates the drawing buffer.
 */
function drawsDisplayP3(renderer: WebGLRenderer): boolean {
  let supported = displayP3Support.get(renderer);
  if (supported === undefined) {
    const gl = renderer.getContext();
    const space = renderer.outputColorSpace;
    renderer.outputColorSpace = DisplayP3ColorSpace;
    supported = 'drawingBufferColorSpace' in gl && gl.drawingBufferColorSpace === 'display-p3';
    renderer.outputColorSpace = space;
    displayP3Support.set(renderer, supported);
  }
  return supported;
}

/**
 * A WebGL2 renderer for bubbles on a canvas (the drawing buffer is kept for screenshots and reads).
 * Where the GPU compiles in parallel, its views check their programs' links themselves (linkFailures.ts)
 * instead of three's check at the first draw, which would wait for the GPU.
 */
export function createBubbleRenderer(canvas: HTMLCanvasElement): WebGLRenderer {
  const renderer = new WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
  if (renderer.extensions.has('KHR_parallel_shader_compile')) renderer.debug.checkShaderErrors = false;
  return renderer;
}

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
  private readonly background: Mesh<SphereGeometry, ShaderMaterial>;
  /** HDR environments this view is fetching (one request each, however many frames ask meanwhile). */
  private readonly loadingEnvironments = new Set<HdrEnvironment>();
  /** HDR environments that failed to load in this view, with why (`sky` is shown instead). */
  private readonly failedEnvironments = new Map<HdrEnvironment, string>();
  /** The tone mapping of the environment shown (`auto`: none for the sky standing in for an HDR map). */
  private toneMapping: ThreeToneMapping = NoToneMapping;
  /** Called when an HDR environment this view asked for arrives or fails (the caller redraws). */
  onEnvironmentChange: (() => void) | null = null;
  private readonly filmProbe = new FilmProbe();
  /** The programs of the frames to come, compiled without blocking where the GPU compiles in parallel. */
  private readonly programs = new ProgramsInParallel();
  /** The view's size in CSS pixels and its pixel ratio. */
  private size = { width: 1, height: 1, pixelRatio: 1 };
  /** Whether the canvas really shows Display P3 (false where the browser cannot). */
  displayIsP3 = false;
  private settings: FilmSettings;
  /**
   * The light the film is drawn in (null before the first frame). In `fourier` mode a new light's
   * spectral transform comes from a worker; until it arrives the frames keep the light shown.
   */
  private lightShown: Pick<FilmSettings, 'illuminant' | 'normalization'> | null = null;
  private lightWaiting = false;
  /** The simulation of an evolving field's film (null for another field): made when the field is shown, dropped when it is left. */
  private fieldState: { readonly field: FieldName; readonly state: FieldState } | null = null;
  /** Whether the last frame drew an evolving film short of the settings' time (more frames bring it there). */
  filmBehind = false;

  constructor(
    readonly renderer: WebGLRenderer,
    settings: FilmSettings,
    readonly quality: FilmQuality = DEFAULT_FILM_QUALITY,
  ) {
    this.settings = settings;
    this.table = new FilmTable(quality);
    this.camera.position.set(0, 0, CAMERA_DISTANCE);
    this.bubble = new Mesh(new SphereGeometry(1, 128, 64), createBubbleMaterial(settings, quality));
    this.background = new Mesh(new SphereGeometry(50, 64, 32), createBackgroundMaterial());
    this.scene.add(this.background, this.bubble);
    // After a lost context comes back, three re-creates programs and re-uploads textures by
    // itself; the table and an evolving film, drawn on the GPU, are gone and must be drawn again.
    renderer.domElement.addEventListener('webglcontextrestored', this.rebuildTable);
    this.apply(settings);
  }

  private readonly rebuildTable = () => {
    this.programs.forget();
    this.table.invalidate();
    this.fieldState?.state.invalidate();
  };

  /** The time (s) the evolving film drawn shows (less than the settings' while behind), or null for another field. */
  get filmTimeSeconds(): number | null {
    return this.fieldState?.state.timeSeconds ?? null;
  }

  /** The evolving field's simulation, if the field shown evolves (for tests and the benchmark). */
  get evolvingFilm(): FieldState | null {
    return this.fieldState?.state ?? null;
  }

  get current(): FilmSettings {
    return this.settings;
  }

  /** Takes new settings (already validated). Cheap: the table is brought up to date when drawn. */
  apply(s: FilmSettings): void {
    this.settings = s;
    if (this.fieldState?.field !== s.field) {
      this.fieldState?.state.dispose();
      const state = createFieldState(s.field, this.renderer);
      this.fieldState = state && { field: s.field, state };
      this.filmBehind = false;
    }
    this.displayIsP3 = (s.space === 'display-p3' || s.space === 'wide-gamut') && drawsDisplayP3(this.renderer);
    const map = isHdrEnvironment(s.env) ? environmentTexture(s.env, this) : null;
    if (!map) releaseEnvironmentTexture(this);
    if (isHdrEnvironment(s.env) && !map && !this.failedEnvironments.has(s.env) && !this.loadingEnvironments.has(s.env)) this.load(s.env);
    // Until an HDR map arrives (or if it failed), the procedural sky stands in.
    const shown = isHdrEnvironment(s.env) && !map ? { ...s, env: 'sky' as const } : s;
    const toneMapping = TONE_MAPPINGS[toneMappingOf(shown)];
    if (toneMapping !== this.toneMapping) {
      // three keeps a program per tone mapping a material was drawn with, until the material is
      // disposed: dispose both (set up anew on their next draw), so switching holds one program each.
      this.bubble.material.dispose();
      this.background.material.dispose();
      this.toneMapping = toneMapping;
    }
    this.background.visible = shown.env !== 'none';
    updateBackgroundMaterial(this.background.material, shown, map);
    const light = this.filmLight(s);
    updateBubbleUniforms(
      this.bubble.material,
      { ...shown, ...light },
      this.quality,
      s.mode === 'table' ? this.table : null,
      this.displayIsP3,
      map,
    );
  }

  /** The light to draw `s`'s film in: its own, or in `fourier` mode the one shown while its transform is computed. */
  private filmLight(s: FilmSettings): Pick<FilmSettings, 'illuminant' | 'normalization'> {
    const wanted = { illuminant: s.illuminant, normalization: s.normalization };
    const shown = this.lightShown;
    this.lightWaiting =
      s.mode === 'fourier' &&
      shown !== null &&
      JSON.stringify(wanted) !== JSON.stringify(shown) &&
      !spectralTransformReady(s.illuminant, s.normalization);
    if (this.lightWaiting) return shown!;
    this.lightShown = wanted;
    return wanted;
  }

  /** Fetches an HDR environment; when it arrives (or fails) the view shows it (or says why not). */
  private load(env: HdrEnvironment): void {
    this.loadingEnvironments.add(env);
    loadEnvironmentPixels(env).then(
      () => this.environmentArrived(env),
      (error: unknown) => {
        this.failedEnvironments.set(env, error instanceof Error ? error.message : String(error));
        this.environmentArrived(env);
      },
    );
  }

  private environmentArrived(env: HdrEnvironment): void {
    this.loadingEnvironments.delete(env);
    if (this.disposed || this.settings.env !== env) return;
    this.apply(this.settings);
    this.onEnvironmentChange?.();
  }

  /**
   * Compiles the view's programs (bubble, background, the table pass) without blocking where the GPU
   * compiles in parallel (KHR_parallel_shader_compile), the light's textures made meanwhile;
   * resolves when the first frame can be drawn without waiting on a compile.
   */
  async prepare(): Promise<void> {
    // Without the extension (SwiftShader) compiling is blocking however it is asked for: the first frame does it.
    if (!this.compilesInParallel) return;
    this.renderer.toneMapping = this.toneMapping;
    this.setDrawingBufferSpace();
    await this.programs.compile(this.programsKey(), () => this.compilePrograms());
  }

  private get compilesInParallel(): boolean {
    return this.renderer.extensions.has('KHR_parallel_shader_compile');
  }

  /**
   * What picks the programs a frame draws with: the materials' defines and the tone mapping. Not the
   * drawing buffer's space, which three keys them by too: setting it reallocates the buffer, so the
   * frame shown could not be kept; a change of space compiles in its own frame.
   */
  private programsKey(): string {
    const background = this.background.visible ? this.background.material.defines : null;
    const table = this.settings.mode === 'table' ? this.table.passKey(this.settings) : null;
    return JSON.stringify([this.bubble.material.defines, background, table, this.toneMapping]);
  }

  /**
   * Compiles the programs of the next frame (bubble, background, the table pass) and of the probe
   * that follows it, where the GPU compiles in parallel without blocking; the light's textures are made meanwhile.
   */
  private compilePrograms(): Promise<unknown> {
    // Only what the frame draws: three compiles hidden meshes too (the background with env=none),
    // a program no frame would use, and one a restored context would not make again.
    const drawn = [this.bubble, ...(this.background.visible ? [this.background] : [])];
    return Promise.all([
      ...drawn.map((mesh) => this.renderer.compileAsync(mesh, this.camera, this.scene)),
      this.filmProbe.compileAsync(this.renderer, this.camera, this.bubble),
      this.settings.mode === 'table' ? this.table.prepare(this.renderer, this.settings) : null,
    ]).then(() => {
      if (!this.renderer.debug.checkShaderErrors) for (const failure of linkFailures(this.renderer)) console.error(failure);
    });
  }

  /** The drawing buffer's space for this view: only on a change, as a new space reallocates the buffer, which waits for the GPU's queued work. */
  private setDrawingBufferSpace(): void {
    const space = this.displayIsP3 ? DisplayP3ColorSpace : SRGBColorSpace;
    if (this.renderer.outputColorSpace !== space) this.renderer.outputColorSpace = space;
  }

  /** Whether the HDR environment asked for is shown, still on its way, or failed. */
  get environmentStatus(): EnvironmentStatus {
    const env = this.settings.env;
    if (!isHdrEnvironment(env) || this.background.material.defines.TFC_ENVIRONMENT === 2) return { state: 'shown' };
    const reason = this.failedEnvironments.get(env);
    return reason === undefined ? { state: 'loading', env } : { state: 'failed', env, reason };
  }

  /** Rebuilds the table if a parameter it depends on changed since it was drawn (coarsely first if `quick`). */
  private syncTable(quick = false): void {
    if (this.settings.mode !== 'table' || !this.table.update(this.renderer, this.settings, quick)) return;
    this.table.bind(this.bubble.material.uniforms);
  }

  /**
   * Whether the last frame was drawn from a coarse table, or in the previous light while the new
   * light's transform is computed (FilmTable; `fourier` mode), or kept while the programs of the
   * next are compiled: more frames follow until one is full.
   */
  get coarse(): boolean {
    return (this.settings.mode === 'table' && this.table.coarse) || this.lightWaiting || this.programs.busy;
  }

  /**
   * Blows air on an evolving film at a point of the view (fractions from the top left) along a
   * screen velocity (CSS pixels per second, right and down), as fast as that moves over the
   * bubble's surface (the radius sets the scale), at most BLOW_MAX_MPS. Nothing off the bubble or
   * for a field whose film does not evolve.
   */
  blow(fx: number, fy: number, vxPx: number, vyPx: number): void {
    const state = this.fieldState?.state;
    if (!state?.blow) return;
    const raycaster = new Raycaster();
    raycaster.setFromCamera(new Vector2(2 * fx - 1, 1 - 2 * fy), this.camera);
    const hit = raycaster.ray.intersectSphere(UNIT_SPHERE, new Vector3());
    if (!hit) return;
    // Metres per CSS pixel at the point's distance (the camera looks along −z: x right, y up).
    const viewHeight = 2 * hit.distanceTo(this.camera.position) * Math.tan((FOV_DEG * Math.PI) / 360);
    const metresPerPixel = (viewHeight / this.size.height) * this.settings.radiusMm * 1e-3;
    const speed = Math.hypot(vxPx, vyPx) * metresPerPixel;
    const scale = speed > BLOW_MAX_MPS ? BLOW_MAX_MPS / speed : 1;
    state.blow([hit.x, hit.y, hit.z], [vxPx * metresPerPixel * scale, -vyPx * metresPerPixel * scale, 0]);
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
    // Per frame, as views may share the renderer (each view's materials are compiled for its own).
    r.toneMapping = this.toneMapping;
    // The app's frames keep the frame shown until the programs of the new one are ready.
    if (quick && this.compilesInParallel && !this.programs.ready(this.programsKey(), () => this.compilePrograms())) return;
    this.setDrawingBufferSpace();
    // The new light's transform has arrived, or a frame that does not wait (tests, screenshots) computes it here.
    if (this.lightWaiting && (!quick || spectralTransformReady(this.settings.illuminant, this.settings.normalization))) {
      this.lightShown = null;
      this.apply(this.settings);
    }
    this.syncTable(quick);
    const film = this.fieldState?.state;
    if (film)
      this.filmBehind = !film.advance(this.bubble.material.uniforms, this.settings, quick ? this.quality.flowStepsPerFrame : Infinity);
    r.render(this.scene, this.camera);
  }

  /**
   * The film at a point of the view (fractions from the top left) as drawn now, or null off the
   * bubble: the pixel comes back from the GPU a frame or two later (FilmProbe).
   */
  probe(fx: number, fy: number): Promise<ProbeReading | null> {
    this.syncTable();
    return this.filmProbe.read(this.renderer, this.camera, this.bubble, this.size, fx, fy);
  }

  private disposed = false;

  /** Frees this view's GPU resources (not the renderer, which may be shared). */
  dispose(): void {
    this.disposed = true;
    releaseEnvironmentTexture(this);
    this.renderer.domElement.removeEventListener('webglcontextrestored', this.rebuildTable);
    this.filmProbe.dispose();
    this.table.dispose();
    this.fieldState?.state.dispose();
    this.bubble.geometry.dispose();
    releaseFilmColorTextures(this.bubble.material);
    this.bubble.material.dispose();
    this.background.geometry.dispose();
    this.background.material.dispose();
  }
}
