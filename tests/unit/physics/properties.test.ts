import { describe, expect, it } from 'vitest';
import { filmOptics, reflectanceAt, transmittanceAt, POLARIZATIONS } from '../../../src/physics/filmReflectance.ts';
import { mulberry32 } from '../../seededRandom.ts';
import { ENERGY_TOL } from '../../tolerances.ts';

const CASES = 100_000;

describe(`properties over ${CASES} random inputs in the whole domain`, () => {
  it('R and T are finite, 0 ≤ R ≤ 1, and R + T = 1 (physical modes), TIR and frustrated TIR included', () => {
    const rand = mulberry32(20261122);
    const pick = <T>(xs: readonly T[]) => xs[Math.floor(rand() * xs.length)] as T;
    let worstEnergy = 0;
    let tirCases = 0;
    let frustratedCases = 0;
    for (let i = 0; i < CASES; i++) {
      // Edges are drawn on purpose: thickness 0, θ 0° and 90°, equal indices.
      const edge = rand() < 0.1;
      const n = () => (edge && rand() < 0.5 ? 1.33 : 1 + 3 * rand());
      const stack = {
        nOutside: n(),
        nFilm: n(),
        nInside: n(),
        thicknessNm: edge && rand() < 0.3 ? 0 : 20000 * rand(),
        angleDeg: edge && rand() < 0.5 ? pick([0, 90]) : 90 * rand(),
      };
      const nSin = stack.nOutside * Math.sin((stack.angleDeg * Math.PI) / 180);
      if (nSin > Math.min(stack.nFilm, stack.nInside)) tirCases++;
      // Frustrated TIR: evanescent in the film, propagating again behind it.
      if (nSin > stack.nFilm && nSin < stack.nInside && stack.thicknessNm > 0) frustratedCases++;
      const pol = pick(POLARIZATIONS);
      const lambda = 380 + 450 * rand();
      const optics = filmOptics(stack, pol);
      const r = reflectanceAt(optics, lambda);
      const t = transmittanceAt(optics, lambda);
      if (!(Number.isFinite(r) && r >= 0 && r <= 1 && Number.isFinite(t))) {
        throw new Error(`case ${i}: R = ${r}, T = ${t} for ${JSON.stringify({ ...stack, pol, lambda })}`);
      }
      if (pol !== 'paper') worstEnergy = Math.max(worstEnergy, Math.abs(r + t - 1));
    }
    expect(worstEnergy).toBeLessThan(ENERGY_TOL);
    expect(tirCases).toBeGreaterThan(CASES / 10);
    expect(frustratedCases).toBeGreaterThan(CASES / 20);
  });
});
