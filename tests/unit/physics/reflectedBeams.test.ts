import { describe, expect, it } from 'vitest';
import { type Complex, cAbs2, cAdd, cExpI, cMul, cScale } from '../../../src/physics/complex.ts';
import { type FilmStack, type Polarization, filmReflectance } from '../../../src/physics/filmReflectance.ts';
import { fresnelCoefficients } from '../../../src/physics/fresnel.ts';
import { BEAM_TAIL_FRACTION, MAX_BEAMS, filmBeams } from '../../../src/physics/reflectedBeams.ts';
import { cosDeg, refractedCos } from '../../../src/physics/snell.ts';
import { ALGEBRAIC_TOL, BEAM_SUM_TOL, GOLDEN_TOL, THIN_FILM_LIMIT_TOL } from '../../tolerances.ts';

/**
 * Figure 1's beams recomputed here from the equations: Snell (eq 1) and the Fresnel coefficients
 * (eqs 5, 6, 9, 10; averaged by eqs 4 and 8 in the paper's mode), then E_0 = r_ab (eq 3) and
 * E_n = t_ab t_ba r_bc (r_ba r_bc)^{n−1} e^{inφ} (eqs 7, 13) with e^{inφ} taken directly, not as a
 * power, and summed one by one until the terms are below 1e-16.
 */
type Kind = 's' | 'p' | 'paper';
const CHANNELS: Record<Polarization, Kind[]> = { unpolarized: ['s', 'p'], s: ['s'], p: ['p'], paper: ['paper'] };
const half = (a: Complex, b: Complex) => cScale(cAdd(a, b), 0.5);

function coefficients(s: FilmStack, kind: Kind) {
  const cos = cosDeg(s.angleDeg);
  const cosI = { re: cos, im: 0 };
  const cosR = refractedCos(s.nFilm, s.nOutside, cos);
  const cosT = refractedCos(s.nInside, s.nOutside, cos);
  const pick = (n1: number, c1: Complex, n2: number, c2: Complex) => {
    const f = fresnelCoefficients(n1, c1, n2, c2);
    return kind === 'paper' ? { r: half(f.rs, f.rp), t: half(f.ts, f.tp) } : kind === 's' ? { r: f.rs, t: f.ts } : { r: f.rp, t: f.tp };
  };
  const ab = pick(s.nOutside, cosI, s.nFilm, cosR);
  const ba = pick(s.nFilm, cosR, s.nOutside, cosI);
  const bc = pick(s.nFilm, cosR, s.nInside, cosT);
  // φ = 2πΔ/λ with Δ = 2 n_b d cos θ_ri (eqs 11, 12), per nm of wavelength: times 1/λ below.
  const phasePerInverseNm = cScale(cosR, 4 * Math.PI * s.nFilm * s.thicknessNm);
  return { rab: ab.r, m: cMul(cMul(ab.t, ba.t), bc.r), q: cMul(ba.r, bc.r), phasePerInverseNm };
}

/** E_0 … while the terms matter (or `count` of them), and their sum. */
function beamsByHand(s: FilmStack, kind: Kind, lambdaNm: number, flipTop = false, count = Infinity) {
  const c = coefficients(s, kind);
  const phase = cScale(c.phasePerInverseNm, 1 / lambdaNm);
  const beams: Complex[] = [flipTop ? cScale(c.rab, -1) : c.rab];
  let qPower: Complex = { re: 1, im: 0 };
  for (let n = 1; n < Math.min(count, 200_000); n++) {
    const e = cMul(cMul(c.m, qPower), cExpI(cScale(phase, n)));
    if (count === Infinity && cAbs2(e) < 1e-32 && n > 1) break;
    beams.push(e);
    qPower = cMul(qPower, c.q);
  }
  return { beams, sum: beams.reduce(cAdd) };
}

const R_BY_HAND = (s: FilmStack, pol: Polarization, lambdaNm: number, flipTop = false) =>
  CHANNELS[pol].reduce((acc, k) => acc + cAbs2(beamsByHand(s, k, lambdaNm, flipTop).sum), 0) / CHANNELS[pol].length;

const stack = (nOutside: number, nFilm: number, nInside: number, thicknessNm: number, angleDeg: number): FilmStack => ({
  nOutside,
  nFilm,
  nInside,
  thicknessNm,
  angleDeg,
});

/** Soap in air; total reflection at the back face (1.5 | 1.33 | 1 past 41.8°); an evanescent film (1.5 | 1 | 1.5 past 41.8°). */
const MEDIA = [
  [1, 1.33, 1],
  [1.5, 1.33, 1],
  [1.5, 1, 1.5],
  [1.5, 1.2, 1],
] as const;
const THICKNESSES = [1, 12, 250, 550, 3000, 20000];
const ANGLES = [0, 30, 50, 60, 80, 89];
const WAVELENGTHS = [380, 555, 830];
const POLARIZATIONS: Polarization[] = ['unpolarized', 'paper', 's', 'p'];

function* cases() {
  for (const [na, nb, nc] of MEDIA)
    for (const d of THICKNESSES) for (const a of ANGLES) for (const l of WAVELENGTHS) yield { s: stack(na, nb, nc, d, a), l };
}

describe("Figure 1's reflected beams", () => {
  it('are E_0 = r_ab and E_n = t_ab t_ba r_bc (r_ba r_bc)^{n−1} e^{inφ}, and stop once the tail is below the stated fraction', () => {
    for (const { s, l } of cases())
      for (const pol of POLARIZATIONS) {
        const got = filmBeams(s, pol, l);
        got.channels.forEach((c, i) => {
          const byHand = beamsByHand(s, CHANNELS[pol][i]!, l, false, c.beams.beams.length).beams;
          const drawn = c.beams.beams;
          drawn.forEach((e, n) => expect(Math.sqrt(cAbs2(cAdd(e, cScale(byHand[n]!, -1))))).toBeLessThan(ALGEBRAIC_TOL));
          const partial = drawn.reduce(cAdd);
          const left = Math.sqrt(cAbs2(cAdd(c.beams.total, cScale(partial, -1))));
          expect(left).toBeLessThanOrEqual(c.beams.tailBound + ALGEBRAIC_TOL);
          if (drawn.length - 1 < MAX_BEAMS) expect(c.beams.tailBound).toBeLessThanOrEqual(BEAM_TAIL_FRACTION);
        });
      }
  });

  it("sum to the reference's R (|E|² = R to 1e-9), with total reflection and in the paper's mode", () => {
    let worst = 0;
    for (const { s, l } of cases())
      for (const pol of POLARIZATIONS) {
        const reference = filmReflectance(l, s, pol);
        const diagram = filmBeams(s, pol, l).reflectance;
        const byHand = R_BY_HAND(s, pol, l);
        worst = Math.max(worst, Math.abs(diagram - reference), Math.abs(byHand - reference));
        expect(Math.abs(diagram - reference), `${JSON.stringify(s)} ${pol} ${l}`).toBeLessThan(BEAM_SUM_TOL);
        expect(Math.abs(byHand - reference), `${JSON.stringify(s)} ${pol} ${l}`).toBeLessThan(BEAM_SUM_TOL);
      }
    console.log(`beams against the reference: worst |R − R_ref| ${worst.toExponential(2)}`);
  });

  it('gives the golden value: n = 1.5 in air, d = 250 nm, λ = 555 nm, normal incidence → R = 0.1215919', () => {
    expect(Math.abs(filmBeams(stack(1, 1.5, 1, 250, 0), 's', 555).reflectance - 0.1215919)).toBeLessThan(GOLDEN_TOL);
  });

  it('with no phase flip at the top surface, equals the same sum with r_ab reversed; a very thin film turns bright', () => {
    for (const { s, l } of cases())
      for (const pol of POLARIZATIONS) {
        expect(Math.abs(filmBeams(s, pol, l, { flipTop: true }).reflectance - R_BY_HAND(s, pol, l, true))).toBeLessThan(BEAM_SUM_TOL);
      }
    // A 1 nm soap film: E_1 + E_2 + … ≈ −r_ab cancels E_0 (black); without the flip they add: R → (2 r_ab)².
    const thin = stack(1, 1.33, 1, 1, 0);
    const rab = (1 - 1.33) / (1 + 1.33);
    expect(filmBeams(thin, 's', 555).reflectance).toBeLessThan(1e-3);
    expect(Math.abs(filmBeams(thin, 's', 555, { flipTop: true }).reflectance - 4 * rab * rab)).toBeLessThan(THIN_FILM_LIMIT_TOL);
  });

  it('stay finite at the edges: grazing, a film of no thickness, an evanescent film of no thickness', () => {
    for (const s of [stack(1, 1.33, 1, 500, 90), stack(1, 1.33, 1, 0, 40), stack(1.5, 1, 1.5, 0, 60), stack(4, 1, 4, 0, 89)])
      for (const pol of POLARIZATIONS) {
        const b = filmBeams(s, pol, 400);
        expect(Number.isFinite(b.reflectance)).toBe(true);
        for (const c of b.channels) expect(c.beams.beams.every((e) => Number.isFinite(e.re) && Number.isFinite(e.im))).toBe(true);
        expect(Math.abs(b.reflectance - filmReflectance(400, s, pol))).toBeLessThan(BEAM_SUM_TOL);
      }
  });
});
