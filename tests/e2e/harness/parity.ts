/** The parity page: film XYZ (FilmXyzProbe) and film thickness of the given cases through the real shaders. */
import { type DataTexture, WebGLRenderer } from 'three';
import { DEFAULT_FILM_QUALITY, type FilmQuality } from '../../../src/settings/filmQuality.ts';
import type { ParityGroup, ParityMode } from '../../../scripts/harness/parityCase.ts';
import { FilmXyzProbe } from '../../../scripts/harness/filmXyzProbe.ts';
import { renderThickness } from './thicknessFieldProbe.ts';
import { GpuFilmSimulation } from '../../../src/gpuFilmDynamics/gpuFilmSimulation.ts';
import { readFilmState, readTexels } from './filmReadback.ts';
import { surfactantResidual } from './surfactantResidual.ts';

const canvas = document.querySelector<HTMLCanvasElement>('#gl');
if (!canvas) throw new Error('parity.html must hold #gl');
const renderer = new WebGLRenderer({ canvas });
const probe = new FilmXyzProbe(renderer);

window.renderFilmXyz = (groups, mode, quality = DEFAULT_FILM_QUALITY) => probe.render(groups, mode, quality);
window.renderThickness = (points, s) => renderThickness(renderer, points, s);
window.runFlow = (parameters, steps, blow, puncture, renew = false) => {
  const sim = new GpuFilmSimulation(renderer, parameters, { renew });
  if (blow) sim.blow(blow.center, blow.velocityMps);
  if (puncture) sim.puncture(...puncture);
  sim.step(steps);
  const { eta, gamma, intact, edgeVelocity, holes } = readFilmState(renderer, sim);
  const result = {
    eta: [...eta],
    gamma: [...gamma],
    intact: [...intact],
    edgeVelocity: [...edgeVelocity],
    holes,
    surfactantResidual: surfactantResidual(renderer, sim),
    steps: sim.steps,
  };
  sim.dispose();
  return result;
};
window.startPaddedFilms = (parameters) => {
  const sim = new GpuFilmSimulation(renderer, parameters);
  const cpu = [...((sim.startPaddedFilm as DataTexture).image.data as Float32Array)];
  void sim.paddedFilm;
  const gpu = [...readTexels(renderer, sim.stateTargets.paddedFilm)];
  sim.dispose();
  return { cpu, gpu };
};
document.body.dataset.ready = 'yes';

declare global {
  interface Window {
    /** XYZ per case of every group, in the groups' order, as the shader computes it. */
    renderFilmXyz?: (groups: readonly ParityGroup[], mode: ParityMode, quality?: FilmQuality) => number[][][];
    /**
     * The GPU film after `steps` steps from its start (air blown as given, pricked at a direction
     * first, renewed after a burst): per cell η, Γ, intact; per edge u·n_e; the open holes; the
     * residual its surfactant solve reaches from there (surfactantResidual.ts).
     */
    runFlow?: (
      parameters: Record<string, number>,
      steps: number,
      blow?: { center: [number, number, number]; velocityMps: [number, number, number] } | null,
      puncture?: [number, number, number] | null,
      renew?: boolean,
    ) => {
      eta: number[];
      gamma: number[];
      intact: number[];
      edgeVelocity: number[];
      holes: { center: number[]; radius: number[] }[];
      surfactantResidual: number;
      steps: number;
    };
    /** A film's padded start as made on the CPU (drawn before the simulation's programs are compiled) and by the GPU's start and halo passes, texel for texel. */
    startPaddedFilms?: (parameters: Record<string, number>) => { cpu: number[]; gpu: number[] };
  }
}
