import { type Complex, cMul } from './complex.ts';
import type { Polarization } from './filmReflectance.ts';
import { isDispersiveMedium } from './medium.ts';
import { type ColorOptions, type Fringes, fringeStepsPerNm, integrateXyz } from './spectralIntegration.ts';
import { LAMBDA_MIN_NM, type Xyz, spectralWeights } from './spectralWeights.ts';
import {
  type InterfaceAmplitudes,
  type LayerStack,
  type LayersOptics,
  airyStep,
  assertLayerStack,
  halfPhaseFactors,
  layersOpticsUnchecked,
  layersReflectanceAt,
} from './transferMatrix.ts';

/**
 * Where the light reaching deeper films has lost so much on its round trip (|Π e^{iφ_j}| below
 * this) that their fringes change R by less than about this much: their path no longer adds to
 * the fringe density (docs/physics.md#stacks-of-films).
 */
export const OPAQUE_ROUND_TRIP = 1e-9;

/**
 * |Γ_j Γ'_j e^{iφ_j}| of every layer j = 1 … N in one channel at λ: the gain of the layer's round
 * trip, which meets on its inner side Γ_j (the recursion's reflector of everything behind it) and
 * on its outer side Γ'_j (the same recursion run outward through the films before it), and loses
 * |e^{iφ_j}| on the way. A cavity between two mirrors has both near 1, however many films each
 * mirror takes; an opaque layer's gain is 0.
 */
function layerRoundTrips(interfaces: readonly InterfaceAmplitudes[], halfPhases: readonly Complex[]): number[] {
  const count = interfaces.length - 1;
  if (count === 0) return [];
  const square = (z: Complex) => cMul(z, z);
  const inner: Complex[] = [interfaces[count]!.r];
  for (let j = count - 1; j >= 1; j--) inner.unshift(airyStep(interfaces[j]!, inner[0]!, square(halfPhases[j]!)).reflector);
  let outer = interfaces[0]!.rBack;
  const magnitude = (z: Complex) => Math.hypot(z.re, z.im);
  return inner.map((gamma, i) => {
    if (i > 0) {
      const { r, t, rBack, tBack } = interfaces[i]!;
      outer = airyStep({ r: rBack, t: tBack, rBack: r, tBack: t }, outer, square(halfPhases[i - 1]!)).reflector;
    }
    return magnitude(gamma) * magnitude(outer) * magnitude(square(halfPhases[i]!));
  });
}

/**
 * The stack's fringes at λ for the sampling rule of docs/physics.md#sampling, as dense and as
 * sharp as one film's would be: their path is the sum of Re Δ_j over the films the light reaches
 * (the phases add, so R(λ) turns no faster than one film of the whole path), and their round trip
 * the largest gain |Γ_j Γ'_j e^{iφ_j}| of those films whose wave propagates (Re Δ_j > 0). For one
 * lossless layer this is |r_ba r_bc|, the film's own rule exactly; for an absorbing one at most
 * that (the film's rule leaves out the loss).
 */
function layerFringes(optics: LayersOptics, lambdaNm: number): Fringes {
  const halfPhases = halfPhaseFactors(optics, lambdaNm);
  const roundTrips = optics.channels.map((c) => layerRoundTrips(c, halfPhases));
  let pathNm = 0;
  let rho = 0;
  let reach = 1;
  optics.opticalPathsNm.forEach((path, j) => {
    if (reach < OPAQUE_ROUND_TRIP) return;
    pathNm += Math.abs(path.re);
    reach *= Math.exp((-2 * Math.PI * path.im) / lambdaNm);
    if (path.re !== 0) for (const trips of roundTrips) rho = Math.max(rho, trips[j]!);
  });
  return { pathNm, rho };
}

const isDispersiveStack = (stack: LayerStack): boolean =>
  [stack.nOutside, stack.nInside, ...stack.films.map((l) => l.n)].some(isDispersiveMedium);

/** The stack's optics at any λ: computed once when no medium depends on λ, at every λ otherwise. */
function opticsOf(stack: LayerStack, polarization: Polarization): (lambdaNm: number) => LayersOptics {
  if (isDispersiveStack(stack)) return (l) => layersOpticsUnchecked(stack, l, polarization);
  const fixed = layersOpticsUnchecked(stack, LAMBDA_MIN_NM, polarization);
  return () => fixed;
}

const stepsPerNmOf = (opticsAt: (lambdaNm: number) => LayersOptics): number => fringeStepsPerNm((l) => layerFringes(opticsAt(l), l));

/**
 * Sub-steps per nm of the adaptive rule for a stack: fringeStepsPerNm of its fringes
 * (layerFringes) at every probe wavelength, so a dispersive layer is taken at its group path. Cost
 * grows with the stack's total optical path: a few thousand R evaluations for stacks a few µm
 * thick, far more for tens of films each many µm thick.
 */
export function layersStepsPerNm(stack: LayerStack, polarization: Polarization = 'unpolarized'): number {
  assertLayerStack(stack);
  return stepsPerNmOf(opticsOf(stack, polarization));
}

/**
 * XYZ of the light a stack reflects, eqs (15)–(18) with R(λ) of the transfer matrix
 * (transferMatrix.ts), sampled by the adaptive rule sized by the stack's total optical path
 * (layersStepsPerNm) unless options.stepsPerNm fixes it. For one layer this is filmXyz.
 */
export function layersXyz(stack: LayerStack, options: ColorOptions = {}): Xyz {
  assertLayerStack(stack);
  const opticsAt = opticsOf(stack, options.polarization ?? 'unpolarized');
  const steps = options.stepsPerNm ?? stepsPerNmOf(opticsAt);
  const w = spectralWeights(options.illuminant ?? 'D65', options.normalization ?? 'white', options.lightTint);
  return integrateXyz((l) => layersReflectanceAt(opticsAt(l), l), w, steps);
}
