import { Color, type ShaderMaterial, type Texture, type WebGLRenderTarget, type WebGLRenderer } from 'three';
import type { ChebyshevSchedule } from '../physics/filmDynamics/chebyshevSchedule.ts';
import { FullscreenPass } from '../gpu/fullscreenPass.ts';
import { type PassName, passMaterials } from './flowPasses.ts';
import { type FlowTargets, allTargets, flowTargets } from './flowTargets.ts';
import { type FlowUniformName, type FlowUniformSets, allFlowUniforms } from './flowUniforms.ts';
import { type DrawInputs, drawPredictionAndSolve } from './solvePasses.ts';

/**
 * The twin's step as draws (docs/flow.md#the-gpu-port): each pass of flowPasses.ts one fullscreen
 * draw into the RGBA float targets of a grid of side n (flowTargets.ts), in the renderer it is
 * given: the surfactant solve's sweeps with the twin's Chebyshev schedule, the transport's passes
 * once per sub-step. It holds the film's state in its targets and knows nothing of time or steps
 * taken.
 */
export class FlowStep {
  private current: FlowTargets;
  private fullscreen = new FullscreenPass();
  /** The film's start, which a renewal puts back. */
  private startFilm: Texture | null = null;
  private readonly uniforms: ReturnType<typeof allFlowUniforms>;
  private readonly materials: Record<PassName, ShaderMaterial>;

  constructor(
    private readonly renderer: WebGLRenderer,
    sets: FlowUniformSets,
    private readonly n: number,
    private readonly schedule: Pick<ChebyshevSchedule, 'momentum' | 'step'>,
    private readonly transportSubsteps: number,
  ) {
    this.current = flowTargets(n);
    this.uniforms = allFlowUniforms(sets);
    this.materials = passMaterials(sets);
  }

  /** The targets that hold the film's state and each pass's result. */
  get targets(): FlowTargets {
    return this.current;
  }

  /** Sets a uniform that every pass reading it keeps until it is set again. */
  set(name: FlowUniformName, value: unknown): void {
    this.uniforms[name].value = value;
  }

  /** Draws with the renderer's target put back afterwards. */
  withTargets(draw: () => void): void {
    const previous = this.renderer.getRenderTarget();
    draw();
    this.renderer.setRenderTarget(previous);
  }

  private draw(pass: PassName, target: WebGLRenderTarget, inputs: DrawInputs): void {
    for (const [k, v] of Object.entries(inputs)) this.set(k as FlowUniformName, v);
    this.renderer.setRenderTarget(target);
    this.fullscreen.render(this.renderer, this.materials[pass]);
  }

  /** The film at `start` (a FLOW_FILM record per cell), at rest (zero edge velocities), with no hole and no burst. */
  start(start: Texture): void {
    const t = this.targets;
    for (const pair of [t.film, t.holes, t.burst]) pair.reset();
    this.startFilm = start;
    this.draw('start', t.film.read, { uFilm: start });
    const r = this.renderer;
    const [colour, alpha] = [r.getClearColor(new Color()), r.getClearAlpha()];
    r.setClearColor(0x000000, 0);
    for (const target of [t.edgeVelocity, t.holes.read, t.burst.read]) {
      r.setRenderTarget(target);
      r.clear(true, false, false);
    }
    r.setClearColor(colour, alpha);
  }

  /** The halo pass: `field` padded into `into`, its ghosts filled. */
  pad(field: WebGLRenderTarget, into: WebGLRenderTarget): void {
    this.draw('pad', into, { uField: field.texture });
  }

  /** One step, the twin's stepFilm pass for pass (evaporation only where it takes film, as there). */
  step(evaporates: boolean): void {
    const t = this.targets;
    const state = { film: t.film.read.texture, edgeVelocity: t.edgeVelocity.texture };
    const x = drawPredictionAndSolve((pass, target, inputs) => this.draw(pass, target, inputs), t, state, this.schedule);
    this.draw('correct', t.edgeVelocity, { uFilm: t.film.read.texture, uSolvedGamma: x.texture });
    for (let k = 0; k < this.transportSubsteps; k++) {
      this.draw('limiter', t.limiter, { uEdgeVelocity: t.edgeVelocity.texture });
      this.draw('flux', t.flux, { uFilm: t.film.read.texture, uLimiter: t.limiter.texture });
      this.drawFilm('update', { uFlux: t.flux.texture });
    }
    if (evaporates) this.drawFilm('evaporate', {});
    this.rupture();
  }

  /** The film after `pass` has read the current one. */
  private drawFilm(pass: 'update' | 'evaporate', inputs: DrawInputs): void {
    const film = this.targets.film;
    this.draw(pass, film.write, { ...inputs, uFilm: film.read.texture });
    film.swap();
  }

  /** The hole table after `pass` (openHoles or growRims) has read the current one. */
  private drawHoles(pass: 'openHoles' | 'growRims', inputs: DrawInputs): void {
    const holes = this.targets.holes;
    this.draw(pass, holes.write, { ...inputs, uHoles: holes.read.texture });
    holes.swap();
  }

  /**
   * Pricks the film at a direction (unit or not, the simulation's frame): a hole opens there, if
   * one of the MAX_HOLES is free, and bursts outward from the next step (the twin's punctureFilm).
   */
  puncture(x: number, y: number, z: number): void {
    this.drawHoles('openHoles', { uBurst: this.targets.burst.read.texture, uPuncture: [x, y, z], uPunctured: 1 });
  }

  /** Pass 8, rupture and the rims (ruptureFilm.glsl), and the burst's count (renewFilm.glsl). */
  private rupture(): void {
    const t = this.targets;
    // The marked film goes to the free target; the emptied film replaces the film it was marked from.
    const [marked, emptied] = [t.film.write, t.film.read];
    const burst = t.burst.read.texture;
    this.draw('rupture', marked, { uFilm: emptied.texture, uHoles: t.holes.read.texture });
    this.draw('ruptureRows', t.ruptureRows, { uFilm: marked.texture });
    this.drawHoles('openHoles', { uRuptureRows: t.ruptureRows.texture, uPunctured: 0, uBurst: burst });
    this.pad(marked, t.paddedFilm);
    this.drawHoles('growRims', { uPaddedFilm: t.paddedFilm.texture });
    this.draw('emptyHoles', emptied, { uFilm: marked.texture, uHoles: t.holes.read.texture, uStartFilm: this.startFilm! });
    this.draw('burstSteps', t.burst.write, { uBurst: burst, uHoles: t.holes.read.texture });
    t.burst.swap();
  }

  /**
   * New targets and quad after a lost context (the film's state is gone with it; `start` draws it
   * anew). The lost context's are let go, not disposed: three would delete objects of the lost
   * context in the new one (a WebGL warning). The programs are three's to make anew.
   */
  invalidate(): void {
    this.current = flowTargets(this.n);
    this.fullscreen = new FullscreenPass();
  }

  dispose(): void {
    for (const target of allTargets(this.targets)) target.dispose();
    this.fullscreen.dispose();
    for (const material of Object.values(this.materials)) material.dispose();
  }
}
