/**
 * Rupture and bursting. A pricked film opens a hole whose rim runs at the Taylor–Culick speed
 * √(2γ/(ρh)) × the rim-speed factor (γ = γ_a − R̄TΓ0 and h the film's thickness, computed here from
 * the published constants); behind the rim there is no film. The speed is read from the area the
 * film has lost, A = 2π(1 − cos r) for a cap of angular radius r, over many steps of the
 * elastic-wave step: at the flow's step the rim crosses the bubble in one or two steps.
 */
import { describe, expect, it } from 'vitest';
import { createFilmSimulation, filmSeconds, punctureFilm, stepFilm } from '../../../../src/physics/filmDynamics/filmSimulation.ts';
import { nearestCell } from '../../../../src/physics/filmDynamics/cubeSphereSampler.ts';
import { elasticWaveTimeStep } from '../../../../src/physics/filmDynamics/timeStep.ts';
import { RIM_SPEED_REL_TOL } from '../../../tolerances.ts';

const GRID_N = 24;

/** The angular radius of the cap with the area of the cells that have lost their film. */
function holeRadius(sim: ReturnType<typeof createFilmSimulation>): number {
  let lost = 0;
  sim.state.intact.forEach((v, c) => (lost += v === 0 ? sim.grid.area[c]! : 0));
  return Math.acos(Math.max(-1, 1 - lost / (2 * Math.PI)));
}

describe('a pricked film bursts', () => {
  const [radiusMm, thicknessNm, surfactantMolM2] = [40, 500, 6.67e-8];
  const surfaceTension = 0.07275 - 8.3144598 * 298.15 * surfactantMolM2;
  const taylorCulick = Math.sqrt((2 * surfaceTension) / (997 * thicknessNm * 1e-9));
  for (const rimSpeedFactor of [1, 0.25]) {
    it(`rim speed ${rimSpeedFactor} × √(2γ/(ρh)) = ${(rimSpeedFactor * taylorCulick).toFixed(2)} m/s, no film behind it`, () => {
      const sim = createFilmSimulation(
        { gridN: GRID_N, radiusMm, thicknessNm, surfactantMolM2, rimSpeedFactor },
        { timeStep: elasticWaveTimeStep },
      );
      punctureFilm(sim, 0, 0, 1);
      const samples: { seconds: number; radius: number }[] = [];
      while (holeRadius(sim) < 2.4) {
        stepFilm(sim);
        samples.push({ seconds: filmSeconds(sim), radius: holeRadius(sim) });
      }
      const first = samples.find((s) => s.radius > 0.4)!;
      const last = samples[samples.length - 1]!;
      const speed = ((last.radius - first.radius) * radiusMm * 1e-3) / (last.seconds - first.seconds);
      expect(Math.abs(speed / (rimSpeedFactor * taylorCulick) - 1)).toBeLessThan(RIM_SPEED_REL_TOL);
      sim.state.intact.forEach((v, c) => {
        if (v === 0) expect([sim.state.eta[c], sim.state.gamma[c]]).toEqual([0, 0]);
      });
      // The rim has not reached the bottom yet: the film there is whole.
      expect(sim.state.intact[nearestCell(sim.grid, 0, 0, -1)]).toBe(1);
    });
  }
  it('a film thinned to the rupture thickness opens by itself', () => {
    const sim = createFilmSimulation({ gridN: 6, thicknessNm: 40, ruptureThicknessNm: 39, evaporationNmS: 100 });
    for (let s = 0; s < 50 && sim.state.holes.length === 0; s++) stepFilm(sim);
    expect(sim.state.holes.length).toBeGreaterThan(0);
  });

  it('is pricked at a direction of any length, and refuses one that is 0 or not finite (or whose length is not), naming `puncture`', () => {
    const sim = createFilmSimulation({ gridN: 6 });
    punctureFilm(sim, 0, 0, 3);
    expect(sim.state.holes[0]!.center).toEqual([0, 0, 1]);
    const bad: [number, number, number][] = [
      [0, 0, 0],
      [Number.NaN, 0, 1],
      [0, Number.POSITIVE_INFINITY, 0],
      [1.5e308, 1.5e308, 1.5e308],
    ];
    for (const [x, y, z] of bad)
      expect(() => punctureFilm(sim, x, y, z), String([x, y, z])).toThrow(/^puncture: \[.*\] is not allowed; expected a direction/);
    expect(sim.state.holes).toHaveLength(1);
  });
});
