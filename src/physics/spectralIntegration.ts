import { type FilmOptics, type FilmStack, type Polarization, filmOptics, reflectanceAt } from './filmReflectance.ts';
import { type IlluminantSpec } from './illuminants.ts';
import type { LightTint } from './lightTint.ts';
import { type Medium, assertMedium, isDispersiveMedium, mediumStackAt } from './medium.ts';
import {
  LAMBDA_MIN_NM,
  LAMBDA_SPAN_NM,
  type Normalization,
  type SpectralWeights,
  type WeightedLine,
  type Xyz,
  spectralWeights,
} from './spectralWeights.ts';

/** A line source's colour: Σ R(λ_l) · weight over its lines (docs/physics.md#lights). */
export const linesXyz = (reflectance: (lambdaNm: number) => number, lines: readonly WeightedLine[]): Xyz =>
  lines.reduce<Xyz>(
    (xyz, l) => {
      const r = reflectance(l.nm);
      return [xyz[0] + r * l.x, xyz[1] + r * l.y, xyz[2] + r * l.z];
    },
    [0, 0, 0],
  );

/**
 * ∫ R(λ) W(λ) dλ over 380–830 nm (a line source's weights: the sum over its lines instead) for the three weight tables, by the trapezoid rule with
 * `stepsPerNm` equal sub-steps in every 1 nm interval. The 1 nm knots of W are nodes, so W is
 * exactly linear between nodes and the only error is R's variation between samples.
 */
export function integrateXyz(reflectance: (lambdaNm: number) => number, w: SpectralWeights, stepsPerNm: number): Xyz {
  if (w.lines) return linesXyz(reflectance, w.lines);
  const h = 1 / stepsPerNm;
  let X = 0;
  let Y = 0;
  let Z = 0;
  for (let i = 0; i < LAMBDA_SPAN_NM; i++) {
    const x0 = w.x[i] as number,
      x1 = w.x[i + 1] as number;
    const y0 = w.y[i] as number,
      y1 = w.y[i + 1] as number;
    const z0 = w.z[i] as number,
      z1 = w.z[i + 1] as number;
    for (let j = i === 0 ? 0 : 1; j <= stepsPerNm; j++) {
      const f = j * h;
      const r = reflectance(LAMBDA_MIN_NM + i + f) * (j === 0 || (j === stepsPerNm && i === LAMBDA_SPAN_NM - 1) ? 0.5 : 1);
      X += r * (x0 + (x1 - x0) * f);
      Y += r * (y0 + (y1 - y0) * f);
      Z += r * (z0 + (z1 - z0) * f);
    }
  }
  return [X * h, Y * h, Z * h];
}

/**
 * Sampling that converges at every thickness (docs/physics.md#sampling). R(λ) is periodic in the phase φ
 * with one fringe per 2π, and a fringe spans about λ²/Δ nm, narrowest at 380 nm. The trapezoid
 * rule on a periodic analytic function converges geometrically with the number of samples per
 * period, at a rate set by how close eq (13)'s pole 1/(r_ba r_bc) is to the unit circle, so:
 *   samples per fringe K = max(MIN_SAMPLES_PER_FRINGE, FINESSE_SAMPLES / (1 − |r_ba r_bc|)),
 *   sub-steps per nm     = max(1, ⌈K · Re Δ / 380²⌉).
 * Cost: 451 R evaluations (×2 polarisations when unpolarised) up to Re Δ ≈ 18 000 nm (a soap
 * film 6.8 µm thick at normal incidence), then growing linearly with Δ: about 2 700 for
 * n_b = 2.5, d = 20 µm, 0°; high-finesse films near grazing incidence take more.
 */
export const MIN_SAMPLES_PER_FRINGE = 8;
export const FINESSE_SAMPLES = 4;
/** Caps the cost where |r_ba r_bc| → 1 (near grazing); the fringes there are needle-thin dips. */
export const MAX_SAMPLES_PER_FRINGE = 2000;

export function adaptiveStepsPerNm(optics: FilmOptics): number {
  return stepsPerNmFor(Math.abs(optics.opticalPathNm.re), roundTripMagnitude(optics));
}

/** The largest |r_ba r_bc| of the optics' channels: how close eq (13)'s pole is to the unit circle. */
const roundTripMagnitude = (optics: FilmOptics): number =>
  Math.max(...optics.channels.map((c) => Math.hypot(c.roundTrip.re, c.roundTrip.im)));

/** Sub-steps per nm for fringes of a path `pathNm` (their density bound at 380 nm) and a round trip ρ. */
function stepsPerNmFor(pathNm: number, rho: number): number {
  if (pathNm === 0) return 1;
  const perFringe = Math.min(MAX_SAMPLES_PER_FRINGE, Math.max(MIN_SAMPLES_PER_FRINGE, FINESSE_SAMPLES / Math.max(1e-9, 1 - rho)));
  return Math.max(1, Math.ceil((perFringe * pathNm) / (LAMBDA_MIN_NM * LAMBDA_MIN_NM)));
}

/** Where a dispersive film's fringe density is sampled: every 10 nm of the band. */
const DISPERSION_PROBE_STEP_NM = 10;

/** What the sampling rule reads of a film's fringes at one λ: their path Re Δ (nm) and the round trip's magnitude ρ. */
export interface Fringes {
  readonly pathNm: number;
  readonly rho: number;
}

/**
 * The same rule for fringes whose path depends on λ (a dispersive film, a stack of films). The
 * phase φ = 2πΔ(λ)/λ then turns by 2πΔ_g/λ² per nm with the group path Δ_g = Δ − λ dΔ/dλ, so the
 * rule takes the largest Δ_g (dΔ/dλ by central differences over DISPERSION_PROBE_STEP_NM) and the
 * largest ρ over the band. For a path that does not vary, dΔ/dλ is exactly 0 and this is the rule
 * of the one path.
 */
export function fringeStepsPerNm(fringesAt: (lambdaNm: number) => Fringes): number {
  const lambdas = Array.from(
    { length: LAMBDA_SPAN_NM / DISPERSION_PROBE_STEP_NM + 1 },
    (_, k) => LAMBDA_MIN_NM + k * DISPERSION_PROBE_STEP_NM,
  );
  const fringes = lambdas.map(fringesAt);
  const path = fringes.map((f) => f.pathNm);
  let groupPath = 0;
  path.forEach((p, k) => {
    const [lo, hi] = [Math.max(0, k - 1), Math.min(path.length - 1, k + 1)];
    const slope = (path[hi]! - path[lo]!) / (lambdas[hi]! - lambdas[lo]!);
    groupPath = Math.max(groupPath, Math.abs(p - lambdas[k]! * slope));
  });
  return stepsPerNmFor(groupPath, Math.max(...fringes.map((f) => f.rho)));
}

/** fringeStepsPerNm of a film whose index depends on λ: for a constant index, adaptiveStepsPerNm of the one optics. */
export const dispersiveStepsPerNm = (opticsAt: (lambdaNm: number) => FilmOptics): number =>
  fringeStepsPerNm((l) => {
    const optics = opticsAt(l);
    return { pathNm: optics.opticalPathNm.re, rho: roundTripMagnitude(optics) };
  });

export interface ColorOptions {
  readonly illuminant?: IlluminantSpec;
  readonly polarization?: Polarization;
  readonly normalization?: Normalization;
  /** The light's tint (lightTint.ts); untinted when absent. */
  readonly lightTint?: LightTint;
  /** Fixed sub-steps per nm instead of the adaptive rule (for convergence studies). */
  readonly stepsPerNm?: number;
}

/**
 * XYZ of the light a film reflects, eqs (15)–(18). A dispersive film or inside (a material, a
 * Cauchy film, a tabulated metal) takes ñ(λ) exactly: Snell, Fresnel and the phase at every sample
 * (docs/physics.md#a-dispersive-film); an absorbing one takes the complex phase of
 * docs/physics.md#absorbing-media. Constant real indices take the path they always did.
 */
export function filmXyz(stack: FilmStack<Medium>, options: ColorOptions = {}): Xyz {
  const polarization = options.polarization ?? 'unpolarized';
  const w = spectralWeights(options.illuminant ?? 'D65', options.normalization ?? 'white', options.lightTint);
  if (![stack.nOutside, stack.nFilm, stack.nInside].some(isDispersiveMedium)) {
    const optics = filmOptics(mediumStackAt(stack, LAMBDA_MIN_NM), polarization);
    return integrateXyz((l) => reflectanceAt(optics, l), w, options.stepsPerNm ?? adaptiveStepsPerNm(optics));
  }
  assertMedium('nFilm', stack.nFilm, 'film');
  assertMedium('nInside', stack.nInside, 'inside');
  const opticsAt = (l: number) => filmOptics(mediumStackAt(stack, l), polarization);
  return integrateXyz((l) => reflectanceAt(opticsAt(l), l), w, options.stepsPerNm ?? dispersiveStepsPerNm(opticsAt));
}

/** R at one wavelength of a film whose media may depend on λ (eqs 1–14 with ñ_b(λ), ñ_c(λ)). */
export const dispersiveReflectance = (lambdaNm: number, stack: FilmStack<Medium>, polarization: Polarization = 'unpolarized'): number =>
  reflectanceAt(filmOptics(mediumStackAt(stack, lambdaNm), polarization), lambdaNm);

/** XYZ of the illuminant itself (a perfect white reflector), the white point for CIELAB. */
export const whiteXyz = (illuminant: IlluminantSpec, normalization: Normalization = 'white'): Xyz =>
  integrateXyz(() => 1, spectralWeights(illuminant, normalization), 1);
