/**
 * The step size worked by hand from the published constants (flowConstants.ts's sources: ρ = 997
 * kg/m³, ρ_a = 1.184 kg/m³, ν_a = 1.562e-5 m²/s, G = 9.8 m/s², R̄T = 8.3144598 × 298.15 J/mol),
 * the grid's spacings taken as given: Δt = min(mean spacing/max(gη/Cr, 1.5 × wind), 10 × closest
 * spacing/√M) in R/U, and the transport's sub-steps.
 */
import { describe, expect, it } from 'vitest';
import { createFilmSimulation } from '../../../../src/physics/filmDynamics/filmSimulation.ts';
import { elasticWaveTimeStep } from '../../../../src/physics/filmDynamics/timeStep.ts';
import { FLOAT_TOLERANCE } from '../../../tolerances.ts';

/** Cr, M and g of eq. (17) in U = 1 m/s, for R in mm, h̄ in nm and Γ0 in mol/m². */
function numbersByHand(radiusMm: number, thicknessNm: number, surfactantMolM2: number) {
  const [r, eta0] = [radiusMm * 1e-3, thicknessNm * 0.5e-9];
  return {
    airFriction: (1.184 * Math.sqrt(1.562e-5 * r)) / (997 * eta0),
    marangoni: (surfactantMolM2 * 8.3144598 * 298.15) / (997 * eta0),
    gravity: 9.8 * r,
    secondsPerUnit: r,
  };
}

describe('the step', () => {
  it('at the defaults (R 40 mm, h̄ 550 nm, Γ0 6.67e-8, still air) is the mean spacing over the drainage speed gη/Cr ≈ 0.115 m/s', () => {
    const { airFriction, gravity, marangoni, secondsPerUnit } = numbersByHand(40, 550, 6.67e-8);
    expect(gravity / airFriction).toBeCloseTo(0.1148, 4);
    for (const gridN of [32, 64, 128]) {
      const sim = createFilmSimulation({ gridN });
      const advection = sim.grid.meanSpacing / (gravity / airFriction);
      const waves = (10 * sim.grid.minSpacing) / Math.sqrt(marangoni);
      expect(advection).toBeLessThan(waves);
      expect(Math.abs(sim.dt / advection - 1)).toBeLessThan(FLOAT_TOLERANCE);
      expect(Math.abs(sim.stepSeconds / (advection * secondsPerUnit) - 1)).toBeLessThan(FLOAT_TOLERANCE);
    }
    // At most 300 steps per film second at the default grid.
    expect(1 / createFilmSimulation({ gridN: 128 }).stepSeconds).toBeLessThan(300);
  });

  it('a wind of 0.5 m/s sizes it by the air at the surface, 1.5 × 0.5 m/s', () => {
    const sim = createFilmSimulation({ gridN: 32, windMps: 0.5 });
    expect(Math.abs(sim.dt / (sim.grid.meanSpacing / 0.75) - 1)).toBeLessThan(FLOAT_TOLERANCE);
  });

  it('a thin surfactant-rich film (Γ0 1e-6, h̄ 20 nm) is held to a wave Courant number of 10', () => {
    const { marangoni } = numbersByHand(40, 20, 1e-6);
    const sim = createFilmSimulation({ gridN: 32, surfactantMolM2: 1e-6, thicknessNm: 20 });
    expect(Math.abs(sim.dt / ((10 * sim.grid.minSpacing) / Math.sqrt(marangoni)) - 1)).toBeLessThan(FLOAT_TOLERANCE);
  });

  it('the transport takes the fewest sub-steps that keep its Courant number at the reference speed to 0.7 on the closest spacing', () => {
    for (const given of [{ gridN: 32 }, { gridN: 16, windMps: 0.1 }, { gridN: 32, surfactantMolM2: 1e-6, thicknessNm: 20 }]) {
      const sim = createFilmSimulation(given);
      const { airFriction, gravity } = numbersByHand(40, sim.parameters.thicknessNm, sim.parameters.surfactantMolM2);
      const courant = (s: number) => ((sim.dt / s) * Math.max(gravity / airFriction, 1.5 * sim.parameters.windMps)) / sim.grid.minSpacing;
      expect(courant(sim.transportSubsteps)).toBeLessThanOrEqual(0.7);
      if (sim.transportSubsteps > 1) expect(courant(sim.transportSubsteps - 1)).toBeGreaterThan(0.7);
    }
    expect(createFilmSimulation({ gridN: 32 }).transportSubsteps).toBe(2);
  });

  it('the elastic-wave step for comparison runs: 0.17 ms at the defaults and N = 128, about 5700 a film second', () => {
    const sim = createFilmSimulation({ gridN: 128 }, { timeStep: elasticWaveTimeStep });
    expect(Math.abs(sim.dt / (0.5 * sim.grid.minSpacing) - 1)).toBeLessThan(FLOAT_TOLERANCE);
    expect(sim.stepSeconds * 1e3).toBeCloseTo(0.175, 3);
  });
});
