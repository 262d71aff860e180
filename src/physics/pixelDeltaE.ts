import { XYZ_TO_LINEAR_SRGB, applyMatrix3, invert3, srgbDecode } from './colorConversions.ts';
import { deltaE00 } from './colorDifference.ts';
import type { Xyz } from './spectralWeights.ts';

const LINEAR_SRGB_TO_XYZ = invert3(XYZ_TO_LINEAR_SRGB);

/** The XYZ of an 8-bit sRGB pixel (decoded, then eq 19 inverted). */
export const srgb8ToXyz = (rgb: readonly number[]): Xyz =>
  applyMatrix3(LINEAR_SRGB_TO_XYZ, [0, 1, 2].map((i) => srgbDecode(rgb[i]! / 255)) as [number, number, number]);

/** CIEDE2000 between two 8-bit sRGB pixels, with the display's white (255, 255, 255) as the reference white. */
export const pixelDeltaE00 = (a: readonly number[], b: readonly number[]): number =>
  deltaE00(srgb8ToXyz(a), srgb8ToXyz(b), srgb8ToXyz([255, 255, 255]));
