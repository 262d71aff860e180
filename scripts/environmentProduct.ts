/**
 * `npm run environment-product`: how far the product of two RGB triples (the film's colour under
 * the light times an environment's colour) is from the film's reflection of that colour as a
 * spectrum, M · c (src/physics/environmentMatrix.ts), for a soap film (n 1.33 in air) at normal
 * incidence, 50–1500 nm every 5 nm, under D65: ΔE00 median and largest per colour, CIELAB against
 * D65's white. The colours are linear sRGB relative to the light's white. Prints Markdown for
 * docs/physics.md.
 */
import { median } from './bench/median.ts';
import { XYZ_TO_LINEAR_SRGB, applyMatrix3, invert3 } from '../src/physics/colorConversions.ts';
import { deltaE00 } from '../src/physics/colorDifference.ts';
import { filmEnvironmentMatrix, reflectedXyz } from '../src/physics/environmentMatrix.ts';
import { filmXyz, whiteXyz } from '../src/physics/spectralIntegration.ts';

const COLOURS: readonly (readonly [string, readonly [number, number, number]])[] = [
  ['sunset orange', [1, 0.45, 0.1]],
  ['sky blue', [0.3, 0.55, 1]],
  ['park green', [0.15, 0.45, 0.08]],
  ['teal', [0.02, 0.45, 0.42]],
  ['red sign', [0.85, 0.04, 0.03]],
];

const LINEAR_SRGB_TO_XYZ = invert3(XYZ_TO_LINEAR_SRGB);
const white = whiteXyz('D65');
const films = Array.from({ length: 291 }, (_, i) => ({ nOutside: 1, nFilm: 1.33, nInside: 1, thicknessNm: 50 + 5 * i, angleDeg: 0 }));
const matrices = films.map((f) => ({
  m: filmEnvironmentMatrix(f, { illuminant: 'D65' }),
  rgb: applyMatrix3(XYZ_TO_LINEAR_SRGB, filmXyz(f)),
}));

console.log('| colour (linear sRGB) | ΔE00 median | ΔE00 largest |\n|---|---|---|');
for (const [name, c] of COLOURS) {
  const errors = matrices.map(({ m, rgb }) => {
    const product = applyMatrix3(LINEAR_SRGB_TO_XYZ, [rgb[0] * c[0], rgb[1] * c[1], rgb[2] * c[2]]);
    return deltaE00(product, reflectedXyz(m, c), white);
  });
  console.log(`| ${name} (${c.join(', ')}) | ${median(errors).toFixed(2)} | ${Math.max(...errors).toFixed(1)} |`);
}
