import {
  Color,
  type DataTexture,
  FloatType,
  NearestFilter,
  RGBAFormat,
  ShaderMaterial,
  type Texture,
  WebGLRenderTarget,
  type WebGLRenderer,
} from 'three';
import { cubeFaceColumns } from '../physics/flow/cubeSphereFaces.ts';
import { type CubeSphereGrid, cubeSphereGrid } from '../physics/flow/cubeSphereGrid.ts';
import { cubeSphereHalo } from '../physics/flow/cubeSphereSampler.ts';
import { type FlowNumbers, flowNumbers } from '../physics/flow/flowNumbers.ts';
import { type FlowParameters, validateFlowParameters } from '../physics/flow/flowParameters.ts';
import { initialFilm } from '../physics/flow/initialFilm.ts';
import { LOG_MEAN_SERIES_BELOW } from '../physics/flow/logarithmicMean.ts';
import { SURFACTANT_JACOBI_SWEEPS } from '../physics/flow/solveSurfactant.ts';
import { WIND_SURFACE_FACTOR, timeStep } from '../physics/flow/timeStep.ts';
import { PURE_SURFACE_TENSION_N_M, VELOCITY_SCALE_M_S } from '../physics/flow/flowConstants.ts';
import { HOLE_RAYS, MAX_HOLES } from '../physics/flow/filmHoles.ts';
import { taylorCulickSpeedMps } from '../physics/flow/flowNumbers.ts';
import { rimLeadRad, rimThicknessFloorNm } from '../physics/flow/ruptureFilm.ts';
import { floatTexture } from '../gpu/floatRow.ts';
import { FULLSCREEN_VERTEX, FullscreenPass } from '../gpu/fullscreenPass.ts';
import { shaderSource } from '../gpu/shaderSource.ts';
import { type AtlasSize, cellTexelIndex, edgeAtlasSize, faceAtlasSize } from './flowAtlas.ts';
import { renewSteps } from './renewFilm.ts';
import { type FlowGridTextures, HALO_TAP_TEXELS, flowGridTextures } from './flowGridTextures.ts';

/**
 * Each pass: the GLSL file of the twin's module it mirrors and the call that computes a texel. The
 * halo pass's function takes its textures as arguments (the bubble's shader samples a padded film
 * with the same file), so its pass declares them.
 */
const PASSES = {
  reconstruct: ['reconstructCellVelocity.glsl', 'tfcReconstructCellVelocity()'],
  pad: ['cubeSphereSampler.glsl', 'tfcPadField(uHaloTaps, uField)', 'uniform sampler2D uHaloTaps;\nuniform sampler2D uField;'],
  predict: ['predictEdgeVelocity.glsl', 'tfcPredictEdgeVelocity()'],
  weights: ['solveSurfactant.glsl', 'tfcSurfactantWeights()'],
  system: ['solveSurfactant.glsl', 'tfcSurfactantSystem()'],
  sweep: ['solveSurfactant.glsl', 'tfcJacobiSweep()'],
  correct: ['solveSurfactant.glsl', 'tfcCorrectEdgeVelocity()'],
  limiter: ['transportFilm.glsl', 'tfcTransportLimiter()'],
  flux: ['transportFilm.glsl', 'tfcTransportFlux()'],
  update: ['transportFilm.glsl', 'tfcTransportUpdate()'],
  start: ['filmSimulation.glsl', 'tfcStartFilm()'],
  evaporate: ['filmSimulation.glsl', 'tfcEvaporate()'],
  rupture: ['ruptureFilm.glsl', 'tfcRuptureFilm()'],
  ruptureRows: ['ruptureFilm.glsl', 'tfcRuptureRows()'],
  openHoles: ['ruptureFilm.glsl', 'tfcOpenHoles()'],
  growRims: ['ruptureFilm.glsl', 'tfcGrowRims()'],
  emptyHoles: ['ruptureFilm.glsl', 'tfcEmptyHoles()'],
  burstSteps: ['renewFilm.glsl', 'tfcBurstSteps()'],
} as const satisfies Record<string, readonly [string, string] | readonly [string, string, string]>;
type PassName = keyof typeof PASSES;

/** The fragment shader of a pass: its module's GLSL and a main writing the call's texel. */
const passShader = ([file, texel, inputs = '']: readonly [string, string, string?]): string =>
  `${shaderSource(file)}\n${inputs}\nvoid main() { gl_FragColor = ${texel}; }\n`;

/** The angular width of a blow's patch of air (radians): about a sixth of the bubble across. */
export const BLOW_WIDTH_RAD = 0.3;

/** The channel masks of a Jacobi sweep's guess: the system's Γ (its b channel) or a sweep's result (r). */
const SYSTEM_GUESS = [0, 0, 1, 0];
const SWEEP_GUESS = [1, 0, 0, 0];

/** The texels of a hole's frame after its rays: centre (with the open flag), e1, e2 (tfcReadHole). */
const HOLE_FRAME_TEXELS = 3;
/** The hole table (shaders/flow/filmHoles.glsl): a row per hole, its rays' radii and then its frame. */
const HOLE_TABLE: AtlasSize = { width: HOLE_RAYS + HOLE_FRAME_TEXELS, height: MAX_HOLES };
/** No puncture (uPuncture's w = 0). */
const NO_PUNCTURE = [0, 0, 0, 0];

const floatTarget = (size: AtlasSize): WebGLRenderTarget =>
  new WebGLRenderTarget(size.width, size.height, {
    type: FloatType,
    format: RGBAFormat,
    minFilter: NearestFilter,
    magFilter: NearestFilter,
    depthBuffer: false,
  });

/** The textures a step reads and writes (RGBA float, one texel per cell, padded cell or edge). */
function flowTargets(n: number) {
  const cells = faceAtlasSize(n);
  const padded = faceAtlasSize(n + 2);
  const edges = edgeAtlasSize(n);
  return {
    /** (η, Γ, intact, 0), ping-ponged. */
    film: [floatTarget(cells), floatTarget(cells)] as [WebGLRenderTarget, WebGLRenderTarget],
    edgeVelocity: floatTarget(edges),
    cellVelocity: floatTarget(cells),
    paddedCellVelocity: floatTarget(padded),
    prediction: floatTarget(edges),
    weights: floatTarget(cells),
    system: floatTarget(cells),
    /** The first sweep's result (its g: the starting residual²), then two ping-pong buffers. */
    sweeps: [floatTarget(cells), floatTarget(cells), floatTarget(cells)],
    limiter: floatTarget(cells),
    flux: floatTarget(edges),
    /** The padded film, for sampling h anywhere (the bubble's field and the rims). */
    paddedFilm: floatTarget(padded),
    /** Each row's (face, j) count of cells that opened a hole this step, 6n × 1. */
    ruptureRows: floatTarget({ width: 6 * n, height: 1 }),
    /** The hole table, and the steps since no film was left (1 × 1), each ping-ponged. */
    holes: [floatTarget(HOLE_TABLE), floatTarget(HOLE_TABLE)] as [WebGLRenderTarget, WebGLRenderTarget],
    burst: [floatTarget({ width: 1, height: 1 }), floatTarget({ width: 1, height: 1 })] as [WebGLRenderTarget, WebGLRenderTarget],
  };
}
type FlowTargets = ReturnType<typeof flowTargets>;

/**
 * The flowing film of src/physics/flow/ on the GPU, pass for pass (docs/flow.md#the-gpu-port): the
 * same grid, parameters, start and fixed step Δt, each of the twin's passes one fragment-shader
 * draw into RGBA float render targets of the renderer it is given (the cell, padded and edge
 * atlases of flowAtlas.ts). `step` runs whole steps; `paddedFilm` is the film to sample. With
 * `renew` a new bubble follows a burst (renewFilm.ts); the twin has no such option.
 */
export class GpuFilmSimulation {
  readonly parameters: FlowParameters;
  readonly numbers: FlowNumbers;
  readonly grid: CubeSphereGrid;
  /** The fixed step in R/U, and in seconds. */
  readonly dt: number;
  readonly stepSeconds: number;
  /** Steps taken since the start. */
  steps = 0;
  private targets: FlowTargets;
  private textures: FlowGridTextures;
  /** The start's (η, Γ) per cell, in float64 from initialFilm, rounded once. */
  private start: DataTexture;
  private fullscreen = new FullscreenPass();
  private readonly uniforms: Record<string, { value: unknown }>;
  private readonly materials: Record<PassName, ShaderMaterial>;
  /** Whether the film target holds the start (false until the first draw after creation, reset or a lost context). */
  private started = false;
  /** The film, hole and burst targets now, and the steps the padded film was made for. */
  private current = 0;
  private currentHoles = 0;
  private currentBurst = 0;
  private paddedAt = -1;
  /** The sweeps whose residuals the last step's solve left: the first (from Γ) and the one measured at its solution. */
  private residualTargets: [WebGLRenderTarget, WebGLRenderTarget] | null = null;

  /** A film at its start, every parameter checked first (validateFlowParameters). */
  constructor(
    private readonly renderer: WebGLRenderer,
    given: Partial<Record<string, unknown>> = {},
    options: { readonly renew?: boolean } = {},
  ) {
    this.parameters = validateFlowParameters(given);
    this.numbers = flowNumbers(this.parameters);
    this.grid = cubeSphereGrid(this.parameters.gridN);
    this.dt = timeStep(this.grid, this.numbers);
    this.stepSeconds = this.dt * this.numbers.timeScaleS;
    this.targets = flowTargets(this.grid.n);
    this.textures = flowGridTextures(this.grid, cubeSphereHalo(this.grid));
    this.start = this.startTexture();
    const { airFriction, gravity, marangoni, wind, evaporation, ruptureEta, ruptureGamma } = this.numbers;
    const value = (v: unknown) => ({ value: v });
    this.uniforms = {
      uFlowGridN: value(this.grid.n),
      uCubeFaces: value(Float32Array.from(cubeFaceColumns())),
      ...Object.fromEntries(Object.keys(this.textures).map((k) => [k, value(null)])),
      uDt: value(this.dt),
      uAirFriction: value(airFriction),
      uGravity: value(gravity),
      uMarangoni: value(marangoni),
      uSurfaceWind: value(WIND_SURFACE_FACTOR * wind),
      uEvaporationLoss: value(evaporation * this.dt),
      uRuptureEta: value(ruptureEta),
      uRuptureGamma: value(ruptureGamma),
      uGuessChannel: value(SWEEP_GUESS),
      uBlowCenter: value([0, 0, 1]),
      uBlowVelocity: value([0, 0, 0]),
      uRimSpeed: value(
        (this.parameters.rimSpeedFactor * taylorCulickSpeedMps(PURE_SURFACE_TENSION_N_M, 2 * this.numbers.halfThicknessM)) /
          VELOCITY_SCALE_M_S,
      ),
      uRimEtaFloor: value(rimThicknessFloorNm(this.parameters) / this.parameters.thicknessNm),
      uRimLead: value(rimLeadRad(this.grid.n)),
      uRenewSteps: value(renewSteps(options.renew ?? false, this.stepSeconds)),
      uPuncture: value(NO_PUNCTURE),
      ...Object.fromEntries(
        [
          'uField',
          'uFilm',
          'uEdgeVelocity',
          'uCellVelocity',
          'uPaddedCellVelocity',
          'uPrediction',
          'uSurfactantWeights',
          'uSurfactantRhs',
          'uGuess',
          'uSolvedGamma',
          'uLimiter',
          'uFlux',
          'uRuptureRows',
          'uHoles',
          'uPaddedFilm',
          'uStartFilm',
          'uBurst',
        ].map((k) => [k, value(null)]),
      ),
    };
    this.bindGrid();
    const defines = {
      TFC_HALO_TAP_TEXELS: HALO_TAP_TEXELS,
      TFC_LOG_MEAN_SERIES_BELOW: LOG_MEAN_SERIES_BELOW,
      TFC_BLOW_WIDTH_RAD: BLOW_WIDTH_RAD,
      TFC_HOLE_RAYS: HOLE_RAYS,
      TFC_MAX_HOLES: MAX_HOLES,
    };
    this.materials = Object.fromEntries(
      Object.entries(PASSES).map(([name, pass]) => [
        name,
        new ShaderMaterial({ defines, uniforms: this.uniforms, vertexShader: FULLSCREEN_VERTEX, fragmentShader: passShader(pass) }),
      ]),
    ) as Record<PassName, ShaderMaterial>;
  }

  private startTexture(): DataTexture {
    const { eta, gamma } = initialFilm(this.grid, this.parameters.seed);
    const size = faceAtlasSize(this.grid.n);
    const data = new Float32Array(4 * size.width * size.height);
    for (let c = 0; c < this.grid.cellCount; c++) data.set([eta[c]!, gamma[c]!], 4 * cellTexelIndex(this.grid.n, c));
    return floatTexture(data, size.width, size.height);
  }

  private bindGrid(): void {
    for (const [k, texture] of Object.entries(this.textures)) this.uniforms[k]!.value = texture;
  }

  /** Back to the start (drawn with the next step or padded film). */
  reset(): void {
    this.started = false;
    this.steps = 0;
    this.paddedAt = -1;
    this.residualTargets = null;
  }

  /**
   * Air blown at a direction (unit, the simulation's frame) with a velocity in m/s (its part
   * tangent there counts) for the steps that follow, until `blow` is called again; a zero
   * velocity is still air (the twin's air).
   */
  blow(center: readonly [number, number, number], velocityMps: readonly [number, number, number]): void {
    const along = velocityMps[0] * center[0] + velocityMps[1] * center[1] + velocityMps[2] * center[2];
    this.uniforms.uBlowCenter!.value = [...center];
    this.uniforms.uBlowVelocity!.value = velocityMps.map((v, k) => (v - along * center[k]!) / VELOCITY_SCALE_M_S);
  }

  /** Runs `count` whole steps Δt. */
  step(count = 1): void {
    if (count <= 0) return;
    this.withTargets(() => {
      this.ensureStarted();
      for (let k = 0; k < count; k++) this.stepOnce();
    });
  }

  /** The padded film (η, Γ, intact, 0), its ghosts filled, at the steps taken: what tfcSamplePadded reads. */
  get paddedFilm(): Texture {
    if (this.paddedAt !== this.steps || !this.started) {
      this.withTargets(() => {
        this.ensureStarted();
        this.pad(this.film, this.targets.paddedFilm);
      });
      this.paddedAt = this.steps;
    }
    return this.targets.paddedFilm.texture;
  }

  private get film(): WebGLRenderTarget {
    return this.targets.film[this.current]!;
  }

  /** Draws with the renderer's target put back afterwards. */
  private withTargets(draw: () => void): void {
    const previous = this.renderer.getRenderTarget();
    draw();
    this.renderer.setRenderTarget(previous);
  }

  private draw(pass: PassName, target: WebGLRenderTarget, inputs: Record<string, Texture | readonly number[]>): void {
    for (const [k, v] of Object.entries(inputs)) this.uniforms[k]!.value = v;
    this.renderer.setRenderTarget(target);
    this.fullscreen.render(this.renderer, this.materials[pass]);
  }

  private ensureStarted(): void {
    if (this.started) return;
    this.current = 0;
    this.currentHoles = 0;
    this.currentBurst = 0;
    this.draw('start', this.film, { uFilm: this.start });
    // The film starts at rest (zero edge velocities), with no hole and no burst.
    const r = this.renderer;
    const [colour, alpha] = [r.getClearColor(new Color()), r.getClearAlpha()];
    r.setClearColor(0x000000, 0);
    for (const target of [this.targets.edgeVelocity, this.holes, this.burst]) {
      r.setRenderTarget(target);
      r.clear(true, false, false);
    }
    r.setClearColor(colour, alpha);
    this.started = true;
  }

  private get holes(): WebGLRenderTarget {
    return this.targets.holes[this.currentHoles]!;
  }

  private get burst(): WebGLRenderTarget {
    return this.targets.burst[this.currentBurst]!;
  }

  /** The hole table after `pass` (openHoles or growRims) has read the current one. */
  private drawHoles(pass: 'openHoles' | 'growRims', inputs: Record<string, Texture | readonly number[]>): void {
    this.draw(pass, this.targets.holes[1 - this.currentHoles]!, { ...inputs, uHoles: this.holes.texture });
    this.currentHoles = 1 - this.currentHoles;
  }

  /**
   * Pricks the film at a direction (unit or not, the simulation's frame): a hole opens there, if
   * one of the MAX_HOLES is free, and bursts outward from the next step (the twin's punctureFilm).
   */
  puncture(x: number, y: number, z: number): void {
    this.withTargets(() => {
      this.ensureStarted();
      this.drawHoles('openHoles', { uBurst: this.burst.texture, uPuncture: [x, y, z, 1] });
    });
  }

  private pad(field: WebGLRenderTarget, into: WebGLRenderTarget): void {
    this.draw('pad', into, { uField: field.texture });
  }

  /** One step, the twin's stepFilm pass for pass. */
  private stepOnce(): void {
    const t = this.targets;
    const film = () => this.film.texture;
    const nextFilm = () => this.targets.film[1 - this.current]!;
    const flip = () => (this.current = 1 - this.current);
    this.draw('reconstruct', t.cellVelocity, { uEdgeVelocity: t.edgeVelocity.texture });
    this.pad(t.cellVelocity, t.paddedCellVelocity);
    this.draw('predict', t.prediction, {
      uFilm: film(),
      uCellVelocity: t.cellVelocity.texture,
      uPaddedCellVelocity: t.paddedCellVelocity.texture,
    });
    this.draw('weights', t.weights, { uPrediction: t.prediction.texture });
    this.draw('system', t.system, { uSurfactantWeights: t.weights.texture });
    this.draw('sweep', t.sweeps[0]!, { uSurfactantRhs: t.system.texture, uGuess: t.system.texture, uGuessChannel: SYSTEM_GUESS });
    let x = t.sweeps[0]!;
    for (let k = 1; k <= SURFACTANT_JACOBI_SWEEPS; k++) {
      // The sweep after the last measures the residual at the solution (the twin's extra sweep).
      const next = x === t.sweeps[1] ? t.sweeps[2]! : t.sweeps[1]!;
      this.draw('sweep', next, { uGuess: x.texture, uGuessChannel: SWEEP_GUESS });
      if (k < SURFACTANT_JACOBI_SWEEPS) x = next;
      else this.residualTargets = [t.sweeps[0]!, next];
    }
    this.draw('correct', t.edgeVelocity, { uSolvedGamma: x.texture });
    this.draw('limiter', t.limiter, { uEdgeVelocity: t.edgeVelocity.texture });
    this.draw('flux', t.flux, { uFilm: film(), uLimiter: t.limiter.texture });
    this.draw('update', nextFilm(), { uFilm: film(), uFlux: t.flux.texture });
    flip();
    if (this.numbers.evaporation > 0) {
      this.draw('evaporate', nextFilm(), { uFilm: film() });
      flip();
    }
    this.rupture();
    this.steps++;
  }

  /** Pass 8, rupture and the rims (ruptureFilm.glsl), and the burst's count (renewFilm.glsl). */
  private rupture(): void {
    const t = this.targets;
    const [marked, emptied] = [t.film[1 - this.current]!, t.film[this.current]!];
    const burst = this.burst.texture;
    this.draw('rupture', marked, { uFilm: this.film.texture, uHoles: this.holes.texture });
    this.draw('ruptureRows', t.ruptureRows, { uFilm: marked.texture });
    this.drawHoles('openHoles', { uRuptureRows: t.ruptureRows.texture, uPuncture: NO_PUNCTURE, uBurst: burst });
    this.pad(marked, t.paddedFilm);
    this.drawHoles('growRims', { uPaddedFilm: t.paddedFilm.texture });
    this.draw('emptyHoles', emptied, { uFilm: marked.texture, uHoles: this.holes.texture, uStartFilm: this.start });
    this.draw('burstSteps', t.burst[1 - this.currentBurst]!, { uBurst: burst, uHoles: this.holes.texture });
    this.currentBurst = 1 - this.currentBurst;
  }

  private read(target: WebGLRenderTarget): Float32Array {
    const out = new Float32Array(4 * target.width * target.height);
    this.renderer.readRenderTargetPixels(target, 0, 0, target.width, target.height, out);
    return out;
  }

  /** The film read back, in the twin's cell order: η and Γ (in η0, Γ0) and whether intact. */
  readFilm(): { eta: Float32Array; gamma: Float32Array; intact: Uint8Array } {
    this.withTargets(() => this.ensureStarted());
    const texels = this.read(this.film);
    const cells = this.grid.cellCount;
    const [eta, gamma, intact] = [new Float32Array(cells), new Float32Array(cells), new Uint8Array(cells)];
    for (let c = 0; c < cells; c++) {
      const t = 4 * cellTexelIndex(this.grid.n, c);
      [eta[c], gamma[c], intact[c]] = [texels[t]!, texels[t + 1]!, texels[t + 2]!];
    }
    return { eta, gamma, intact };
  }

  /** The open holes read back, in the order they opened: each one's centre and its rays' angular radii (the twin's FilmHole). */
  readHoles(): { center: number[]; radius: number[] }[] {
    this.withTargets(() => this.ensureStarted());
    const texels = this.read(this.holes);
    const row = (s: number, k: number) => texels.subarray(4 * (s * HOLE_TABLE.width + k), 4 * (s * HOLE_TABLE.width + k + 1));
    return Array.from({ length: MAX_HOLES }, (_, s) => s)
      .filter((s) => row(s, HOLE_RAYS)[3] !== 0)
      .map((s) => ({ center: [...row(s, HOLE_RAYS).subarray(0, 3)], radius: Array.from({ length: HOLE_RAYS }, (_, k) => row(s, k)[0]!) }));
  }

  /** The edge velocities u·n_e (in U) read back, in the twin's edge order. */
  readEdgeVelocity(): Float32Array {
    const texels = this.read(this.targets.edgeVelocity);
    return Float32Array.from({ length: this.grid.edgeCount }, (_, e) => texels[4 * e]!);
  }

  /**
   * The relative residual ‖b − AΓ'‖/‖b − AΓ‖ the last step's surfactant solve reached (0 before a
   * step, or when Γ already solved it), summed on the CPU from the sweeps' per-cell squares.
   */
  surfactantResidual(): number {
    if (!this.residualTargets) return 0;
    const sum = (target: WebGLRenderTarget) => {
      const texels = this.read(target);
      let s = 0;
      for (let t = 1; t < texels.length; t += 4) s += texels[t]!;
      return Math.sqrt(s);
    };
    const initial = sum(this.residualTargets[0]);
    return initial > 0 ? sum(this.residualTargets[1]) / initial : 0;
  }

  /**
   * New GPU objects after a lost context, the film back at its start. The lost context's targets
   * and textures are let go, not disposed: three would delete objects of the lost context in the new
   * one (a WebGL warning). The programs are three's to make anew.
   */
  invalidate(): void {
    this.targets = flowTargets(this.grid.n);
    this.textures = flowGridTextures(this.grid, cubeSphereHalo(this.grid));
    this.start = this.startTexture();
    this.fullscreen = new FullscreenPass();
    this.bindGrid();
    this.reset();
  }

  dispose(): void {
    for (const target of Object.values(this.targets).flat()) target.dispose();
    const textures: DataTexture[] = [this.start, ...Object.values<DataTexture>(this.textures)];
    for (const texture of textures) texture.dispose();
    this.fullscreen.dispose();
    for (const material of Object.values(this.materials)) material.dispose();
  }
}
