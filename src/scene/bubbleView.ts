import { Mesh, PerspectiveCamera, Scene, ShaderMaterial, SphereGeometry, type WebGLRenderer } from 'three';
import { createBubbleMaterial, updateBubbleUniforms } from '../bubble/bubbleMaterial.ts';
import type { FieldState } from '../fields/thicknessField.ts';
import { environmentKind } from '../environments/environments.ts';
import { releaseFilmColorTextures } from '../film/filmColor.ts';
import { createBackgroundMaterial, updateBackgroundMaterial } from '../bubble/environmentMaterial.ts';
import { methodReads } from '../methods/methods.ts';
import { DEFAULT_FILM_QUALITY, type FilmQuality } from '../settings/filmQuality.ts';
import { FilmTable } from '../film/filmTable.ts';
import type { FilmSettings } from '../settings/filmSettings.ts';
import { blowOnBubble } from './blowOnBubble.ts';
import { EvolvingFilm } from './evolvingFilm.ts';
import { FilmLight } from './filmLight.ts';
import { FrameCost, type FrameCostReading } from './frameCost.ts';
import { compileFramePrograms, compilesInParallel } from './framePrograms.ts';
import { FilmProbe, type ProbeReading } from './probe.ts';
import { ProgramsInParallel } from './programsInParallel.ts';
import { type EnvironmentStatus, ShownEnvironment } from './shownEnvironment.ts';
import { ViewOutput } from './viewOutput.ts';

/** The camera sits on +z; the unit bubble (seen under 2·asin(1/4) = 29°) fills ~83 % of the 35° view's height. */
const CAMERA_DISTANCE = 4;
const FOV_DEG = 35;

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
  private readonly environment = new ShownEnvironment((env) => this.environmentArrived(env));
  private readonly output = new ViewOutput();
  /** Called when an HDR environment this view asked for arrives or fails (the caller redraws). */
  onEnvironmentChange: (() => void) | null = null;
  private readonly filmProbe = new FilmProbe();
  /** The programs of the frames to come, compiled without blocking where the GPU compiles in parallel. */
  private readonly programs = new ProgramsInParallel();
  private readonly light = new FilmLight();
  /** The view's size in CSS pixels and its pixel ratio. */
  private size = { width: 1, height: 1, pixelRatio: 1 };
  private settings: FilmSettings;
  /** The evolving film, for a field whose film evolves (its time, and whether the last frame left it behind). */
  readonly film: EvolvingFilm;
  /**
   * The most steps the flowing film takes in an app's frame (`render(true)`): the quality's
   * `flowStepsPerFrame` unless the page's frame governor sets it (Infinity: all the time asks).
   */
  flowStepsPerFrame: number;
  private readonly cost: FrameCost;
  private disposed = false;

  constructor(
    readonly renderer: WebGLRenderer,
    settings: FilmSettings,
    readonly quality: FilmQuality = DEFAULT_FILM_QUALITY,
  ) {
    this.settings = settings;
    this.table = new FilmTable(quality);
    this.film = new EvolvingFilm(renderer);
    this.flowStepsPerFrame = quality.flowStepsPerFrame;
    this.cost = new FrameCost(renderer);
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
    this.film.invalidate();
    this.cost.invalidate();
  };

  /** The evolving field's simulation, if the field shown evolves. */
  get evolvingFilm(): FieldState | null {
    return this.film.state;
  }

  /** Whether the canvas really shows Display P3 (false where the browser cannot). */
  get displayIsP3(): boolean {
    return this.output.displayIsP3;
  }

  get current(): FilmSettings {
    return this.settings;
  }

  /** Whether the view draws with the film table (its method reads one). */
  private get drawsTable(): boolean {
    return methodReads(this.settings.mode, 'table');
  }

  /** Takes new settings (already validated). Cheap: the table is brought up to date when drawn. */
  apply(s: FilmSettings): void {
    this.settings = s;
    this.film.show(s.field);
    const { settings: shown, map } = this.environment.show(s);
    if (this.output.take(this.renderer, s, shown)) {
      // three keeps a program per tone mapping a material was drawn with, until the material is
      // disposed: dispose both (set up anew on their next draw), so switching holds one program each.
      this.bubble.material.dispose();
      this.background.material.dispose();
    }
    this.background.visible = environmentKind(shown.env) !== 'none';
    updateBackgroundMaterial(this.background.material, shown, map);
    updateBubbleUniforms(
      this.bubble.material,
      { ...shown, ...this.light.of(s) },
      this.quality,
      this.drawsTable ? this.table : null,
      this.output.displayIsP3,
      map,
    );
  }

  private environmentArrived(env: FilmSettings['env']): void {
    if (this.disposed || this.settings.env !== env) return;
    this.apply(this.settings);
    this.onEnvironmentChange?.();
  }

  /** Whether the HDR environment asked for is shown, still on its way, or failed. */
  get environmentStatus(): EnvironmentStatus {
    return this.environment.status(this.settings.env);
  }

  /**
   * Compiles the programs of the first frame without blocking where the GPU compiles in parallel,
   * the light's textures made meanwhile; resolves when it can be drawn without waiting on a compile.
   */
  async prepare(): Promise<void> {
    // Without the extension (SwiftShader) compiling is blocking however it is asked for: the first frame does it.
    if (!compilesInParallel(this.renderer)) return;
    // The drawing buffer as the frame draws it: sized after the compile is queued, it would wait for it.
    this.output.fit(this.renderer, this.size);
    this.output.toneMap(this.renderer);
    this.output.setSpace(this.renderer);
    await this.programs.compile(this.programsKey(), () => this.compilePrograms());
  }

  /**
   * What picks the programs a frame draws with: the materials' defines and the tone mapping. Not the
   * drawing buffer's space, which three keys them by too: setting it reallocates the buffer, so the
   * frame shown could not be kept; a change of space compiles in its own frame.
   */
  private programsKey(): string {
    const background = this.background.visible ? this.background.material.defines : null;
    const table = this.drawsTable ? this.table.passKey(this.settings) : null;
    return JSON.stringify([this.bubble.material.defines, background, table, this.output.programKey]);
  }

  /** The programs of the next frame (bubble, background, the table pass) and of the probe that follows it. */
  private compilePrograms(): Promise<void> {
    return compileFramePrograms(
      this.renderer,
      this.camera,
      this.scene,
      [this.bubble, ...(this.background.visible ? [this.background] : [])],
      [
        this.filmProbe.compileAsync(this.renderer, this.camera, this.bubble),
        this.drawsTable ? this.table.prepare(this.renderer, this.settings) : null,
      ],
    );
  }

  /** Rebuilds the table if a parameter it depends on changed since it was drawn (coarsely first if `quick`). */
  private syncTable(quick = false): void {
    if (!this.drawsTable || !this.table.update(this.renderer, this.settings, quick)) return;
    this.table.bind(this.bubble.material.uniforms);
  }

  /**
   * Whether the last frame was drawn from a coarse table, or in the previous light while the new
   * light's transform is computed (FilmLight), or kept while the programs of the next are
   * compiled: more frames follow until one is full.
   */
  get coarse(): boolean {
    return (this.drawsTable && this.table.coarse) || this.light.waiting || this.programs.busy;
  }

  /**
   * Blows air on an evolving film at a point of the view (fractions from the top left) along a
   * screen velocity (CSS pixels per second, right and down): blowOnBubble.ts. Nothing off the
   * bubble or for a field whose film does not evolve.
   */
  blow(fx: number, fy: number, vxPx: number, vyPx: number): void {
    if (this.film.state?.blow) this.film.blow(blowOnBubble(this.camera, this.size.height, this.settings.radiusMm, [fx, fy], [vxPx, vyPx]));
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
   * Draws one frame into the renderer's canvas, sized to this view first; returns whether it drew
   * (not while the context is lost, nor in an app's frame that keeps the frame shown while the
   * programs of the next compile). `quick` (the app's frames): a table that has to be rebuilt is
   * drawn coarsely first, so a change shows in the next frame; the frame after completes it.
   */
  render(quick = false): boolean {
    const r = this.renderer;
    this.output.fit(r, this.size);
    if (this.contextLost) return false;
    // Per frame, as views may share the renderer (each view's materials are compiled for its own).
    this.output.toneMap(r);
    // The app's frames keep the frame shown until the programs of the new one are ready.
    if (quick && compilesInParallel(r) && !this.programs.ready(this.programsKey(), () => this.compilePrograms())) return false;
    this.output.setSpace(r);
    // The new light's transform has arrived, or a frame that does not wait (tests, screenshots) computes it here.
    if (this.light.waiting && (!quick || this.light.arrived(this.settings))) {
      this.light.forget();
      this.apply(this.settings);
    }
    this.syncTable(quick);
    const uniforms = this.bubble.material.uniforms;
    if (quick) {
      // The app's frames are measured (FrameCost) for the page's frame governor.
      this.cost.simulate(
        () => this.film.advance(uniforms, this.settings, this.flowStepsPerFrame),
        () => this.film.finish(),
        this.film.flowGrid?.gridN,
      );
      this.cost.draw(() => r.render(this.scene, this.camera));
    } else {
      this.film.advance(uniforms, this.settings, Infinity);
      r.render(this.scene, this.camera);
    }
    return true;
  }

  /** What the app's frame drawn last cost (FrameCost): the simulation's part and the bubble's draw, apart. */
  takeFrameCost(): FrameCostReading {
    return this.cost.take();
  }

  /**
   * The film at a point of the view (fractions from the top left) as drawn now, or null off the
   * bubble: the pixel comes back from the GPU a frame or two later (FilmProbe).
   */
  probe(fx: number, fy: number): Promise<ProbeReading | null> {
    this.syncTable();
    return this.filmProbe.read(this.renderer, this.camera, this.bubble, this.size, fx, fy);
  }

  /** Frees this view's GPU resources (not the renderer, which may be shared). */
  dispose(): void {
    this.disposed = true;
    this.environment.dispose();
    this.renderer.domElement.removeEventListener('webglcontextrestored', this.rebuildTable);
    this.filmProbe.dispose();
    this.cost.dispose();
    this.table.dispose();
    this.film.dispose();
    this.bubble.geometry.dispose();
    releaseFilmColorTextures(this.bubble.material);
    this.bubble.material.dispose();
    this.background.geometry.dispose();
    this.background.material.dispose();
  }
}
