/**
 * Exact values at the edges of the domain, each from an analytic limit rather than from the code
 * under test, and bad input refused before anything is computed.
 */
import { describe, expect, it } from 'vitest';
import {
  FILM_STACK_DOMAIN,
  type FilmStack,
  POLARIZATIONS,
  filmReflectance,
  filmTransmittance,
} from '../../../src/physics/filmReflectance.ts';
import { ParameterError } from '../../../src/input/validate.ts';
import { ALGEBRAIC_TOL, ROUNDING_TOL } from '../../tolerances.ts';

/** Indices chosen to make every ordering: film above, below and between its media; TIR and frustrated TIR. */
const INDICES = [1, 1.33, 1.5, 2.5, 4] as const;
const LAMBDA_NM = 537;

function* stacks(thicknessNm: number, angleDeg: number): Generator<FilmStack> {
  for (const nOutside of INDICES)
    for (const nFilm of INDICES)
      for (const nInside of INDICES) {
        yield { nOutside, nFilm, nInside, thicknessNm, angleDeg };
      }
}

/**
 * A single interface n1 | n2 at θ1, from Hecht's forms with θ2 from Snell and cos θ2 = √(1 − sin²θ2)
 * (|r| = 1 past the critical angle): the s and p values.
 */
function singleInterface(n1: number, n2: number, angleDeg: number): Record<'s' | 'p', number> {
  const c1 = Math.cos((angleDeg * Math.PI) / 180);
  const s2 = (n1 / n2) * Math.sin((angleDeg * Math.PI) / 180);
  if (s2 >= 1) return { s: 1, p: 1 }; // total internal reflection
  const c2 = Math.sqrt(1 - s2 * s2);
  const rs = (n1 * c1 - n2 * c2) / (n1 * c1 + n2 * c2);
  const rp = (n2 * c1 - n1 * c2) / (n2 * c1 + n1 * c2);
  return { s: rs * rs, p: rp * rp };
}

describe('exact values at the edges of the domain', () => {
  it('θ = 90°: R = 1 and T = 0 wherever there is an interface; R = 0, T = 1 where there is none', () => {
    // cos θ_i = 0 makes eqs (5), (6) give r_ab = −1 and eqs (9), (10) t_ab = 0 for n_b ≠ n_a, so no
    // light enters the film and r = r_ab. With n_b = n_a the b|c interface is met at grazing
    // incidence instead (r = −1 again). Only n_a = n_c with no film (d = 0 or n_b = n_a) leaves
    // no interface at all — in the physical modes: the paper mode keeps eq (13) at d = 0, where
    // t_ab = 0 reflects everything (continuous with d > 0; docs/physics.md#thickness-zero).
    for (const thicknessNm of [0, 250, 20_000]) {
      for (const s of stacks(thicknessNm, 90)) {
        for (const pol of POLARIZATIONS) {
          const noFilm = thicknessNm === 0 && pol !== 'paper';
          const noInterface = s.nOutside === s.nInside && (noFilm || s.nFilm === s.nOutside);
          expect(filmReflectance(LAMBDA_NM, s, pol), `${JSON.stringify(s)} ${pol}`).toBe(noInterface ? 0 : 1);
          if (pol !== 'paper') expect(filmTransmittance(LAMBDA_NM, s, pol)).toBe(noInterface ? 1 : 0);
        }
      }
    }
  });

  // The paper mode at thickness 0 follows its own eq (13), pinned by the continuity test in filmReflectance.test.ts.
  it('thickness 0 is the bare outside|inside interface (Fresnel, TIR included) in the physical modes', () => {
    for (const angleDeg of [0, 30, 60, 85]) {
      for (const s of stacks(0, angleDeg)) {
        const bare = singleInterface(s.nOutside, s.nInside, angleDeg);
        for (const pol of ['s', 'p'] as const) {
          expect(Math.abs(filmReflectance(LAMBDA_NM, s, pol) - bare[pol]), `${JSON.stringify(s)} ${pol}`).toBeLessThan(ALGEBRAIC_TOL);
        }
        const unpolarized = (bare.s + bare.p) / 2;
        expect(Math.abs(filmReflectance(LAMBDA_NM, s) - unpolarized)).toBeLessThan(ALGEBRAIC_TOL);
      }
    }
  });

  it('total internal reflection behind an evanescent film (n_a sin θ above n_b and n_c): R = 1, T = 0 at every thickness', () => {
    // No wave propagates past the outside medium and none is absorbed, so all the light comes back;
    // in the physical modes only, as the paper's averaged amplitudes do not conserve energy.
    const evanescent = (s: FilmStack) => s.nOutside * Math.sin((s.angleDeg * Math.PI) / 180) > Math.max(s.nFilm, s.nInside);
    for (const thicknessNm of [0, 250, 20_000]) {
      for (const angleDeg of [30, 60, 85]) {
        for (const s of [...stacks(thicknessNm, angleDeg)].filter(evanescent)) {
          for (const pol of ['s', 'p', 'unpolarized'] as const) {
            expect(Math.abs(filmReflectance(LAMBDA_NM, s, pol) - 1), `${JSON.stringify(s)} ${pol}`).toBeLessThan(ROUNDING_TOL);
            expect(filmTransmittance(LAMBDA_NM, s, pol)).toBe(0);
          }
        }
      }
    }
    // Other indices, at 500 nm: n_a sin θ = 1.50 above n_b = 1.2 and n_c = 1.1, through 20 µm of evanescent film.
    const thick = { nOutside: 1.6, nFilm: 1.2, nInside: 1.1, thicknessNm: 20_000, angleDeg: 70 };
    expect(Math.abs(filmReflectance(500, thick) - 1)).toBeLessThan(ROUNDING_TOL);
  });

  it('equal indices reflect nothing (R = 0, T = 1) at every thickness, angle and polarisation', () => {
    for (const n of INDICES) {
      for (const thicknessNm of [0, 1, 777, 20_000]) {
        for (const angleDeg of [0, 45, 89.99, 90]) {
          const s = { nOutside: n, nFilm: n, nInside: n, thicknessNm, angleDeg };
          for (const pol of POLARIZATIONS) {
            expect(filmReflectance(LAMBDA_NM, s, pol)).toBe(0);
            if (pol !== 'paper') expect(Math.abs(filmTransmittance(LAMBDA_NM, s, pol) - 1)).toBeLessThan(ALGEBRAIC_TOL);
          }
        }
      }
    }
  });
});

describe('bad input to the reference', () => {
  const base: FilmStack = { nOutside: 1, nFilm: 1.33, nInside: 1, thicknessNm: 500, angleDeg: 0 };
  const bad = [Number.NaN, Number.POSITIVE_INFINITY, Number.NEGATIVE_INFINITY];
  const outside = (field: keyof FilmStack) => [FILM_STACK_DOMAIN[field].min - 1e-9, FILM_STACK_DOMAIN[field].max + 1e-9];
  const rows = (Object.keys(FILM_STACK_DOMAIN) as (keyof FilmStack)[]).flatMap((field) =>
    [...bad, ...outside(field)].map((value) => [field, value] as const),
  );
  it.each(rows)('%s = %s throws a ParameterError naming the field and its range', (field, value) => {
    const { min, max } = FILM_STACK_DOMAIN[field];
    const call = () => filmReflectance(LAMBDA_NM, { ...base, [field]: value });
    expect(call).toThrow(ParameterError);
    expect(call).toThrow(new RegExp(`^${field}: .* expected a number in \\[${min}, ${max}\\]`));
  });
});
