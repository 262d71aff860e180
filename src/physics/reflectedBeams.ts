import { type Complex, cAbs2, cAdd, cDiv, cExpI, cMul, cScale, cSub } from './complex.ts';
import { type Channel, type FilmStack, type Polarization, assertFilmStack, channelCoefficients, channelsOf } from './filmReflectance.ts';
import { fresnelCoefficients } from './fresnel.ts';
import { cosDeg, refractedCos } from './snell.ts';

/**
 * The beams of the paper's Figure 1, one by one: the light reflected at the top surface (E_0,
 * eq 3) and the light that enters the film and leaves it again after n round trips (E_1 eq 7,
 * E_n the n-th term of eq 13), each relative to the incident field E_inc:
 *   E_0 = r_ab,   E_n = t_ab t_ba r_bc (r_ba r_bc)^{n−1} e^{inφ}   (n ≥ 1),
 * whose sum is eq (13)'s closed form E = r_ab + t_ab t_ba r_bc e^{iφ} / (1 − r_ba r_bc e^{iφ}),
 * and R = |E|² (eq 14). Past a critical angle the cosines and φ are complex (snell.ts): in an
 * evanescent film |e^{iφ}| < 1 and the beams beyond E_0 fade with the thickness.
 */

/** The amplitude coefficients of one polarisation channel that the beams are products of (eqs 4–10). */
export interface BeamCoefficients {
  readonly rab: Complex;
  readonly tab: Complex;
  readonly tba: Complex;
  readonly rba: Complex;
  readonly rbc: Complex;
}

/** The film's angles: cos θ_ri in the film (eq 1) and cos θ_t behind it; imaginary past a critical angle. */
export interface FilmAngles {
  readonly cosRefracted: Complex;
  readonly cosTransmitted: Complex;
}

/** cos θ_ri and cos θ_t of a stack (eqs 1, 2). */
export function filmAngles(stack: FilmStack): FilmAngles {
  const cos = cosDeg(stack.angleDeg);
  return {
    cosRefracted: refractedCos(stack.nFilm, stack.nOutside, cos),
    cosTransmitted: refractedCos(stack.nInside, stack.nOutside, cos),
  };
}

/** The coefficients of one channel at the interfaces a→b, b→a and b→c. Throws a ParameterError outside FILM_STACK_DOMAIN. */
export function beamCoefficients(stack: FilmStack, channel: Channel): BeamCoefficients {
  assertFilmStack(stack);
  const { nOutside: na, nFilm: nb, nInside: nc } = stack;
  const cosI = refractedCos(na, na, cosDeg(stack.angleDeg));
  const { cosRefracted: cosR, cosTransmitted: cosT } = filmAngles(stack);
  const [rab, tab] = channelCoefficients(fresnelCoefficients(na, cosI, nb, cosR), channel) as [Complex, Complex];
  const [rba, tba] = channelCoefficients(fresnelCoefficients(nb, cosR, na, cosI), channel) as [Complex, Complex];
  const [rbc] = channelCoefficients(fresnelCoefficients(nb, cosR, nc, cosT), channel) as [Complex];
  return { rab, tab, tba, rba, rbc };
}

/** Δ = 2 n_b d cos θ_ri in nm: eq (12) with θ_ro = θ_ri (parallel faces), in its reduced form; complex when evanescent. */
export const opticalPathNm = (stack: FilmStack): Complex => cScale(filmAngles(stack).cosRefracted, 2 * stack.nFilm * stack.thicknessNm);

/** φ = 2πΔ/λ, eq (11). */
export const filmPhase = (stack: FilmStack, lambdaNm: number): Complex => cScale(opticalPathNm(stack), (2 * Math.PI) / lambdaNm);

/**
 * How many beams are summed one by one: after E_N the tail Σ_{n>N} E_n is bounded by
 * |t_ab t_ba r_bc| |x|^N / (1 − |x|), x = r_ba r_bc e^{iφ}, and N is the least N ≥ 1 whose bound
 * is below this fraction of the incident amplitude.
 */
export const BEAM_TAIL_FRACTION = 1e-3;
/** Beams drawn at most; where the bound needs more (|x| → 1), the rest is one closed-form tail. */
export const MAX_BEAMS = 12;

export interface BeamOptions {
  /** Reverse r_ab's sign in E_0 only (a top surface without its phase flip): not physics, a lesson. */
  readonly flipTop?: boolean;
  readonly tailFraction?: number;
  readonly maxBeams?: number;
}

export interface ReflectedBeams {
  /** E_0 … E_N, relative to E_inc. */
  readonly beams: readonly Complex[];
  /** E, eq (13)'s closed form (with E_0's sign reversed under flipTop). */
  readonly total: Complex;
  /** The bound on |E − Σ beams|; Infinity where |x| ≥ 1 (the series itself does not converge). */
  readonly tailBound: number;
}

/** The beams of one channel at phase φ. */
export function reflectedBeams(c: BeamCoefficients, phase: Complex, options: BeamOptions = {}): ReflectedBeams {
  const { flipTop = false, tailFraction = BEAM_TAIL_FRACTION, maxBeams = MAX_BEAMS } = options;
  const e0 = flipTop ? cScale(c.rab, -1) : c.rab;
  const z = cExpI(phase);
  const first = cMul(cMul(cMul(c.tab, c.tba), c.rbc), z); // E_1, eq (7)
  if (first.re === 0 && first.im === 0) return { beams: [e0], total: e0, tailBound: 0 };
  const x = cMul(cMul(c.rba, c.rbc), z);
  const ratio = Math.sqrt(cAbs2(x));
  const bound = (n: number) => (ratio < 1 ? (Math.sqrt(cAbs2(first)) * ratio ** n) / (1 - ratio) : Infinity);
  const beams = [e0, first];
  while (beams.length <= maxBeams && bound(beams.length - 1) > tailFraction) beams.push(cMul(beams[beams.length - 1]!, x));
  const total = cAdd(e0, cDiv(first, cSub({ re: 1, im: 0 }, x)));
  return { beams, total, tailBound: bound(beams.length - 1) };
}

/** One channel of a film's beams: its coefficients and its beams. */
export interface ChannelBeams {
  readonly channel: Channel;
  readonly coefficients: BeamCoefficients;
  readonly beams: ReflectedBeams;
}

/** The beams of every channel a polarisation averages, and R = the mean of |E|² (eq 14). */
export interface FilmBeams {
  readonly channels: readonly ChannelBeams[];
  readonly reflectance: number;
}

/** Figure 1 at one wavelength: each channel's beams and the film's R. Domain: FILM_STACK_DOMAIN, λ > 0. */
export function filmBeams(stack: FilmStack, polarization: Polarization, lambdaNm: number, options: BeamOptions = {}): FilmBeams {
  const phase = filmPhase(stack, lambdaNm);
  const channels = channelsOf(polarization).map((channel): ChannelBeams => {
    const coefficients = beamCoefficients(stack, channel);
    return { channel, coefficients, beams: reflectedBeams(coefficients, phase, options) };
  });
  const reflectance = channels.reduce((sum, c) => sum + cAbs2(c.beams.total), 0) / channels.length;
  return { channels, reflectance };
}
