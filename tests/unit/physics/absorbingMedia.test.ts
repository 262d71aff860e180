/**
 * Films and insides with complex indices ñ = n + ik (docs/physics.md#absorbing-media). Expected
 * values come from outside the code under test: a characteristic-matrix (transfer-matrix)
 * computation written here, the normal-incidence Fresnel formula, the real-index path itself
 * (k → 0), the perfect-conductor limit (k → ∞) and energy conservation with the absorption of the
 * matrix method.
 */
import { describe, expect, it } from 'vitest';
import { type Complex, type RefractiveIndex } from '../../../src/physics/complex.ts';
import {
  type FilmStack,
  COMPLEX_INDEX_DOMAIN,
  filmOptics,
  filmReflectance,
  filmTransmittance,
  reflectanceAt,
  transmittanceAt,
} from '../../../src/physics/filmReflectance.ts';
import { filmXyz, whiteXyz } from '../../../src/physics/spectralIntegration.ts';
import { ParameterError } from '../../../src/input/validate.ts';
import { ALGEBRAIC_TOL, ENERGY_TOL, GOLD_GOLDEN_TOL, TMM_TOL } from '../../tolerances.ts';

// Complex arithmetic of the test's own, so the reference shares no code with src/physics.
const c = (re: number, im = 0): Complex => ({ re, im });
const add = (a: Complex, b: Complex) => c(a.re + b.re, a.im + b.im);
const sub = (a: Complex, b: Complex) => c(a.re - b.re, a.im - b.im);
const mul = (a: Complex, b: Complex) => c(a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re);
const div = (a: Complex, b: Complex) => {
  const d = b.re * b.re + b.im * b.im;
  return c((a.re * b.re + a.im * b.im) / d, (a.im * b.re - a.re * b.im) / d);
};
const abs2 = (a: Complex) => a.re * a.re + a.im * a.im;
const conj = (a: Complex) => c(a.re, -a.im);
const sqrt = (a: Complex) => {
  const r = Math.hypot(a.re, a.im);
  const re = Math.sqrt((r + a.re) / 2);
  const im = Math.sqrt((r - a.re) / 2);
  return c(re, a.im < 0 ? -im : im);
};
const cos = (z: Complex) => c(Math.cos(z.re) * Math.cosh(z.im), -Math.sin(z.re) * Math.sinh(z.im));
const sin = (z: Complex) => c(Math.sin(z.re) * Math.cosh(z.im), Math.cos(z.re) * Math.sinh(z.im));
const I = c(0, 1);
const index = (n: number | Complex): Complex => (typeof n === 'number' ? c(n) : n);

/**
 * ñ cos θ in a medium for light from n_a at θ_i: √(ñ² − (n_a sin θ_i)²) on the branch where the
 * wave decays or propagates forward (Im ≥ 0, and Re ≥ 0 on the real axis).
 */
function nCos(n: Complex, nOutside: number, angleDeg: number): Complex {
  const s = nOutside * Math.sin((angleDeg * Math.PI) / 180);
  const root = sqrt(sub(mul(n, n), c(s * s)));
  return root.im < 0 || (root.im === 0 && root.re < 0) ? c(-root.re, -root.im) : root;
}

/**
 * One film between two half-spaces by the characteristic matrix (e^{−iωt}, ñ = n + ik):
 * M = [[cos δ, −i sin δ / η_b], [−i η_b sin δ, cos δ]], δ = (2π/λ) d ñ_b cos θ_b, tilted admittances
 * η = ñ cos θ (s) and ñ / cos θ = ñ² / (ñ cos θ) (p); [B, C] = M [1, η_c];
 * r = (η_a B − C)/(η_a B + C), T = 4 η_a Re η_c / |η_a B + C|², A = 4 η_a Re(B C* − η_c) / |η_a B + C|².
 */
function tmm(lambdaNm: number, s: FilmStack<RefractiveIndex>, pol: 's' | 'p') {
  const [na, nb, nc] = [c(s.nOutside), index(s.nFilm), index(s.nInside)];
  const eta = (n: Complex) => {
    const nc0 = nCos(n, s.nOutside, s.angleDeg);
    return pol === 's' ? nc0 : div(mul(n, n), nc0);
  };
  const [ea, eb, ec] = [eta(na), eta(nb), eta(nc)];
  const delta = mul(c((2 * Math.PI * s.thicknessNm) / lambdaNm), nCos(nb, s.nOutside, s.angleDeg));
  const [cd, sd] = [cos(delta), sin(delta)];
  const B = add(cd, mul(mul(I, c(-1)), div(mul(sd, ec), eb)));
  const C = add(mul(mul(I, c(-1)), mul(eb, sd)), mul(cd, ec));
  const den = add(mul(ea, B), C);
  const r = div(sub(mul(ea, B), C), den);
  const scale = (4 * ea.re) / abs2(den);
  return { R: abs2(r), T: scale * ec.re, A: scale * (mul(B, conj(C)).re - ec.re) };
}

const GOLD: Complex = c(0.43, 2.455); // Johnson & Christy 1972 at 2.26 eV (548.6 nm)
const stack = (over: Partial<FilmStack<RefractiveIndex>>): FilmStack<RefractiveIndex> => ({
  nOutside: 1,
  nFilm: 1.33,
  nInside: 1,
  thicknessNm: 100,
  angleDeg: 0,
  ...over,
});

describe('absorbing media: eqs (13)–(14) with complex indices against the characteristic matrix', () => {
  const OUTSIDE = [1, 1.5];
  const FILMS: (number | Complex)[] = [1.33, 2.5, c(2.2, 0.3), c(2.34, 0.1), GOLD, c(0.05, 3.586), c(1.2, 0)];
  const INSIDES: (number | Complex)[] = [1, 1.52, GOLD, c(0.05, 3.586), c(2.95, 2.93), c(1.2, 5)];
  const THICKNESS_NM = [0, 5, 40, 200, 700];
  const ANGLES_DEG = [0, 30, 60, 80, 89.9];
  const LAMBDAS_NM = [400, 550, 700];

  it('R_s and R_p agree on the whole grid (TIR, grazing, metal films and insides)', () => {
    let worst = 0;
    for (const nOutside of OUTSIDE)
      for (const nFilm of FILMS)
        for (const nInside of INSIDES)
          for (const thicknessNm of THICKNESS_NM)
            for (const angleDeg of ANGLES_DEG) {
              const s = { nOutside, nFilm, nInside, thicknessNm, angleDeg };
              for (const pol of ['s', 'p'] as const) {
                const optics = filmOptics(s, pol);
                for (const l of LAMBDAS_NM) worst = Math.max(worst, Math.abs(reflectanceAt(optics, l) - tmm(l, s, pol).R));
              }
            }
    expect(worst).toBeLessThan(TMM_TOL);
  });

  it('an absorbing film between transparent media conserves energy: R + T + A = 1 (T with the flux factor, A from the matrix)', () => {
    let worst = 0;
    for (const nOutside of OUTSIDE)
      for (const nFilm of [c(2.2, 0.3), GOLD, c(0.05, 3.586)])
        for (const nInside of [1, 1.52])
          for (const thicknessNm of [5, 40, 200])
            for (const angleDeg of ANGLES_DEG)
              for (const pol of ['s', 'p'] as const) {
                const s = { nOutside, nFilm, nInside, thicknessNm, angleDeg };
                const optics = filmOptics(s, pol);
                for (const l of LAMBDAS_NM) {
                  const ref = tmm(l, s, pol);
                  const [R, T] = [reflectanceAt(optics, l), transmittanceAt(optics, l)];
                  expect(ref.A).toBeGreaterThan(0);
                  worst = Math.max(worst, Math.abs(R + T + ref.A - 1), Math.abs(T - ref.T));
                }
              }
    expect(worst).toBeLessThan(ENERGY_TOL);
  });

  it('an absorbing inside is opaque: T = 0; what the matrix sends into it is absorbed there (R + A_film + T_into = 1)', () => {
    const s = stack({ nFilm: c(2.2, 0.3), nInside: GOLD, thicknessNm: 80, angleDeg: 40 });
    for (const pol of ['s', 'p'] as const) {
      expect(filmTransmittance(550, s, pol)).toBe(0);
      const ref = tmm(550, s, pol);
      expect(ref.T).toBeGreaterThan(0);
      expect(Math.abs(filmReflectance(550, s, pol) + ref.A + ref.T - 1)).toBeLessThan(ENERGY_TOL);
    }
  });
});

describe('absorbing media: limits', () => {
  it('d = 0 on gold at 548.6 nm, normal incidence: R = |(ñ − 1)/(ñ + 1)|² = 0.786916', () => {
    const R = filmReflectance(548.6, stack({ nInside: GOLD, thicknessNm: 0 }));
    const [n, k] = [GOLD.re, GOLD.im];
    expect(Math.abs(R - ((n - 1) ** 2 + k * k) / ((n + 1) ** 2 + k * k))).toBeLessThan(ALGEBRAIC_TOL);
    expect(Math.abs(R - 0.786916)).toBeLessThan(GOLD_GOLDEN_TOL);
  });

  it('k = 0 is the real path bit for bit, and k → 0 tends to it', () => {
    for (const angleDeg of [0, 45, 70, 89])
      for (const thicknessNm of [0, 120, 900]) {
        const real = stack({ nOutside: 1.4, nFilm: 1.9, nInside: 1.2, thicknessNm, angleDeg });
        const zeroK = { ...real, nFilm: c(1.9, 0), nInside: c(1.2, 0) };
        for (const pol of ['unpolarized', 's', 'p', 'paper'] as const)
          for (const l of [380, 555, 830]) {
            expect(filmReflectance(l, zeroK, pol)).toBe(filmReflectance(l, real, pol));
            expect(filmTransmittance(l, zeroK, pol)).toBe(filmTransmittance(l, real, pol));
            // dR/dk is at most ~4π d/λ · O(1): a k of 1e-12 moves R by ~1e-9 at most.
            const small = filmReflectance(l, { ...real, nFilm: c(1.9, 1e-12) }, pol);
            expect(Math.abs(small - filmReflectance(l, real, pol))).toBeLessThan(1e-8);
          }
      }
  });

  it('k → ∞ makes the inside a perfect mirror: R → 1 for s and p at any angle', () => {
    for (const angleDeg of [0, 60, 85]) {
      const gaps = [1, 10, 100].map((k) => 1 - filmReflectance(550, stack({ nInside: c(1, k), thicknessNm: 0, angleDeg })));
      expect(gaps[1]!).toBeLessThan(gaps[0]!);
      expect(gaps[2]!).toBeLessThan(gaps[1]!);
      // At normal incidence 1 − R = 4n/((n + 1)² + k²); obliquely the p wave's gap grows as 1/cos θ.
      expect(gaps[2]!).toBeLessThan(4e-4 / Math.cos((angleDeg * Math.PI) / 180));
      expect(gaps[2]!).toBeGreaterThan(0);
    }
  });

  it('no NaN at the corners of the domain', () => {
    const { n, k } = COMPLEX_INDEX_DOMAIN;
    for (const nn of [n.min, 1, n.max])
      for (const kk of [k.min, 1, k.max])
        for (const thicknessNm of [0, 1, 20000])
          for (const angleDeg of [0, 60, 89.99, 90])
            for (const where of ['nFilm', 'nInside'] as const)
              for (const l of [380, 830]) {
                const s = stack({ [where]: c(nn, kk), nOutside: 4, thicknessNm, angleDeg });
                const [R, T] = [filmReflectance(l, s), filmTransmittance(l, s)];
                expect(R, JSON.stringify(s)).toBeGreaterThanOrEqual(0);
                expect(R, JSON.stringify(s)).toBeLessThanOrEqual(1);
                expect(Number.isFinite(T) && T >= 0 && T <= 1 + ENERGY_TOL, JSON.stringify(s)).toBe(true);
              }
  });

  it('a constant-R metal gives XYZ = R × the white (the colour integral takes complex media)', () => {
    const R = filmReflectance(550, stack({ nInside: GOLD, thicknessNm: 0 }));
    const xyz = filmXyz({ nOutside: 1, nFilm: 1.33, nInside: { complex: [GOLD.re, GOLD.im] }, thicknessNm: 0, angleDeg: 0 });
    whiteXyz('D65').forEach((w, i) => expect(Math.abs(xyz[i]! - R * w)).toBeLessThan(ALGEBRAIC_TOL));
  });

  it('refuses k < 0, n too small, a complex outside, each naming the parameter', () => {
    const bad: [Partial<FilmStack<RefractiveIndex>>, string, RegExp][] = [
      [{ nInside: c(0.43, -1) }, 'nInside', /k is -1, below 0/],
      [{ nFilm: c(0, 1) }, 'nFilm', /n is 0, below 0\.01/],
      [{ nFilm: c(Number.NaN, 1) }, 'nFilm', /n is not a finite number/],
      [{ nInside: c(1, 101) }, 'nInside', /k is 101, above 100/],
    ];
    for (const [over, parameter, message] of bad) {
      let error: unknown = null;
      try {
        filmReflectance(550, stack(over));
      } catch (e) {
        error = e;
      }
      expect(error).toBeInstanceOf(ParameterError);
      expect((error as ParameterError).parameter).toBe(parameter);
      expect((error as ParameterError).message).toMatch(message);
    }
  });
});
