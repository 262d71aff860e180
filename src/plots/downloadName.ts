import { type IlluminantSpec, illuminantKey } from '../physics/illuminants.ts';
import { type LightTint, isWhiteTint } from '../physics/lightTint.ts';

/** What a download is named after: the probed film and its light. */
export interface ProbedView {
  readonly thicknessNm: number;
  readonly angleDeg: number;
  readonly illuminant: IlluminantSpec;
  /** The light's tint (none: untinted). */
  readonly lightTint?: LightTint;
}

/**
 * A download's file name, after the view: `film-550nm-D65-30deg-spectrum.png` (thickness and
 * angle rounded to whole nm and degrees; a daylight CCT written `6500K`, a line `line-632.8nm`, a
 * tinted light followed by its tint, `FL2-tint-1-0.5-0.2`). Only digits, letters,
 * `-` and `.`: every part is a number or a schema-checked name.
 */
export function downloadName(view: ProbedView, what: string, extension: string): string {
  const i = view.illuminant;
  const named = typeof i === 'object' && 'daylightCct' in i ? `${i.daylightCct}K` : illuminantKey(i);
  const tint = view.lightTint;
  const light = tint === undefined || isWhiteTint(tint) ? named : `${named}-tint-${tint.join('-')}`;
  return `film-${Math.round(view.thicknessNm)}nm-${light}-${Math.round(view.angleDeg)}deg-${what}.${extension}`;
}
