import { type NumberDomain, isInDomain, parseDecimal, rejectValue } from '../input/validate.ts';

/**
 * A tinted light: linear sRGB (R, G, B) relative to the light's white, each in [0, 1]. The light's
 * spectrum is the illuminant's times the tint's spectrum by Mallett and Yuksel's sRGB basis,
 * R·r(λ) + G·g(λ) + B·b(λ) (illuminants.ts, tintSpectrum; docs/physics.md#a-tinted-light). Its
 * names, checks and text here, apart from the basis's tables, so checking a tint loads no data.
 */
export type LightTint = readonly [number, number, number];

/** Where each component of a tint may be. */
export const LIGHT_TINT_DOMAIN: NumberDomain = { min: 0, max: 1, unit: '' };
/** The untinted light: the basis sums to 1, so its spectrum is the illuminant's. */
export const WHITE_TINT: LightTint = [1, 1, 1];

/** What a tint may be, as every message (URL, element, CLI, the material's options) states it. */
export const LIGHT_TINT_EXPECTED = `three numbers R,G,B, each in [${LIGHT_TINT_DOMAIN.min}, ${LIGHT_TINT_DOMAIN.max}]`;

const isTint = (values: readonly unknown[]): values is LightTint =>
  values.length === 3 && values.every((v) => isInDomain(v, LIGHT_TINT_DOMAIN));

/** A tint as text `R,G,B` (URL, attribute, command line); null when not three numbers in the domain. */
export function parseLightTint(text: string): LightTint | null {
  const values = text.split(',').map(parseDecimal);
  return isTint(values) ? values : null;
}

/** A tint as a JSON value (cases files, the material's options): `[R, G, B]`; else a ParameterError naming `field`. */
export function lightTintFromJson(value: unknown, field = 'lightTint'): LightTint {
  if (Array.isArray(value) && isTint(value)) return [value[0], value[1], value[2]];
  return rejectValue(field, value, LIGHT_TINT_EXPECTED);
}

/** A tint as text: `R,G,B` (what parseLightTint reads back). */
export const lightTintText = (tint: LightTint): string => tint.join(',');

/** Whether a tint leaves the light as it is. */
export const isWhiteTint = (tint: LightTint): boolean => tint.every((c, i) => c === WHITE_TINT[i]);
