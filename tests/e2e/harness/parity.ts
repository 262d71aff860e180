/** The parity page: film XYZ of the given cases through the real shaders (FilmXyzProbe). */
import { WebGLRenderer } from 'three';
import { DEFAULT_FILM_QUALITY } from '../../../src/render/filmQuality.ts';
import { FilmXyzProbe } from '../../../src/render/filmXyzProbe.ts';

const canvas = document.querySelector<HTMLCanvasElement>('#gl');
if (!canvas) throw new Error('parity.html must hold #gl');
const probe = new FilmXyzProbe(new WebGLRenderer({ canvas }));

window.renderFilmXyz = (groups, mode, quality = DEFAULT_FILM_QUALITY) => probe.render(groups, mode, quality);
document.body.dataset.ready = 'yes';
