/**
 * The stationary film, the simulation's independent check: in still air without evaporation a
 * film starting uniform (Γ/η = 1) drains until Marangoni stress holds gravity, at
 * h(θ) = h̄ (a/sinh a) e^(−a cos θ), a = ρGRη0/(Γ0R̄T) (docs/flow.md#the-stationary-film). Also
 * its symmetry: nothing breaks the symmetry about the vertical axis, so the cube's own symmetries
 * map the film onto itself to rounding, and it is axisymmetric to the grid's truncation error.
 */
import { beforeAll, describe, expect, it } from 'vitest';
import { type FilmSimulation, advanceFilm, createFilmSimulation } from '../../../../src/physics/filmDynamics/filmSimulation.ts';
import { PROFILE_THETA_DEG, thicknessProfileNm, thicknessSampler } from '../../../../src/physics/filmDynamics/filmMeasures.ts';
import { nearestCell } from '../../../../src/physics/filmDynamics/cubeSphereSampler.ts';
import { elasticWaveTimeStep } from '../../../../src/physics/filmDynamics/timeStep.ts';
import {
  AXISYMMETRY_REL_TOL,
  MIRROR_SYMMETRY_TOL,
  SEAM_SYMMETRY_TOL,
  SETTLED_PROFILE_REL_TOL,
  SETTLED_SLOPE_REL_TOL,
} from '../../../tolerances.ts';
import { logThicknessSlope, stationaryExponent } from './flowTestHelpers.ts';

/** 10 cells per face side; 6 s of film time is past the measured settling (the slower case's speed falls ×0.11 per second, to 2e-7 m/s at 6 s). */
const GRID_N = 10;
const SETTLE_SECONDS = 6;
/** Speed (in U = 1 m/s) below which the film counts as at rest: drainage starts at ~0.1 m/s. */
const SETTLED_SPEED = 1e-5;

const settled = (given: Record<string, number>): FilmSimulation => {
  const sim = createFilmSimulation({ gridN: GRID_N, ...given });
  advanceFilm(sim, SETTLE_SECONDS);
  return sim;
};

describe('the settled film', () => {
  const cases = [
    { radiusMm: 40, thicknessNm: 800, surfactantMolM2: 6.67e-8 },
    { radiusMm: 80, thicknessNm: 1000, surfactantMolM2: 1e-7 },
  ];
  for (const c of cases) {
    const a = stationaryExponent(c.radiusMm, c.thicknessNm, c.surfactantMolM2);
    it(`R ${c.radiusMm} mm, h̄ ${c.thicknessNm} nm, Γ0 ${c.surfactantMolM2}: ln h against cos θ has slope −a = −${a.toFixed(3)}`, () => {
      const sim = settled(c);
      expect(sim.state.holes).toHaveLength(0);
      // Settled: the film has come to rest.
      expect(Math.max(...sim.state.edgeVelocity.map(Math.abs))).toBeLessThan(SETTLED_SPEED);
      expect(Math.abs(logThicknessSlope(sim) / -a - 1)).toBeLessThan(SETTLED_SLOPE_REL_TOL);
      const profile = thicknessProfileNm(sim);
      PROFILE_THETA_DEG.forEach((thetaDeg, k) => {
        const analytic = ((c.thicknessNm * a) / Math.sinh(a)) * Math.exp(-a * Math.cos((thetaDeg * Math.PI) / 180));
        expect(Math.abs(profile[k]! / analytic - 1)).toBeLessThan(SETTLED_PROFILE_REL_TOL);
      });
    });
  }
});

describe('still air, seed 0: the film stays axisymmetric', () => {
  const sim = createFilmSimulation({ gridN: GRID_N });
  // The elastic-wave step: its departure points stay close to the edges', so no seam is crossed and mirrors hold to rounding.
  const smallSteps = createFilmSimulation({ gridN: GRID_N }, { timeStep: elasticWaveTimeStep });
  beforeAll(() => {
    advanceFilm(sim, 1);
    advanceFilm(smallSteps, 1);
  });
  const { center } = sim.grid;
  const eta = sim.state.eta;
  /** Each cell's value against the value at its image under a map of the cube onto itself that keeps the vertical axis. */
  const worstMismatch = (image: (x: number, y: number, z: number) => [number, number, number], film = eta): number => {
    let worst = 0;
    for (let c = 0; c < sim.grid.cellCount; c++) {
      const [x, y, z] = image(center[3 * c]!, center[3 * c + 1]!, center[3 * c + 2]!);
      worst = Math.max(worst, Math.abs(film[nearestCell(sim.grid, x, y, z)]! / film[c]! - 1));
    }
    return worst;
  };
  const mirrors: ((x: number, y: number, z: number) => [number, number, number])[] = [
    (x, y, z) => [-x, y, z],
    (x, y, z) => [x, -y, z],
    (x, y, z) => [-x, -y, z],
  ];
  it('is unchanged, to rounding, by the mirrors x → −x and y → −y and the half turn at the elastic-wave step', () => {
    expect(smallSteps.state.eta.some((v) => Math.abs(v - 1) > 0.1)).toBe(true);
    for (const mirror of mirrors) expect(worstMismatch(mirror, smallSteps.state.eta)).toBeLessThan(MIRROR_SYMMETRY_TOL);
  });
  it("is unchanged by them at the flow's step to the seams' sampling error (its departure points cross seams)", () => {
    expect(eta.some((v) => Math.abs(v - 1) > 0.1)).toBe(true);
    for (const mirror of mirrors) expect(worstMismatch(mirror)).toBeLessThan(SEAM_SYMMETRY_TOL);
  });
  it('is unchanged by a quarter turn and the mirror x ↔ y to the seams’ sampling error', () => {
    expect(worstMismatch((x, y, z) => [-y, x, z])).toBeLessThan(SEAM_SYMMETRY_TOL);
    expect(worstMismatch((x, y, z) => [y, x, z])).toBeLessThan(SEAM_SYMMETRY_TOL);
  });
  it('varies along each circle of latitude by less than the grid tolerance', () => {
    const h = thicknessSampler(sim);
    for (const thetaDeg of PROFILE_THETA_DEG) {
      const theta = (thetaDeg * Math.PI) / 180;
      const ring = Array.from({ length: 90 }, (_, k) => {
        const phi = (2 * Math.PI * k) / 90;
        return h(Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta));
      });
      const mean = ring.reduce((s, v) => s + v, 0) / ring.length;
      expect((Math.max(...ring) - Math.min(...ring)) / mean).toBeLessThan(AXISYMMETRY_REL_TOL);
    }
  });
});
