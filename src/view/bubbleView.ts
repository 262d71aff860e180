import { Mesh, PerspectiveCamera, Scene, ShaderMaterial, SphereGeometry, type WebGLRenderer } from 'three';
import { createBubbleMaterial, updateBubbleUniforms } from '../bubbleMaterials/bubbleMaterial.ts';
import { environmentKind } from '../environments/environments.ts';
import { updateFieldUniforms } from '../fields/fields.ts';
import { releaseFilmColorTextures } from '../film/filmColor.ts';
import { createBackgroundMaterial, updateBackgroundMaterial } from '../bubbleMaterials/environmentMaterial.ts';
import { spectralTransformReady } from '../film/spectralTransformTexture.ts';
import { filmPlanes } from '../settings/filmLight.ts';
import { methodReads } from '../methods/methods.ts';
import { DEFAULT_SETTINGS } from '../settings/filmParameters.ts';
import { DEFAULT_FILM_QUALITY, type FilmQuality } from '../settings/filmQuality.ts';
import { FilmTable } from '../film/filmTable.ts';
import { ProgressiveTableBuild } from '../film/progressiveTableBuild.ts';
import type { FilmSettings } from '../settings/filmSettings.ts';
import { blowOnBubble } from './blowOnBubble.ts';
import { bubbleHit } from './bubbleRay.ts';
import type { DrawnFrame } from './drawnFrame.ts';
import { EnvironmentLoads } from './environmentLoads.ts';
import { type FramePace, type FrameReport, NOT_DRAWN, type ViewOffers } from './frameReport.ts';
import { EvolvingFilm } from './evolvingFilm.ts';
import { FrameCost } from './frameCost.ts';
import { drawsDisplayP3 } from './displaySpace.ts';
import { compilesInParallel } from './framePrograms.ts';
import { FilmProbe, type ProbeReading } from './probe.ts';
import { ViewPrograms } from './viewPrograms.ts';
import { ViewOutput } from './viewOutput.ts';

/** The camera sits on +z; the unit bubble (seen under 2·asin(1/4) = 29°) fills ~83 % of the 35° view's height. */
const CAMERA_DISTANCE = 4;
const FOV_DEG = 35;

/**
 * A bubble: camera, environment, the film material and its table, drawn by a renderer that may
 * be its own or shared by several views (then programs and spectral textures are compiled and
 * uploaded once). It draws the frame it is shown (`show`: what its app resolved: drawnFrame.ts),
 * on demand: `render()` draws one frame and reports it; the caller loops only while animating.
 */
export class BubbleView {
  readonly camera = new PerspectiveCamera(FOV_DEG, 1, 0.1, 100);
  readonly scene = new Scene();
  readonly table: FilmTable;
  readonly bubble: Mesh<SphereGeometry, ShaderMaterial>;
  private readonly background: Mesh<SphereGeometry, ShaderMaterial>;
  private readonly environments = new EnvironmentLoads(() => this.onEnvironmentChange?.());
  private readonly output = new ViewOutput();
  /** Called when an HDR environment arrives or fails (the app resolves its frame again). */
  onEnvironmentChange: (() => void) | null = null;
  private readonly filmProbe = new FilmProbe();
  private readonly programs: ViewPrograms;
  /** The view's size in CSS pixels and its pixel ratio. */
  private size = { width: 1, height: 1, pixelRatio: 1 };
  /** The frame shown, and the film it draws (its light the one asked for in a frame that does not wait for it). */
  private frame: DrawnFrame | null = null;
  private settings: FilmSettings = DEFAULT_SETTINGS;
  private readonly film: EvolvingFilm;
  private readonly cost: FrameCost;
  private report: FrameReport = NOT_DRAWN;

  constructor(
    readonly renderer: WebGLRenderer,
    readonly quality: FilmQuality = DEFAULT_FILM_QUALITY,
  ) {
    this.table = new FilmTable(quality, (pass) => new ProgressiveTableBuild(pass));
    this.film = new EvolvingFilm(renderer);
    this.cost = new FrameCost(renderer);
    this.camera.position.set(0, 0, CAMERA_DISTANCE);
    this.bubble = new Mesh(new SphereGeometry(1, 128, 64), createBubbleMaterial(this.settings, quality));
    this.background = new Mesh(new SphereGeometry(50, 64, 32), createBackgroundMaterial());
    this.scene.add(this.background, this.bubble);
    this.programs = new ViewPrograms(this);
    // After a lost context comes back, three re-creates programs and re-uploads textures by
    // itself; the table and an evolving film, drawn on the GPU, are gone and must be drawn again.
    renderer.domElement.addEventListener('webglcontextrestored', this.rebuildTable);
  }

  private readonly rebuildTable = () => {
    this.programs.forget();
    this.table.invalidate();
    this.film.invalidate();
    this.cost.invalidate();
  };

  /** Whether the canvas really shows Display P3 (false where the browser cannot). */
  get displayIsP3(): boolean {
    return this.output.displayIsP3;
  }

  /** What this view offers its frames: the environments arrived or failed, parallel compiles, the lights ready, the light drawn last, its steps per frame. */
  get offers(): ViewOffers {
    return {
      environmentLoaded: (env) => this.environments.loaded(env),
      environmentFailure: (env) => this.environments.failure(env),
      compilesInParallel: compilesInParallel(this.renderer),
      drawsDisplayP3: () => drawsDisplayP3(this.renderer),
      lightReady: (light) => spectralTransformReady(light, filmPlanes(light)),
      lightShown: this.frame && {
        illuminant: this.settings.illuminant,
        lightTint: this.settings.lightTint,
        normalization: this.settings.normalization,
      },
      baseStepsPerFrame: this.quality.flowStepsPerFrame,
    };
  }

  /** What the last frame drew. */
  get lastFrame(): FrameReport {
    return this.report;
  }

  /** Whether the view draws with the film table (its method reads one). */
  get drawsTable(): boolean {
    return methodReads(this.settings.mode, 'table');
  }

  /** The film settings drawn (the frame's), for the programs of the next frame (ViewPrograms). */
  get filmDrawn(): FilmSettings {
    return this.settings;
  }

  /** Whether the background sphere is drawn (an environment with a backdrop). */
  get backgroundShown(): Mesh<SphereGeometry, ShaderMaterial> | null {
    return this.background.visible ? this.background : null;
  }

  /** Takes the frame to draw (immutable; cheap: the table is brought up to date when drawn). */
  show(frame: DrawnFrame): void {
    this.frame = frame;
    if (frame.fetch) this.environments.fetch(frame.fetch);
    this.draw(frame.film, frame);
  }

  /** Takes a frame that differs from the one shown only in the film's time (retimed): only the field's uniforms follow. */
  showTime(frame: DrawnFrame): void {
    this.frame = frame;
    this.settings = { ...this.settings, timeSeconds: frame.film.timeSeconds };
    updateFieldUniforms(this.bubble.material.uniforms, this.settings, frame.field);
  }

  /** Sets the materials to the film drawn (its field and the canvas's space as the frame draws them). */
  private draw(s: FilmSettings, { field, displayP3 }: DrawnFrame): void {
    this.settings = s;
    this.film.show(s.field);
    const map = this.environments.map(s.env);
    if (this.output.take(s, displayP3)) {
      // three keeps a program per tone mapping a material was drawn with, until the material is
      // disposed: dispose both (set up anew on their next draw), so switching holds one program each.
      this.bubble.material.dispose();
      this.background.material.dispose();
    }
    this.background.visible = environmentKind(s.env) !== 'none';
    updateBackgroundMaterial(this.background.material, s, map);
    updateBubbleUniforms(this.bubble.material, s, field, this.quality, this.drawsTable ? this.table : null, this.output.displayIsP3, map);
  }

  /**
   * Compiles the programs of the first frame without blocking where the GPU compiles in parallel,
   * the light's textures made meanwhile; resolves when it can be drawn without waiting on a compile.
   */
  async prepare(): Promise<void> {
    // Without the extension (SwiftShader) compiling is blocking however it is asked for: the first frame does it.
    if (!this.frame?.keepsFrameWhileCompiling) return;
    // The drawing buffer as the frame draws it: sized after the compile is queued, it would wait for it.
    this.output.fit(this.renderer, this.size);
    this.output.toneMap(this.renderer);
    this.output.setSpace(this.renderer);
    await this.programs.compile(this.output.programKey, this.filmProbe);
  }

  /** Rebuilds the table if a parameter it depends on or its range (the frame's) changed since it was drawn (coarsely first in a paced frame). */
  private syncTable(paced = false): void {
    const range = this.frame?.field.maxThicknessNm;
    if (range === undefined || !this.drawsTable || !this.table.update(this.renderer, this.settings, range, paced)) return;
    this.table.bind(this.bubble.material.uniforms);
  }

  /**
   * Blows air on an evolving film at a point of the view (fractions from the top left) along a
   * screen velocity (CSS pixels per second, right and down): blowOnBubble.ts. Nothing off the
   * bubble or for a field whose film does not evolve.
   */
  blow(fx: number, fy: number, vxPx: number, vyPx: number): void {
    this.film.blow(blowOnBubble(this.camera, this.size.height, this.settings.radiusMm, [fx, fy], [vxPx, vyPx]));
  }

  /** Bursts an evolving film where a point of the view (fractions from the top left) meets the bubble (bubbleRay.ts); as `blow`, nothing off it. */
  burst(fx: number, fy: number): void {
    this.film.burst(bubbleHit(this.camera, [fx, fy])?.point.toArray() ?? null);
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

  /** Draws the frame shown into the renderer's canvas, sized to this view first, and reports it: paced or complete (FramePace). */
  render(pace: FramePace = 'complete'): FrameReport {
    const paced = pace === 'paced';
    const r = this.renderer;
    const frame = this.frame;
    this.output.fit(r, this.size);
    if (this.contextLost || !frame) return (this.report = NOT_DRAWN);
    // Per frame, as views may share the renderer (each view's materials are compiled for its own).
    this.output.toneMap(r);
    const keeps = paced && frame.keepsFrameWhileCompiling && !this.programs.ready(this.output.programKey, this.filmProbe);
    if (keeps) return (this.report = { ...NOT_DRAWN, film: this.film.reading });
    this.output.setSpace(r);
    // A frame that does not wait draws the light asked for, its transform computed here.
    if (!paced && frame.lightPending) this.draw({ ...frame.film, ...frame.lightPending }, frame);
    this.syncTable(paced);
    const uniforms = this.bubble.material.uniforms;
    let cost: FrameReport['cost'] = null;
    if (paced) {
      this.cost.simulate(
        () => this.film.advance(uniforms, this.settings, frame.field.derived, frame.stepsPerFrame),
        () => this.film.finish(),
        this.film.reading?.flow?.gridN,
      );
      this.cost.draw(() => r.render(this.scene, this.camera));
      cost = { ...this.cost.take(), settling: this.film.settling };
    } else {
      this.film.advance(uniforms, this.settings, frame.field.derived, Infinity);
      r.render(this.scene, this.camera);
    }
    const coarse = (this.drawsTable && this.table.coarse) || (paced && frame.lightPending !== null) || this.programs.busy;
    return (this.report = { drawn: true, coarse, film: this.film.reading, cost });
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
    this.onEnvironmentChange = null;
    this.environments.dispose();
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
