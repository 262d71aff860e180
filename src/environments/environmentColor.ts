import { type NumberDomain, isInDomain, parseDecimal } from '../input/validate.ts';

/**
 * A uniform coloured environment (`env=color:R,G,B`): the same radiance L(ω) = (R, G, B) from every
 * direction, linear sRGB relative to the light's white. A room of one colour, for teaching: the
 * walls reflect it in every mirror direction and it shows behind, so the film is seen reflecting one
 * known colour, as a spectrum (docs/physics.md#environments). Its checks and text here;
 * the environments' registry (environments.ts) takes it as the one environment given by parameters.
 */
export type EnvironmentColor = readonly [number, number, number];

/**
 * Where each component may be: up to four times the light's white, so that a film reflecting a
 * few percent still shows brightly against a background that clips to white (tone mapping `none`).
 */
export const ENVIRONMENT_COLOR_DOMAIN: NumberDomain = { min: 0, max: 4, unit: '' };

/** The prefix of a colour's text, and the form every message writes it in. */
export const ENVIRONMENT_COLOR_PREFIX = 'color:';
export const ENVIRONMENT_COLOR_FORM = `${ENVIRONMENT_COLOR_PREFIX}R,G,B`;

/** What a colour may be, as every message states it. */
export const ENVIRONMENT_COLOR_EXPECTED = `${ENVIRONMENT_COLOR_FORM}, each in [${ENVIRONMENT_COLOR_DOMAIN.min}, ${ENVIRONMENT_COLOR_DOMAIN.max}]`;

const CHANNELS = ['R', 'G', 'B'] as const;

/**
 * A colour's text `color:R,G,B`: the colour, or why not (`problem`, in English, null for a text
 * that is not a colour's at all: it names no `color:`).
 */
export function readEnvironmentColor(text: string): { readonly color: EnvironmentColor } | { readonly problem: string | null } {
  if (!text.startsWith(ENVIRONMENT_COLOR_PREFIX)) return { problem: null };
  const values = text.slice(ENVIRONMENT_COLOR_PREFIX.length).split(',').map(parseDecimal);
  if (values.length !== CHANNELS.length || values.some(Number.isNaN)) return { problem: 'not three numbers R,G,B' };
  const { min, max } = ENVIRONMENT_COLOR_DOMAIN;
  const outside = values.findIndex((v) => !isInDomain(v, ENVIRONMENT_COLOR_DOMAIN));
  if (outside >= 0)
    return { problem: `${CHANNELS[outside]} is ${values[outside]}, ${values[outside]! < min ? `below ${min}` : `above ${max}`}` };
  return { color: [values[0]!, values[1]!, values[2]!] };
}

/** A colour as text: `color:R,G,B` (what readEnvironmentColor reads back). */
export const environmentColorText = (color: EnvironmentColor): string => `${ENVIRONMENT_COLOR_PREFIX}${color.join(',')}`;
