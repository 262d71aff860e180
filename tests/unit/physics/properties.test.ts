import { describe, expect, it } from 'vitest';
import {
  type FilmStack,
  type Polarization,
  filmOptics,
  reflectanceAt,
  transmittanceAt,
  POLARIZATIONS,
} from '../../../src/physics/filmReflectance.ts';
import { mulberry32 } from '../../seededRandom.ts';
import { ENERGY_TOL } from '../../tolerances.ts';

const CASES = 100_000;

/** One stack of each kind [n_a, n_b, n_c, θ], 150 nm thick at λ = 450 nm, in every mode before the random ones. */
const NAMED_STACKS = [
  [1, 1.33, 1, 40], // no total reflection
  [1.6, 1.2, 1.5, 60], // frustrated TIR: evanescent in the film, propagating behind it
  [1.6, 1.4, 1.1, 70], // TIR in the film and behind it
  [2, 3, 1, 89], // TIR behind a propagating film
] as const;

interface Case {
  readonly stack: FilmStack;
  readonly pol: Polarization;
  readonly lambda: number;
}

function* cases(): Generator<Case> {
  for (const [nOutside, nFilm, nInside, angleDeg] of NAMED_STACKS)
    for (const pol of POLARIZATIONS) yield { stack: { nOutside, nFilm, nInside, thicknessNm: 150, angleDeg }, pol, lambda: 450 };
  const rand = mulberry32(20261122);
  const pick = <T>(xs: readonly T[]) => xs[Math.floor(rand() * xs.length)] as T;
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
    yield { stack, pol: pick(POLARIZATIONS), lambda: 380 + 450 * rand() };
  }
}

describe(`properties over ${NAMED_STACKS.length} named stacks and ${CASES} random inputs in the whole domain`, () => {
  it('R and T are finite, 0 ≤ R ≤ 1, and R + T = 1 (physical modes), TIR and frustrated TIR included in every mode', () => {
    let worstEnergy = 0;
    const count = () => Object.fromEntries(POLARIZATIONS.map((pol) => [pol, 0])) as Record<Polarization, number>;
    const tirCases = count();
    const frustratedCases = count();
    for (const { stack, pol, lambda } of cases()) {
      const nSin = stack.nOutside * Math.sin((stack.angleDeg * Math.PI) / 180);
      if (nSin > Math.min(stack.nFilm, stack.nInside)) tirCases[pol]++;
      // Frustrated TIR: evanescent in the film, propagating again behind it.
      if (nSin > stack.nFilm && nSin < stack.nInside && stack.thicknessNm > 0) frustratedCases[pol]++;
      const optics = filmOptics(stack, pol);
      const r = reflectanceAt(optics, lambda);
      const t = transmittanceAt(optics, lambda);
      if (!(Number.isFinite(r) && r >= 0 && r <= 1 && Number.isFinite(t))) {
        throw new Error(`R = ${r}, T = ${t} for ${JSON.stringify({ ...stack, pol, lambda })}`);
      }
      if (pol !== 'paper') worstEnergy = Math.max(worstEnergy, Math.abs(r + t - 1));
    }
    expect(worstEnergy).toBeLessThan(ENERGY_TOL);
    // Each mode draws a quarter of the cases: over 2.5% of them with TIR and 1.25% frustrated in each, so over 10% and 5% in all.
    for (const pol of POLARIZATIONS) {
      expect(tirCases[pol], pol).toBeGreaterThan(CASES / 40);
      expect(frustratedCases[pol], pol).toBeGreaterThan(CASES / 80);
    }
  });
});
