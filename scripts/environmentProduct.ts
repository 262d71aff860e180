/**
 * `npm run environment-product`: how far the product of two RGB triples (the film's colour under
 * the light times an environment's colour) is from the film's reflection of that colour as a
 * spectrum, M · c (src/physics/environmentMatrix.ts), for a soap film (n 1.33 in air) at normal
 * incidence, 50–1500 nm every 5 nm, under D65: ΔE00 median and largest per colour, CIELAB against
 * D65's white. The colours are linear sRGB relative to the light's white. Then the light of the far
 * wall seen through the near one, which the bubble draws as (c' − M_near c') with c' = M_far c (two
 * matrices in turn, the far wall's colour an RGB triple between them), against the integral of
 * (1 − R_near) R_far times the light of colour c, and the product of RGB triples for comparison.
 * Prints Markdown for docs/physics.md.
 */
import { median } from './bench/median.ts';
import { XYZ_TO_LINEAR_SRGB, applyMatrix3, invert3 } from '../src/physics/colorConversions.ts';
import { deltaE00 } from '../src/physics/colorDifference.ts';
import { filmEnvironmentMatrix, reflectedXyz } from '../src/physics/environmentMatrix.ts';
import { filmXyz, integrateXyz, whiteXyz } from '../src/physics/spectralIntegration.ts';
import { type Matrix3 } from '../src/physics/colorConversions.ts';
import { filmOptics, reflectanceAt } from '../src/physics/filmReflectance.ts';
import { spectralWeights } from '../src/physics/spectralWeights.ts';

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

/** M in linear sRGB: XYZ → linear sRGB after M. */
const workingMatrix = (m: Matrix3) => (c: readonly [number, number, number]) => applyMatrix3(XYZ_TO_LINEAR_SRGB, reflectedXyz(m, c));
/** The far wall is the near one's thickness times this (a bubble's walls differ; equal walls are a special case). */
const FAR_OVER_NEAR = 1.3;
const walls = films.map((near) => {
  const far = { ...near, thicknessNm: near.thicknessNm * FAR_OVER_NEAR };
  return {
    near,
    far,
    mNear: workingMatrix(filmEnvironmentMatrix(near, { illuminant: 'D65' })),
    mFar: workingMatrix(filmEnvironmentMatrix(far, { illuminant: 'D65' })),
  };
});

console.log(`\nThe far wall (${FAR_OVER_NEAR} × the near wall's thickness) seen through the near wall:\n`);
console.log(
  '| colour (linear sRGB) | drawn (two matrices): ΔE00 median | largest | RGB product: ΔE00 median | largest |\n|---|---|---|---|---|',
);
for (const [name, c] of COLOURS) {
  const drawn: number[] = [];
  const product: number[] = [];
  for (const { near, far, mNear, mFar } of walls) {
    const [oNear, oFar] = [filmOptics(near), filmOptics(far)];
    const reference = integrateXyz((l) => (1 - reflectanceAt(oNear, l)) * reflectanceAt(oFar, l), spectralWeights('D65', 'white', c), 8);
    const farColour = mFar(c);
    const kept = mNear(farColour);
    drawn.push(
      deltaE00(
        applyMatrix3(LINEAR_SRGB_TO_XYZ, [0, 1, 2].map((i) => farColour[i]! - kept[i]!) as unknown as [number, number, number]),
        reference,
        white,
      ),
    );
    const [rNear, rFar] = [near, far].map((f) => applyMatrix3(XYZ_TO_LINEAR_SRGB, filmXyz(f)));
    const rgb = [0, 1, 2].map((i) => (1 - rNear![i]!) * rFar![i]! * c[i]!) as unknown as [number, number, number];
    product.push(deltaE00(applyMatrix3(LINEAR_SRGB_TO_XYZ, rgb), reference, white));
  }
  console.log(
    `| ${name} | ${median(drawn).toFixed(2)} | ${Math.max(...drawn).toFixed(2)} | ${median(product).toFixed(2)} | ${Math.max(...product).toFixed(1)} |`,
  );
}
