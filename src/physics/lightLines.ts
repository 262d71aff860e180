import { type NumberDomain, isInDomain, parseDecimal } from '../input/validate.ts';

/**
 * Line sources: light at a few wavelengths only, I_in(λ) = Σ p_l δ(λ − λ_l). Eqs (15)–(18) then
 * sum over the lines instead of integrating, X_j = Σ p_l R(λ_l) x̄_j(λ_l) / k (docs/physics.md#lights).
 */

/** One line of a line source: its wavelength in nm and its relative power. */
export interface SpectralLine {
  readonly nm: number;
  readonly power: number;
}

/** Low-pressure sodium's D doublet: D2 at 588.995 nm and D1 at 589.592 nm, powers 2 : 1. */
export const SODIUM_D_LINES: readonly SpectralLine[] = [
  { nm: 588.995, power: 2 },
  { nm: 589.592, power: 1 },
];

/** Where a single line (`line:NM`) may be: the visible band, where the colour-matching functions matter. */
export const LINE_DOMAIN_NM: NumberDomain = { min: 380, max: 780, unit: 'nm' };
/** The most lines a light has (the shaders' uniform array is this long). */
export const MAX_LIGHT_LINES = SODIUM_D_LINES.length;

/** The prefix of a single line's text: `line:NM`. */
export const LINE_PREFIX = 'line:';

/** A single line as text `line:NM` with NM in LINE_DOMAIN_NM: its wavelength, or null. */
export function parseLineNm(text: string): number | null {
  if (!text.startsWith(LINE_PREFIX)) return null;
  const nm = parseDecimal(text.slice(LINE_PREFIX.length));
  return isInDomain(nm, LINE_DOMAIN_NM) ? nm : null;
}

/** What a single line may be, as the messages state it. */
export const LINE_EXPECTED = `${LINE_PREFIX}NM with NM in [${LINE_DOMAIN_NM.min}, ${LINE_DOMAIN_NM.max}] nm`;
