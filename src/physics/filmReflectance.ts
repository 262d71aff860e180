import {
  type Complex,
  type RefractiveIndex,
  cAbs2,
  cAdd,
  cDiv,
  cExpI,
  cMul,
  cScale,
  cSub,
  cTimesIndex,
  realIndex,
  sameIndex,
} from './complex.ts';
import { type InterfaceCoefficients, fresnelCoefficients, transmittedFluxRatio } from './fresnel.ts';
import type { Medium } from './medium.ts';
import { cosDeg, refractedCos } from './snell.ts';
import { type NumberDomain, ParameterError, assertInRange, isInDomain } from '../input/validate.ts';

/**
 * How the two polarisations are combined:
 * - `unpolarized`: R = (R_s + R_p)/2, each with its own Airy sum (physical; the default);
 * - `paper`: the paper's eqs (4) and (8), which average the s and p *amplitudes* first and then
 *   sum once. Its r_ab vanishes at normal incidence, so R ≡ 0 there (docs/physics.md#paper-mode-at-normal-incidence);
 * - `s`, `p`: one polarisation only.
 */
export const POLARIZATIONS = ['unpolarized', 'paper', 's', 'p'] as const;
export type Polarization = (typeof POLARIZATIONS)[number];

/**
 * The outside of a film whose film and inside are of kind N: a real constant where they are indices
 * (numbers or ñ), any transparent Medium where they are media (the far wall seen from inside a glass
 * sphere: its n at each λ).
 */
type OutsideOf<N> = [N] extends [RefractiveIndex] ? number : Medium;

/**
 * A film b of thickness d between an outside medium a and an inside medium c, lit at θ_i: one layer
 * of a stack (docs/physics.md#stacks-of-films), the film of the paper's eqs (1)–(14). Its film and
 * inside are of one kind N:
 * - `number` (the default): real indices, each within FILM_STACK_DOMAIN;
 * - `RefractiveIndex`: a film and an inside that may absorb (ñ = n + ik, docs/physics.md#absorbing-media),
 *   ñ within COMPLEX_INDEX_DOMAIN; the outside, where the light comes from and returns to, stays transparent;
 * - `Medium`: media whose ñ may depend on λ (medium.ts); `mediumStackAt` gives the film at one λ.
 */
export interface FilmStack<N extends RefractiveIndex | Medium = number> {
  /** n_a, 1 ≤ n ≤ 4 */ readonly nOutside: OutsideOf<N>;
  /** n_b, 1 ≤ n ≤ 4 */ readonly nFilm: N;
  /** n_c, 1 ≤ n ≤ 4 */ readonly nInside: N;
  /** d in nm, 0 ≤ d ≤ 20 000 (the documented domain; larger is finite but slow to integrate) */
  readonly thicknessNm: number;
  /** θ_i in degrees, 0 ≤ θ ≤ 90 */ readonly angleDeg: number;
}

/** The domain of each field of a FilmStack: what every entry point checks and filmOptics enforces. */
export const FILM_STACK_DOMAIN = {
  nOutside: { min: 1, max: 4, unit: '' },
  nFilm: { min: 1, max: 4, unit: '' },
  nInside: { min: 1, max: 4, unit: '' },
  thicknessNm: { min: 0, max: 20_000, unit: 'nm' },
  angleDeg: { min: 0, max: 90, unit: 'degrees' },
} as const satisfies Record<keyof FilmStack, NumberDomain>;

/**
 * The domain of a complex index ñ = n + ik (film or inside): n > 0 (metals have n well below 1;
 * the floor keeps cos θ = (ñ cos θ)/ñ finite) and 0 ≤ k (absorbing, never gain). The upper ends
 * are far past any tabulated material (k ≈ 9 for aluminium at 830 nm) and leave room for the
 * perfect-conductor limit k → ∞.
 */
export const COMPLEX_INDEX_DOMAIN = {
  n: { min: 0.01, max: 10, unit: '' },
  k: { min: 0, max: 100, unit: '' },
} as const satisfies Record<'n' | 'k', NumberDomain>;

/** ñ as messages write it: `0.43+2.455i`. */
export const complexIndexText = (n: Complex): string => `${n.re}${n.im < 0 ? '-' : '+'}${Math.abs(n.im)}i`;

/** What is wrong with a complex index (null: nothing), in words a message can quote. */
export function complexIndexProblem(n: Complex): string | null {
  for (const [name, value, domain] of [
    ['n', n.re, COMPLEX_INDEX_DOMAIN.n],
    ['k', n.im, COMPLEX_INDEX_DOMAIN.k],
  ] as const) {
    const v: number = value;
    if (isInDomain(v, domain)) continue;
    if (!Number.isFinite(v)) return `${name} is not a finite number`;
    const gain = name === 'k' && v < 0 ? ' (k < 0 would be a medium with gain)' : '';
    return `${name} is ${String(v)}, ${v < domain.min ? `below ${domain.min}` : `above ${domain.max}`}${gain}`;
  }
  return null;
}

/** Throws a ParameterError naming the first field outside FILM_STACK_DOMAIN (NaN and ±Infinity included). */
export function assertFilmStack(stack: FilmStack<RefractiveIndex>): void {
  for (const field of Object.keys(FILM_STACK_DOMAIN) as (keyof FilmStack)[]) {
    const { min, max, unit } = FILM_STACK_DOMAIN[field];
    const value = stack[field];
    if (typeof value === 'number') {
      assertInRange(field, value, min, max, unit);
      continue;
    }
    const problem = complexIndexProblem(value);
    if (problem) throw new ParameterError(field, `${field}: ${complexIndexText(value)} is not allowed (${problem})`);
  }
}

export const SOAP_FILM_IN_AIR = { nOutside: 1, nFilm: 1.33, nInside: 1 } as const;

/**
 * The λ-independent factors of eq (13) for one polarisation channel:
 * r = r_ab + (t_ab t_ba r_bc) e^{iφ} / (1 − r_ba r_bc e^{iφ}), and the transmitted amplitude
 * t = (t_ab t_bc) e^{iφ/2} / (1 − r_ba r_bc e^{iφ}).
 */
export interface AiryTerms {
  readonly rab: Complex;
  /** t_ab t_ba r_bc: zero when no light enters the film (grazing incidence) */
  readonly multiple: Complex;
  /** r_ba r_bc, the round-trip factor of eq (13)'s geometric series */
  readonly roundTrip: Complex;
  /** t_ab t_bc */
  readonly through: Complex;
}

/** Everything about a film that does not depend on λ (the indices are dispersionless). */
export interface FilmOptics {
  /** Channels whose reflectances are averaged: [s, p] for unpolarized, one otherwise. */
  readonly channels: readonly AiryTerms[];
  /** Δ = 2 n_b d cos θ_r in nm, the reduced form of eq (12); complex past the critical angle or in an absorbing film. */
  readonly opticalPathNm: Complex;
  /** Re(n_c cos θ_t) / (n_a cos θ_i), the ratio of normal energy fluxes for T (its limit at grazing); 0 for an absorbing inside. */
  readonly fluxRatio: number;
}

const ZERO: Complex = { re: 0, im: 0 };
const ONE: Complex = { re: 1, im: 0 };

function airyTerms(ab: Complex[], ba: Complex[], bc: Complex[]): AiryTerms {
  const [rab, tab] = ab as [Complex, Complex];
  const [rba, tba] = ba as [Complex, Complex];
  const [rbc, tbc] = bc as [Complex, Complex];
  return { rab, multiple: cMul(cMul(tab, tba), rbc), roundTrip: cMul(rba, rbc), through: cMul(tab, tbc) };
}

/** One polarisation channel of an interface: s, p, or the paper's amplitude average of the two (eqs 4, 8). */
export type Channel = 's' | 'p' | 'paper';

/** [r, t] of one channel of an interface: its s or p coefficients, or in `paper` their averages (eqs 4, 8). */
export const channelCoefficients = (c: InterfaceCoefficients, channel: Channel): Complex[] =>
  channel === 'paper' ? [cScale(cAdd(c.rs, c.rp), 0.5), cScale(cAdd(c.ts, c.tp), 0.5)] : channel === 's' ? [c.rs, c.ts] : [c.rp, c.tp];

/** The channels whose reflectances a polarisation averages: [s, p] for unpolarized, one otherwise. */
export const channelsOf = (polarization: Polarization): Channel[] => (polarization === 'unpolarized' ? ['s', 'p'] : [polarization]);

/**
 * A zero-thickness film in the physical channels (s, p): the bare a|c interface. This is eq (13)'s
 * own value at d = 0 (φ = 0): by the Stokes relations t_ab t_ba = 1 − r_ab², r_ba = −r_ab,
 * r_ab + t_ab t_ba r_bc / (1 − r_ba r_bc) = r_ac. It also gives the θ → 90° limit where eq (13)
 * read literally does not: at exact grazing t_ab = 0 makes it |r_ab|² = 1 even when n_a = n_c.
 * The paper's averaged amplitudes (eqs 4, 8) obey no Stokes relation, so `paper` keeps eq (13) at
 * d = 0 (R is then continuous in d; docs/physics.md, "Thickness 0").
 */
const bareInterface = ([r, t]: Complex[]): AiryTerms => ({
  rab: r as Complex,
  multiple: ZERO,
  roundTrip: ZERO,
  through: t as Complex,
});

/**
 * The λ-independent part of the film's optics: Snell (eqs 1, 2), the Fresnel coefficients of
 * the three interfaces a→b, b→a, b→c (eqs 5, 6, 9, 10, with eqs 4 and 8 in `paper` mode), and
 * the optical path difference Δ (eq 12, reduced to 2 n_b d cos θ_r). A stack outside
 * FILM_STACK_DOMAIN throws a ParameterError before anything is computed.
 */
export function filmOptics(stack: FilmStack<RefractiveIndex>, polarization: Polarization = 'unpolarized'): FilmOptics {
  assertFilmStack(stack);
  const { nOutside: na, nFilm: nb, nInside: nc, thicknessNm: d } = stack;
  const cos = cosDeg(stack.angleDeg);
  const cosI = refractedCos(na, na, cos);
  const cosR = refractedCos(nb, na, cos);
  const cosT = refractedCos(nc, na, cos);
  // At exact grazing incidence no energy crosses any real interface (R = 1); only where there is
  // no interface at all (n_c = n_a and the film absent or index-matched) does the light go on. The
  // paper mode keeps eq (13) at d = 0, whose t_ab = 0 at grazing reflects everything there too.
  // An absorbing inside is opaque: what crosses into it is absorbed there, so T = 0.
  const noInterface = sameIndex(na, nc) && ((d === 0 && polarization !== 'paper') || sameIndex(na, nb));
  const fluxRatio = transmittedFluxRatio(na, cosI, nc, cosT, noInterface);
  // Δ = 2 ñ_b d cos θ_r, complex for an absorbing film (Im Δ > 0: the round trip's attenuation).
  const realFilm = realIndex(nb);
  const opticalPathNm = realFilm === null ? cScale(cTimesIndex(cosR, nb), 2 * d) : cScale(cosR, 2 * realFilm * d);

  const kinds = channelsOf(polarization);

  const ab = fresnelCoefficients(na, cosI, nb, cosR);
  const ba = fresnelCoefficients(nb, cosR, na, cosI);
  const bc = fresnelCoefficients(nb, cosR, nc, cosT);
  const ac = d === 0 ? fresnelCoefficients(na, cosI, nc, cosT) : null;
  return {
    channels: kinds.map((k) =>
      ac && k !== 'paper'
        ? bareInterface(channelCoefficients(ac, k))
        : airyTerms(channelCoefficients(ab, k), channelCoefficients(ba, k), channelCoefficients(bc, k)),
    ),
    opticalPathNm,
    fluxRatio,
  };
}

/** e^{iφ} with φ = 2πΔ/λ, eq (11). */
const phaseFactor = (optics: FilmOptics, lambdaNm: number, fraction = 1): Complex =>
  cExpI(cScale(optics.opticalPathNm, (fraction * 2 * Math.PI) / lambdaNm));

/**
 * R at one wavelength, eqs (13)–(14), averaged over the channels. Domain: λ > 0.
 * |r|² ≤ 1 holds exactly; rounding can overshoot it by an ulp under total reflection, so the
 * result is held to [0, 1].
 */
export function reflectanceAt(optics: FilmOptics, lambdaNm: number): number {
  const z = phaseFactor(optics, lambdaNm);
  let sum = 0;
  for (const c of optics.channels) {
    const series = c.multiple.re === 0 && c.multiple.im === 0 ? ZERO : cDiv(cMul(c.multiple, z), cSub(ONE, cMul(c.roundTrip, z)));
    sum += cAbs2(cAdd(c.rab, series));
  }
  return Math.min(1, sum / optics.channels.length);
}

/**
 * T at one wavelength: |t|² times the flux ratio, with t = t_ab t_bc e^{iφ/2} / (1 − r_ba r_bc e^{iφ})
 * (the transmitted counterpart of eq 13). For real indices R + T = 1 in the physical modes;
 * the paper's amplitude average does not conserve energy, so its T is not 1 − R.
 */
export function transmittanceAt(optics: FilmOptics, lambdaNm: number): number {
  if (optics.fluxRatio === 0) return 0;
  const z = phaseFactor(optics, lambdaNm);
  const zHalf = phaseFactor(optics, lambdaNm, 0.5);
  let sum = 0;
  for (const c of optics.channels) {
    sum += cAbs2(cDiv(cMul(c.through, zHalf), cSub(ONE, cMul(c.roundTrip, z))));
  }
  return (optics.fluxRatio * sum) / optics.channels.length;
}

/** R(λ; n_a, n_b, n_c, d, θ_i): eqs (1)–(14) in one call. */
export const filmReflectance = (lambdaNm: number, stack: FilmStack<RefractiveIndex>, polarization: Polarization = 'unpolarized') =>
  reflectanceAt(filmOptics(stack, polarization), lambdaNm);

/** T(λ; n_a, n_b, n_c, d, θ_i), the transmitted fraction. */
export const filmTransmittance = (lambdaNm: number, stack: FilmStack<RefractiveIndex>, polarization: Polarization = 'unpolarized') =>
  transmittanceAt(filmOptics(stack, polarization), lambdaNm);

/**
 * The mean of one channel's R over the phase window [φ0 − w, φ0 + w], in closed form.
 *
 * Eq (13) rewritten as r = (α + β z)/(1 − c z) with z = e^{iφ}, α = r_ab, β = t_ab t_ba r_bc − r_ab c,
 * c = r_ba r_bc = ρ e^{iγ}, gives R = (a0 + 2 Re(ᾱβ z)) / D(ψ), a0 = |α|² + |β|²,
 * D(ψ) = 1 + ρ² − 2ρ cos ψ, ψ = φ + γ. With u = ᾱβ/c the antiderivatives are elementary:
 *   ∫ dψ/D = (ψ + 2 atan2(ρ sin ψ, 1 − ρ cos ψ)) / (1 − ρ²),   ∫ sin ψ dψ/D = ln D / (2ρ),
 * so, writing δA for the atan2 difference over the window divided by w and L for
 * ln(D(ψ0+w)/D(ψ0−w)) / (2w) (both formed without cancellation),
 *   R̄ = (a0 (1 + δA) + Re u (2ρ² + (1 + ρ²) δA)) / (1 − ρ²) − Im u · L.
 * This is how fringes finer than a wavelength bin or a table cell average instead of aliasing
 * (docs/physics.md#closed-form-mean). Domain: real φ0, w ≥ 0, ρ < 1 (ρ → 1 only at grazing, where R is |r_ab|²).
 */
export function meanChannelReflectance(c: AiryTerms, phaseCenter: number, halfWidth: number): number {
  const alpha = c.rab;
  const beta = cSub(c.multiple, cMul(c.rab, c.roundTrip));
  const a0 = cAbs2(alpha) + cAbs2(beta);
  const ab = cMul({ re: alpha.re, im: -alpha.im }, beta);
  const rho2 = cAbs2(c.roundTrip);
  const w = halfWidth;
  const sinc = w === 0 ? 1 : Math.sin(w) / w;
  if (c.multiple.re === 0 && c.multiple.im === 0) return cAbs2(alpha);
  if (rho2 === 0) {
    // No round trip: R = a0 + 2 Re(ᾱβ z), whose mean is exact with sinc(w).
    return a0 + 2 * sinc * (ab.re * Math.cos(phaseCenter) - ab.im * Math.sin(phaseCenter));
  }
  const rho = Math.sqrt(rho2);
  const psi0 = phaseCenter + Math.atan2(c.roundTrip.im, c.roundTrip.re);
  const u = cDiv(ab, c.roundTrip);
  const cosW = Math.cos(w),
    cos0 = Math.cos(psi0),
    sin0 = Math.sin(psi0);
  // δA = [A(ψ0+w) − A(ψ0−w)] / w, A(ψ) = arg(1 − ρ e^{−iψ}); the difference is one atan2.
  const y = 2 * rho * sinc * (cos0 - rho * cosW);
  const x = 1 - 2 * rho * cos0 * cosW + rho2 * Math.cos(2 * w);
  const dA = w < 1e-4 ? y / x : Math.atan2(y * w, x) / w;
  // L = atanh(q)/w with q = (D+ − D−)/(D+ + D−) = 4ρ sin ψ0 sin w / (D+ + D−).
  const dPlus = 1 + rho2 - 2 * rho * Math.cos(psi0 + w);
  const dMinus = 1 + rho2 - 2 * rho * Math.cos(psi0 - w);
  const qOverW = (4 * rho * sin0 * sinc) / (dPlus + dMinus);
  const q = qOverW * w;
  // Below |q| = 1e-3, atanh(q)/q = 1 + q²/3 to 2e-13 (the next term is q⁴/5); the shader's twin uses the
  // same threshold, where float32's atanh of a small q would also lose digits.
  const L = Math.abs(q) < 1e-3 ? qOverW * (1 + (q * q) / 3) : (Math.atanh(q) / q) * qOverW;
  return (a0 * (1 + dA) + u.re * (2 * rho2 + (1 + rho2) * dA)) / (1 - rho2) - u.im * L;
}
