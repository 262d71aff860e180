/**
 * A film's reflection of coloured light as a 3×3 matrix. A colour c (linear sRGB relative to the
 * light's white) is a spectrum by Mallett and Yuksel's basis, ρ_c(λ) = c_r B_r(λ) + c_g B_g(λ) +
 * c_b B_b(λ) (illuminants.ts, tintSpectrum); the film's reflection of light S(λ) ρ_c(λ) is the
 * integral of eqs (15)–(18) with S ρ_c in place of S, linear in c. So it is M · c, where column j
 * of M is the film's XYZ under S·B_j: one matrix per film, thickness and angle serves every colour
 * it reflects (an environment texel, the sky, a tinted light), and M · (1, 1, 1) is the film under
 * the light itself, since the basis sums to 1 (docs/physics.md#coloured-light-as-spectra).
 */
import { type Matrix3, applyMatrix3 } from './colorConversions.ts';
import { type LightTint } from './lightTint.ts';
import { type FilmStack } from './filmReflectance.ts';
import { type Medium } from './medium.ts';
import { type ColorOptions, filmXyz } from './spectralIntegration.ts';
import { type SpectralLight, type Xyz, lightWeights } from './spectralWeights.ts';
import { type SpectralBins, spectralBins } from './binnedIntegration.ts';

/** The basis spectra as tints: the light times B_r, B_g, B_b. */
const BASIS_TINTS: readonly LightTint[] = [
  [1, 0, 0],
  [0, 1, 0],
  [0, 0, 1],
];

/** M, row-major, of a film whose XYZ under the light times a tint's spectrum is `xyzUnder(tint)`. */
export function environmentMatrix(xyzUnder: (tint: LightTint) => Xyz): Matrix3 {
  const [r, g, b] = BASIS_TINTS.map(xyzUnder) as [Xyz, Xyz, Xyz];
  return [r[0], g[0], b[0], r[1], g[1], b[1], r[2], g[2], b[2]];
}

/** M of one film under the options' light (filmXyz's stack and options, bar the tint: a tint t is the colour M · t). */
export const filmEnvironmentMatrix = (stack: FilmStack<Medium>, options: Omit<ColorOptions, 'lightTint'> = {}): Matrix3 =>
  environmentMatrix((tint) => filmXyz(stack, { ...options, lightTint: tint }));

/** XYZ of the film's reflection of light of colour `c` (linear sRGB relative to the light's white): M · c. */
export const reflectedXyz = (m: Matrix3, c: readonly [number, number, number]): Xyz => applyMatrix3(m, c);

/**
 * The bins of `light` (`count` of them) as the shaders integrate each colour plane: the weights of
 * the light (times its basis spectrum, if it has one), each bin's phase window that of the light
 * without the basis. A basis spectrum is smooth over a bin, so the window hardly moves with it, and
 * sharing it lets one R per bin serve all three columns of M.
 */
export function lightBins(light: SpectralLight, count: number): SpectralBins {
  const bins = spectralBins(lightWeights(light), count);
  if (light.basis === undefined) return bins;
  const { basis: _, ...whole } = light;
  return { ...bins, windows: spectralBins(lightWeights(whole), count).windows };
}
