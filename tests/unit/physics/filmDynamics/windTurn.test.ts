/**
 * The turning wind (windDirection.ts) against the grid's symmetry: the cube-sphere maps onto itself
 * under a quarter turn about the vertical, which takes the wind at angle φ to the wind at φ + 90°.
 * So a uniform film (seed 0, itself unchanged by the turn) whose wind starts at 90° is the quarter
 * turn of the same film whose wind starts at 0°, step for step, to the seams' sampling error (the
 * tolerance of the still film's quarter-turn check, settledFilm.test.ts). A rate of 0 is the
 * steady wind along +x, bit for bit.
 */
import { describe, expect, it } from 'vitest';
import { type FilmSimulation, createFilmSimulation, stepFilm } from '../../../../src/physics/filmDynamics/filmSimulation.ts';
import { nearestCell } from '../../../../src/physics/filmDynamics/cubeSphereSampler.ts';
import { windAngleRad } from '../../../../src/physics/filmDynamics/windDirection.ts';
import { SEAM_SYMMETRY_TOL } from '../../../tolerances.ts';

const GRID_N = 10;
type Map3 = (x: number, y: number, z: number) => [number, number, number];

const run = (sim: FilmSimulation, steps: number): FilmSimulation => {
  for (let k = 0; k < steps; k++) stepFilm(sim);
  return sim;
};

/** The largest relative difference between `turned`'s η and `film`'s at the preimage of each of its cells. */
function worstMismatch(turned: FilmSimulation, film: FilmSimulation, preimage: Map3): number {
  const { center } = turned.grid;
  let worst = 0;
  for (let c = 0; c < turned.grid.cellCount; c++) {
    const [x, y, z] = preimage(center[3 * c]!, center[3 * c + 1]!, center[3 * c + 2]!);
    worst = Math.max(worst, Math.abs(film.state.eta[nearestCell(film.grid, x, y, z)]! / turned.state.eta[c]! - 1));
  }
  return worst;
}

describe('the turning wind', () => {
  it('is the steady wind along +x, bit for bit, at a rate of 0', () => {
    const given = { gridN: 8, seed: 3, windMps: 0.1, evaporationNmS: 20 };
    const [plain, still] = [run(createFilmSimulation(given), 30), run(createFilmSimulation({ ...given, windTurnDegS: 0 }), 30)];
    expect(still.state.eta).toEqual(plain.state.eta);
    expect(still.state.gamma).toEqual(plain.state.gamma);
    expect(still.state.edgeVelocity).toEqual(plain.state.edgeVelocity);
  });

  it('turns counter-clockwise seen from above at the rate, the angle reduced to a turn', () => {
    expect(windAngleRad({ windTurnDegS: 0 }, 1e6)).toBe(0);
    expect(windAngleRad({ windTurnDegS: 12 }, 7.5)).toBeCloseTo(Math.PI / 2, 14);
    expect(windAngleRad({ windTurnDegS: 360 }, 1e5 + 0.25)).toBeCloseTo(Math.PI / 2, 9);
  });

  it('started at 90° gives the quarter turn (x, y) → (−y, x) of the film started at 0°, step for step', () => {
    const given = { gridN: GRID_N, windMps: 0.1, windTurnDegS: 0 };
    const startSteps = 40;
    const probe = createFilmSimulation({ gridN: GRID_N, windMps: 0.1 });
    // The rate that turns the wind by exactly 90° in startSteps steps; the film started then is the one at 90°.
    const turn = 90 / (startSteps * probe.stepSeconds);
    const fromZero = createFilmSimulation({ ...given, windTurnDegS: turn });
    const fromQuarter = createFilmSimulation({ ...given, windTurnDegS: turn });
    fromQuarter.state.steps = startSteps;
    const quarterBack: Map3 = (x, y, z) => [y, -x, z];
    const quarterOn: Map3 = (x, y, z) => [-y, x, z];
    for (const steps of [10, 20, 30]) {
      run(fromZero, 10);
      run(fromQuarter, 10);
      expect(
        fromZero.state.eta.some((v) => Math.abs(v - 1) > 0.01),
        `${steps} steps: the wind has moved the film`,
      ).toBe(true);
      expect(worstMismatch(fromQuarter, fromZero, quarterBack), `${steps} steps`).toBeLessThan(SEAM_SYMMETRY_TOL);
      // The check can fail: the film is not its own quarter turn, and the turn the other way is not it.
      expect(worstMismatch(fromZero, fromZero, quarterBack)).toBeGreaterThan(1e3 * SEAM_SYMMETRY_TOL);
      expect(worstMismatch(fromQuarter, fromZero, quarterOn)).toBeGreaterThan(1e3 * SEAM_SYMMETRY_TOL);
    }
  });
});
