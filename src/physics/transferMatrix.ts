import { type Complex, type RefractiveIndex, cAbs2, cAdd, cDiv, cExpI, cMul, cScale, cSub, cTimesIndex, sameIndex } from './complex.ts';
import { LAYERS_DOMAIN, type ResolvedLayer } from './stackFilms.ts';
import { FILM_STACK_DOMAIN, type Polarization, channelCoefficients, channelsOf } from './filmReflectance.ts';
import { fresnelCoefficients, transmittedFluxRatio } from './fresnel.ts';
import { type Medium, assertMedium, mediumIndexAt, transparentIndexAt } from './medium.ts';
import { cosDeg, refractedCos } from './snell.ts';
import { assertInRange } from '../input/validate.ts';

/**
 * Every film: a stack of one or more films between a transparent outside and an inside
 * (docs/physics.md#stacks-of-films). The media are numbered 0 (the outside), 1…N (the films, outside
 * in) and N + 1 (the inside). Domain (LAYERS_DOMAIN, FILM_STACK_DOMAIN): 1–64 films, each
 * 0–20 000 nm thick and of any medium a film takes (a real n in [1, 4], water, a Cauchy film, a named
 * medium, complex:n,k); the inside any medium the single film's inside takes; the outside a real n in
 * [1, 4] where a user gives it (assertLayerStack), any transparent medium where the film is seen from
 * inside a glass sphere; θ_i in [0°, 90°]. One layer is the film of the paper's eqs (1)–(14)
 * (FilmStack, filmReflectance.ts), whose fast paths src/methods/filmStacks.ts takes for it.
 */
export interface LayerStack {
  readonly nOutside: Medium;
  readonly films: readonly ResolvedLayer[];
  readonly nInside: Medium;
  readonly angleDeg: number;
}

/** Throws a ParameterError naming the first field outside the domain of LayerStack (`films[i].n`, `films[i].thicknessNm`, …). */
export function assertLayerStack(stack: LayerStack): void {
  assertMedium('nOutside', stack.nOutside, 'outside');
  const { count, thicknessNm } = LAYERS_DOMAIN;
  assertInRange('films', stack.films.length, count.min, count.max, count.unit);
  stack.films.forEach((film, i) => {
    assertMedium(`films[${i}].n`, film.n, 'film');
    assertInRange(`films[${i}].thicknessNm`, film.thicknessNm, thicknessNm.min, thicknessNm.max, thicknessNm.unit);
  });
  assertMedium('nInside', stack.nInside, 'inside');
  const { angleDeg } = FILM_STACK_DOMAIN;
  assertInRange('angleDeg', stack.angleDeg, angleDeg.min, angleDeg.max, angleDeg.unit);
}

/** One interface j → j + 1 in one polarisation channel: what a step of the recursion takes. */
export interface InterfaceAmplitudes {
  /** r_{j,j+1} */ readonly r: Complex;
  /** t_{j,j+1} */ readonly t: Complex;
  /** r_{j+1,j} */ readonly rBack: Complex;
  /** t_{j+1,j} */ readonly tBack: Complex;
}

/** Everything about a stack at one wavelength except the phases' 1/λ: the analogue of FilmOptics. */
export interface LayersOptics {
  /** Per channel of channelsOf(polarization), the interfaces 0|1, 1|2, …, N|N+1. */
  readonly channels: readonly (readonly InterfaceAmplitudes[])[];
  /** Per layer 1…N: Δ_j = 2 ñ_j d_j cos θ_j in nm (eq 12 reduced), complex where the layer absorbs or the wave is evanescent. */
  readonly opticalPathsNm: readonly Complex[];
  /** Re(ñ_{N+1} cos θ_{N+1}) / (n_0 cos θ_0), as the single film's; 0 for an absorbing inside. */
  readonly fluxRatio: number;
}

const ZERO: Complex = { re: 0, im: 0 };
const ONE: Complex = { re: 1, im: 0 };
const isZero = (z: Complex): boolean => z.re === 0 && z.im === 0;

/**
 * The stack's optics at λ, unchecked (assertLayerStack first): Snell (eqs 1, 2) in every medium on
 * the decaying branch, the Fresnel coefficients of every interface both ways (eqs 5, 6, 9, 10, or
 * eqs 4, 8 in `paper`), each layer's Δ_j. In the physical channels a 0 nm layer is left out, as
 * the single film takes its bare interface at d = 0 (docs/physics.md#thickness-zero); `paper`
 * keeps it, as the film keeps eq (13) there.
 */
export function layersOpticsUnchecked(stack: LayerStack, lambdaNm: number, polarization: Polarization): LayersOptics {
  const n0 = transparentIndexAt(stack.nOutside, lambdaNm);
  const cosIncidence = cosDeg(stack.angleDeg);
  const films = polarization === 'paper' ? stack.films : stack.films.filter((l) => l.thicknessNm > 0);
  const indices: RefractiveIndex[] = [n0, ...films.map((l) => mediumIndexAt(l.n, lambdaNm)), mediumIndexAt(stack.nInside, lambdaNm)];
  const cos = indices.map((n) => refractedCos(n, n0, cosIncidence));
  const interfaces = indices.slice(1).map((next, j) => ({
    forward: fresnelCoefficients(indices[j]!, cos[j]!, next, cos[j + 1]!),
    back: fresnelCoefficients(next, cos[j + 1]!, indices[j]!, cos[j]!),
  }));
  const channels = channelsOf(polarization).map((k) =>
    interfaces.map(({ forward, back }) => {
      const [r, t] = channelCoefficients(forward, k) as [Complex, Complex];
      const [rBack, tBack] = channelCoefficients(back, k) as [Complex, Complex];
      return { r, t, rBack, tBack };
    }),
  );
  const opticalPathsNm = films.map((l, i) => cScale(cTimesIndex(cos[i + 1]!, indices[i + 1]!), 2 * l.thicknessNm));
  // As for the single film: at exact grazing incidence only a stack with no interface at all passes light.
  const noInterface = indices.every((n) => sameIndex(n, n0));
  const fluxRatio = transmittedFluxRatio(n0, cos[0]!, indices[indices.length - 1]!, cos[cos.length - 1]!, noInterface);
  return { channels, opticalPathsNm, fluxRatio };
}

/** layersOpticsUnchecked after assertLayerStack: a stack outside its domain throws a ParameterError. */
export function layersOptics(stack: LayerStack, lambdaNm: number, polarization: Polarization = 'unpolarized'): LayersOptics {
  assertLayerStack(stack);
  return layersOpticsUnchecked(stack, lambdaNm, polarization);
}

/** e^{iφ_j/2} of every layer at λ, φ_j = 2πΔ_j/λ = 4π ñ_j d_j cos θ_j / λ (eq 11); |·| ≤ 1 on the decaying branch. */
export const halfPhaseFactors = (optics: LayersOptics, lambdaNm: number): Complex[] =>
  optics.opticalPathsNm.map((path) => cExpI(cScale(path, Math.PI / lambdaNm)));

/**
 * One step of the recursion through the interface j|j+1 and the layer j + 1 behind it, whose far
 * side reflects `behind` (Γ_{j+1}) and whose round trip is z = e^{iφ_{j+1}}: eq (13) with r_bc → Γ_{j+1},
 *   Γ_j = r_{j,j+1} + t_{j,j+1} t_{j+1,j} Γ_{j+1} z / loop,   loop = 1 − r_{j+1,j} Γ_{j+1} z.
 * Where the numerator is exactly 0 (no light crosses: grazing incidence, a layer at its exact
 * critical angle) Γ_j is r_{j,j+1}, as in the single film, rather than 0/0.
 */
export function airyStep(step: InterfaceAmplitudes, behind: Complex, z: Complex): { reflector: Complex; loop: Complex } {
  const echo = cMul(behind, z);
  const loop = cSub(ONE, cMul(step.rBack, echo));
  const multiple = cMul(cMul(step.t, step.tBack), echo);
  return { reflector: isZero(multiple) ? step.r : cAdd(step.r, cDiv(multiple, loop)), loop };
}

/**
 * The reflected and transmitted amplitudes Γ_0, τ_0 of one channel by the Airy (Rouard) recursion,
 * from the inside out (Rouard 1937; Heavens, Optical Properties of Thin Solid Films, 1955): the
 * transfer-matrix result of Born & Wolf §1.6 and Byrnes 2016 (arXiv:1603.02720) in another form,
 *   Γ_N = r_{N,N+1},  τ_N = t_{N,N+1},  and for j = N−1 … 0 (airyStep), with z = e^{iφ_{j+1}},
 *   Γ_j = r_{j,j+1} + t_{j,j+1} t_{j+1,j} Γ_{j+1} z / (1 − r_{j+1,j} Γ_{j+1} z),
 *   τ_j = t_{j,j+1} τ_{j+1} z^{1/2} / (1 − r_{j+1,j} Γ_{j+1} z).
 * Each step is eq (13) with the films behind the interface folded into one reflector Γ_{j+1}, so
 * one layer is eq (13) itself. |z| ≤ 1, so a thick evanescent or absorbing layer makes z underflow
 * to 0 and every value stays finite, where a product of 2×2 characteristic matrices overflows.
 * `interfaces` are 0|1 … N|N+1, `halfPhases` e^{iφ_j/2} of films 1 … N.
 */
export function channelAmplitudes(interfaces: readonly InterfaceAmplitudes[], halfPhases: readonly Complex[]): { r: Complex; t: Complex } {
  const last = interfaces[interfaces.length - 1]!;
  let gamma = last.r;
  let tau = last.t;
  for (let j = interfaces.length - 2; j >= 0; j--) {
    const step = interfaces[j]!;
    const zHalf = halfPhases[j]!;
    const { reflector, loop } = airyStep(step, gamma, cMul(zHalf, zHalf));
    const through = cMul(cMul(step.t, tau), zHalf);
    tau = isZero(through) ? ZERO : cDiv(through, loop);
    gamma = reflector;
  }
  return { r: gamma, t: tau };
}

/** R at λ: |Γ_0|² averaged over the channels, held to [0, 1] against an ulp of overshoot under total reflection. Domain: λ > 0. */
export function layersReflectanceAt(optics: LayersOptics, lambdaNm: number): number {
  const halfPhases = halfPhaseFactors(optics, lambdaNm);
  let sum = 0;
  for (const c of optics.channels) sum += cAbs2(channelAmplitudes(c, halfPhases).r);
  return Math.min(1, sum / optics.channels.length);
}

/** T at λ: the flux ratio times |τ_0|², averaged over the channels; 0 into an absorbing inside. */
export function layersTransmittanceAt(optics: LayersOptics, lambdaNm: number): number {
  if (optics.fluxRatio === 0) return 0;
  const halfPhases = halfPhaseFactors(optics, lambdaNm);
  let sum = 0;
  for (const c of optics.channels) sum += cAbs2(channelAmplitudes(c, halfPhases).t);
  return (optics.fluxRatio * sum) / optics.channels.length;
}

/** R(λ) of a stack (Born & Wolf §1.6; Byrnes 2016): for one layer exactly filmReflectance, in every polarisation mode. */
export const layersReflectance = (lambdaNm: number, stack: LayerStack, polarization: Polarization = 'unpolarized'): number =>
  layersReflectanceAt(layersOptics(stack, lambdaNm, polarization), lambdaNm);

/** T(λ) of a stack, the fraction carried into the inside. */
export const layersTransmittance = (lambdaNm: number, stack: LayerStack, polarization: Polarization = 'unpolarized'): number =>
  layersTransmittanceAt(layersOptics(stack, lambdaNm, polarization), lambdaNm);

/**
 * A(λ) = 1 − R − T: what the films absorb, plus all that enters an absorbing inside. 0 to rounding
 * for a lossless stack in the physical modes; in `paper`, whose amplitudes conserve no energy, only a remainder.
 */
export function layersAbsorptance(lambdaNm: number, stack: LayerStack, polarization: Polarization = 'unpolarized'): number {
  const optics = layersOptics(stack, lambdaNm, polarization);
  return 1 - layersReflectanceAt(optics, lambdaNm) - layersTransmittanceAt(optics, lambdaNm);
}

/** R at each of a list of wavelengths (nm, > 0), the stack checked once. */
export function layersReflectanceSpectrum(
  stack: LayerStack,
  lambdasNm: readonly number[],
  polarization: Polarization = 'unpolarized',
): number[] {
  assertLayerStack(stack);
  return lambdasNm.map((l) => layersReflectanceAt(layersOpticsUnchecked(stack, l, polarization), l));
}
