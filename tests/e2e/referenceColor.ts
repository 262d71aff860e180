import { type Matrix3, XYZ_TO_LINEAR_SRGB, applyMatrix3, encode8, mapToGamut } from '../../src/physics/colorConversions.ts';
import { SOAP_FILM_IN_AIR } from '../../src/physics/filmReflectance.ts';
import type { IlluminantSpec } from '../../src/physics/illuminants.ts';
import { layersXyz } from '../../src/physics/stackColor.ts';
import type { FilmStack } from '../../src/physics/filmReflectance.ts';
import type { Medium } from '../../src/physics/medium.ts';
import { filmXyz } from '../../src/physics/spectralIntegration.ts';
import type { Xyz } from '../../src/physics/spectralWeights.ts';
import type { LayerStack } from '../../src/physics/transferMatrix.ts';

/** XYZ as 8-bit codes: XYZ → linear RGB (eq 19 for sRGB, the CLI's srgb8) → clip → encode → round. */
export const xyzTo8 = (xyz: Xyz, toLinear: Matrix3): number[] => mapToGamut(applyMatrix3(toLinear, xyz), xyz[1]).map(encode8);

/** The reference's 8-bit colour of a film (a soap film in air seen head-on unless `stack` says otherwise). */
export function reference8(
  stack: Partial<FilmStack<Medium>> & Pick<FilmStack<Medium>, 'thicknessNm'>,
  illuminant: IlluminantSpec = 'D65',
  toLinear: Matrix3 = XYZ_TO_LINEAR_SRGB,
): number[] {
  return xyzTo8(filmXyz({ ...SOAP_FILM_IN_AIR, angleDeg: 0, ...stack }, { illuminant }), toLinear);
}

/** The reference's 8-bit colour of a stack of films (its XYZ by the transfer matrix, layersXyz), as reference8 gives a film's. */
export function stackReference8(stack: LayerStack, illuminant: IlluminantSpec = 'D65', toLinear: Matrix3 = XYZ_TO_LINEAR_SRGB): number[] {
  return xyzTo8(layersXyz(stack, { illuminant }), toLinear);
}

/** 8-bit rounding on each side, plus the table's interpolation and float32: 2 codes. */
export const MAX_CODE_DIFFERENCE = 2;

export const worstCodeDifference = (a: readonly number[], b: readonly number[]) => Math.max(...a.map((v, i) => Math.abs(v - b[i]!)));
