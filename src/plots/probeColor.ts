import { type Matrix3, applyMatrix3, encode8, mapToGamut } from '../physics/colorConversions.ts';
import { deltaE00 } from '../physics/colorDifference.ts';
import { type Polarization } from '../physics/filmReflectance.ts';
import { type IlluminantSpec } from '../physics/illuminants.ts';
import type { LightTint } from '../physics/lightTint.ts';
import { whiteXyz } from '../physics/spectralIntegration.ts';
import { type Normalization, type Xyz } from '../physics/spectralWeights.ts';
import { type FilmOption, filmStackOf, stackXyz } from '../methods/filmStacks.ts';

/** The reference's account of a probed film, and how far the rendered colour is from it. */
export interface ProbeColor {
  readonly xyz: Xyz;
  readonly linearRgb: readonly [number, number, number];
  /** The gamut-clipped colour, encoded to 8 bits, and as #rrggbb. */
  readonly rgb8: readonly [number, number, number];
  readonly hex: string;
  /** ΔE00 (CIEDE2000) between the rendered and the reference XYZ, under the untinted illuminant's white. */
  readonly deltaE00: number;
}

export interface ProbeLight {
  readonly illuminant: IlluminantSpec;
  /** The light's tint (none: untinted). */
  readonly lightTint?: LightTint;
  readonly polarization: Polarization;
  readonly normalization: Normalization;
}

/** The reference colour (eqs 15–19) of the probed film or stack, compared with what the shader rendered there. */
export function probeColor(film: FilmOption, light: ProbeLight, xyzToLinearRgb: Matrix3, renderedXyz: Xyz): ProbeColor {
  const xyz = stackXyz(filmStackOf(film), light);
  const linearRgb = applyMatrix3(xyzToLinearRgb, xyz);
  const [r, g, b] = mapToGamut(linearRgb, xyz[1]).map(encode8) as [number, number, number];
  const hex = `#${[r, g, b].map((v) => v.toString(16).padStart(2, '0')).join('')}`;
  return { xyz, linearRgb, rgb8: [r, g, b], hex, deltaE00: deltaE00(renderedXyz, xyz, whiteXyz(light.illuminant, light.normalization)) };
}
