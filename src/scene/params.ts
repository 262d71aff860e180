import { FILM_STACK_DOMAIN, POLARIZATIONS } from '../physics/filmReflectance.ts';
import { DAYLIGHT_CCT_MAX_K, DAYLIGHT_CCT_MIN_K, type IlluminantSpec, NAMED_ILLUMINANTS } from '../physics/illuminants.ts';
import { NORMALIZATIONS } from '../physics/spectralIntegration.ts';
import { type NumberDomain, expectedNumber, isInDomain, parseDecimal } from '../physics/validate.ts';
import { DEFAULT_SETTINGS, ENVIRONMENTS, FIELDS, type FilmSettings, MODES, SIDES, SPACES } from '../render/filmSettings.ts';

/** Longer values are refused outright (a mangled link, not a number). */
export const MAX_VALUE_LENGTH = 64;
/** How much of a refused value a message repeats before cutting it short. */
export const MAX_ECHOED_CHARS = 24;

/** One URL parameter: what it accepts (for messages) and its reading, or null when refused. */
interface Parameter {
  readonly expected: string;
  readonly read: (raw: string) => Partial<FilmSettings> | null;
}

const number = (key: keyof FilmSettings, domain: NumberDomain): Parameter => ({
  expected: expectedNumber(domain),
  read: (raw) => {
    const v = parseDecimal(raw);
    return isInDomain(v, domain) ? { [key]: v } : null;
  },
});

const oneOf = (key: keyof FilmSettings, allowed: readonly string[]): Parameter => ({
  expected: `one of ${allowed.join(', ')}`,
  read: (raw) => (allowed.includes(raw) ? { [key]: raw } : null),
});

const CCT_DOMAIN: NumberDomain = { min: DAYLIGHT_CCT_MIN_K, max: DAYLIGHT_CCT_MAX_K, unit: 'K' };
const illuminant: Parameter = {
  expected: `one of ${NAMED_ILLUMINANTS.join(', ')} or a daylight CCT in [${DAYLIGHT_CCT_MIN_K}, ${DAYLIGHT_CCT_MAX_K}] K`,
  read: (raw) => {
    if ((NAMED_ILLUMINANTS as readonly string[]).includes(raw)) return { illuminant: raw as IlluminantSpec };
    const cct = parseDecimal(raw);
    return isInDomain(cct, CCT_DOMAIN) ? { illuminant: { daylightCct: cct } } : null;
  },
};

const flag = (key: keyof FilmSettings): Parameter => ({
  expected: '0 or 1',
  read: (raw) => (raw === '0' || raw === '1' ? { [key]: raw === '1' } : null),
});

const FRACTION: NumberDomain = { min: 0, max: 1, unit: '' };
const probe: Parameter = {
  expected: 'x,y with both in [0, 1] (fractions of the view from the top left)',
  read: (raw) => {
    const parts = raw.split(',').map(parseDecimal);
    const [x, y] = parts;
    return parts.length === 2 && isInDomain(x!, FRACTION) && isInDomain(y!, FRACTION) ? { probe: [x!, y!] } : null;
  },
};

/** The URL parameters, what each accepts, and how it is read. */
export const PARAMETERS: Readonly<Record<string, Parameter>> = {
  thickness: number('thicknessNm', FILM_STACK_DOMAIN.thicknessNm),
  thicknessRange: number('thicknessRangeNm', FILM_STACK_DOMAIN.thicknessNm),
  speed: number('swirlSpeed', { min: 0, max: 10, unit: '' }),
  field: oneOf('field', FIELDS),
  nFilm: number('nFilm', FILM_STACK_DOMAIN.nFilm),
  nOutside: number('nOutside', FILM_STACK_DOMAIN.nOutside),
  nInside: number('nInside', FILM_STACK_DOMAIN.nInside),
  illuminant,
  polarization: oneOf('polarization', POLARIZATIONS),
  normalization: oneOf('normalization', NORMALIZATIONS),
  space: oneOf('space', SPACES),
  mode: oneOf('mode', MODES),
  sides: oneOf('sides', SIDES),
  env: oneOf('env', ENVIRONMENTS),
  exposure: number('exposure', { min: 0, max: 100, unit: '' }),
  animate: flag('animate'),
  time: number('timeSeconds', { min: 0, max: 1e6, unit: 's' }),
  probe,
};

export interface ParsedSettings {
  readonly settings: FilmSettings;
  /** One line per refused parameter, naming it and its allowed range; its default was kept. */
  readonly errors: readonly string[];
}

/** A refused value as a message shows it: quoted, cut short, its length said when cut. */
const shown = (raw: string): string =>
  raw.length > MAX_ECHOED_CHARS ? `${JSON.stringify(raw.slice(0, MAX_ECHOED_CHARS))}… (${raw.length} characters)` : JSON.stringify(raw);

/**
 * Reads settings from a query string. A bad value (or one longer than MAX_VALUE_LENGTH) is
 * reported and never used: the setting keeps its value from `base`, or from an earlier good
 * occurrence of the same parameter. Unknown names belong to others (the embedding page) and are skipped.
 */
export function parseSettings(query: string, base: FilmSettings = DEFAULT_SETTINGS): ParsedSettings {
  let settings = base;
  const errors: string[] = [];
  for (const [name, raw] of new URLSearchParams(query)) {
    // Own keys only: `?constructor=` or `?toString=` must not reach Object.prototype.
    const parameter = Object.hasOwn(PARAMETERS, name) ? PARAMETERS[name] : undefined;
    if (!parameter) continue;
    const read = raw.length > MAX_VALUE_LENGTH ? null : parameter.read(raw);
    if (read) settings = { ...settings, ...read };
    else {
      const tooLong = raw.length > MAX_VALUE_LENGTH ? ` of at most ${MAX_VALUE_LENGTH} characters` : '';
      errors.push(`${name}=${shown(raw)} ignored: expected ${parameter.expected}${tooLong}`);
    }
  }
  return { settings, errors };
}

/** The query string that `parseSettings` turns back into these settings (defaults left out). */
export function settingsToQuery(s: FilmSettings): string {
  const d = DEFAULT_SETTINGS;
  const illuminantText = (i: FilmSettings['illuminant']) => (typeof i === 'object' ? String(i.daylightCct) : i);
  const pairs: [string, string, string][] = [
    ['thickness', String(s.thicknessNm), String(d.thicknessNm)],
    ['thicknessRange', String(s.thicknessRangeNm), String(d.thicknessRangeNm)],
    ['speed', String(s.swirlSpeed), String(d.swirlSpeed)],
    ['field', s.field, d.field],
    ['nFilm', String(s.nFilm), String(d.nFilm)],
    ['nOutside', String(s.nOutside), String(d.nOutside)],
    ['nInside', String(s.nInside), String(d.nInside)],
    ['illuminant', illuminantText(s.illuminant), illuminantText(d.illuminant)],
    ['polarization', s.polarization, d.polarization],
    ['normalization', s.normalization, d.normalization],
    ['space', s.space, d.space],
    ['mode', s.mode, d.mode],
    ['sides', s.sides, d.sides],
    ['env', s.env, d.env],
    ['exposure', String(s.exposure), String(d.exposure)],
    ['animate', s.animate ? '1' : '0', d.animate ? '1' : '0'],
    ['time', String(s.timeSeconds), String(d.timeSeconds)],
    ['probe', s.probe.map((v) => +v.toFixed(4)).join(','), d.probe.join(',')],
  ];
  const query = new URLSearchParams(pairs.filter(([, v, def]) => v !== def).map(([k, v]) => [k, v]));
  return query.toString();
}
