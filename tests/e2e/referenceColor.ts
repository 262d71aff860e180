import { type Matrix3, XYZ_TO_LINEAR_SRGB, applyMatrix3, encode8, mapToGamut } from '../../src/physics/colorConversions.ts';
import { SOAP_FILM_IN_AIR } from '../../src/physics/filmReflectance.ts';
import type { IlluminantSpec } from '../../src/physics/illuminants.ts';
import { type MediumStack } from '../../src/physics/medium.ts';
import { filmXyz } from '../../src/physics/spectralIntegration.ts';

/**
 * The reference's 8-bit colour of a film (a soap film in air seen head-on unless `stack` says
 * otherwise): XYZ → linear RGB (eq 19 for sRGB, the CLI's srgb8) → clip → encode → round.
 */
export function reference8(
  stack: Partial<MediumStack> & Pick<MediumStack, 'thicknessNm'>,
  illuminant: IlluminantSpec = 'D65',
  toLinear: Matrix3 = XYZ_TO_LINEAR_SRGB,
): number[] {
  const xyz = filmXyz({ ...SOAP_FILM_IN_AIR, angleDeg: 0, ...stack }, { illuminant });
  return mapToGamut(applyMatrix3(toLinear, xyz), xyz[1]).map(encode8);
}

/** 8-bit rounding on each side, plus the table's interpolation and float32: 2 codes. */
export const MAX_CODE_DIFFERENCE = 2;

export const worstCodeDifference = (a: readonly number[], b: readonly number[]) => Math.max(...a.map((v, i) => Math.abs(v - b[i]!)));
