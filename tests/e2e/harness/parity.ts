/** The parity page: film XYZ (FilmXyzProbe) and film thickness of the given cases through the real shaders. */
import { WebGLRenderer } from 'three';
import { DEFAULT_FILM_QUALITY, type FilmQuality } from '../../../src/settings/filmQuality.ts';
import type { ParityGroup, ParityMode } from '../../../scripts/harness/parityCase.ts';
import { FilmXyzProbe } from '../../../scripts/harness/filmXyzProbe.ts';
import { renderThickness } from './thicknessFieldProbe.ts';

const canvas = document.querySelector<HTMLCanvasElement>('#gl');
if (!canvas) throw new Error('parity.html must hold #gl');
const renderer = new WebGLRenderer({ canvas });
const probe = new FilmXyzProbe(renderer);

window.renderFilmXyz = (groups, mode, quality = DEFAULT_FILM_QUALITY) => probe.render(groups, mode, quality);
window.renderThickness = (points, s) => renderThickness(renderer, points, s);
document.body.dataset.ready = 'yes';

declare global {
  interface Window {
    /** XYZ per case of every group, in the groups' order, as the shader computes it. */
    renderFilmXyz?: (groups: readonly ParityGroup[], mode: ParityMode, quality?: FilmQuality) => number[][][];
  }
}
