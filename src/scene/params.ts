import { POLARIZATIONS } from '../physics/filmReflectance.ts';
import { DAYLIGHT_CCT_MAX_K, DAYLIGHT_CCT_MIN_K, type IlluminantSpec } from '../physics/illuminants.ts';
import { NORMALIZATIONS } from '../physics/spectralIntegration.ts';
import { DEFAULT_SETTINGS, ENVIRONMENTS, FIELDS, type FilmSettings, MODES, SIDES, SPACES } from '../render/filmSettings.ts';

/** Longer values are refused outright (a mangled link, not a number). */
export const MAX_VALUE_LENGTH = 64;

type Parser = (raw: string) => Partial<FilmSettings>;

const number =
  (key: keyof FilmSettings, min: number, max: number, unit = ''): Parser =>
  (raw) => {
    const v = raw.trim() === '' ? NaN : Number(raw);
    if (!Number.isFinite(v) || v < min || v > max) throw new Error(`expected a number in [${min}, ${max}]${unit ? ` ${unit}` : ''}`);
    return { [key]: v };
  };

const oneOf =
  (key: keyof FilmSettings, allowed: readonly string[]): Parser =>
  (raw) => {
    if (!allowed.includes(raw)) throw new Error(`expected one of ${allowed.join(', ')}`);
    return { [key]: raw };
  };

const illuminant: Parser = (raw) => {
  if (['D55', 'D65', 'D93', 'E', 'D65-table'].includes(raw)) return { illuminant: raw as IlluminantSpec };
  const cct = raw.trim() === '' ? NaN : Number(raw);
  if (!Number.isFinite(cct) || cct < DAYLIGHT_CCT_MIN_K || cct > DAYLIGHT_CCT_MAX_K) {
    throw new Error(`expected D55, D65, D93, E, D65-table or a daylight CCT in [${DAYLIGHT_CCT_MIN_K}, ${DAYLIGHT_CCT_MAX_K}] K`);
  }
  return { illuminant: { daylightCct: cct } };
};

const flag = (key: keyof FilmSettings): Parser => (raw) => {
  if (raw !== '0' && raw !== '1') throw new Error('expected 0 or 1');
  return { [key]: raw === '1' };
};

const probe: Parser = (raw) => {
  const parts = raw.split(',');
  const [x, y] = parts.map((v) => (v.trim() === '' ? NaN : Number(v)));
  if (parts.length !== 2 || !(x! >= 0 && x! <= 1 && y! >= 0 && y! <= 1)) throw new Error('expected x,y with both in [0, 1] (fractions of the view from the top left)');
  return { probe: [x!, y!] };
};

/** The URL parameters, their parsers and (through the messages) their ranges. */
export const PARAMETERS: Record<string, Parser> = {
  thickness: number('thicknessNm', 0, 20000, 'nm'),
  thicknessRange: number('thicknessRangeNm', 0, 20000, 'nm'),
  speed: number('swirlSpeed', 0, 10),
  field: oneOf('field', FIELDS),
  nFilm: number('nFilm', 1, 4),
  nOutside: number('nOutside', 1, 4),
  nInside: number('nInside', 1, 4),
  illuminant,
  polarization: oneOf('polarization', POLARIZATIONS),
  normalization: oneOf('normalization', NORMALIZATIONS),
  space: oneOf('space', SPACES),
  mode: oneOf('mode', MODES),
  sides: oneOf('sides', SIDES),
  env: oneOf('env', ENVIRONMENTS),
  exposure: number('exposure', 0, 100),
  animate: flag('animate'),
  time: number('timeSeconds', 0, 1e6, 's'),
  probe,
};

export interface ParsedSettings {
  readonly settings: FilmSettings;
  /** One line per refused parameter, naming it and its allowed range; its default was kept. */
  readonly errors: readonly string[];
}

/** Reads settings from a query string; a bad value is reported and never used. */
export function parseSettings(query: string, base: FilmSettings = DEFAULT_SETTINGS): ParsedSettings {
  let settings = base;
  const errors: string[] = [];
  for (const [name, raw] of new URLSearchParams(query)) {
    const parse = PARAMETERS[name];
    if (!parse) continue; // unknown names belong to others (the embedding page)
    const shown = raw.length > 24 ? `${raw.slice(0, 24)}…` : raw;
    try {
      if (raw.length > MAX_VALUE_LENGTH) throw new Error(`longer than ${MAX_VALUE_LENGTH} characters`);
      settings = { ...settings, ...parse(raw) };
    } catch (e) {
      errors.push(`${name}=${JSON.stringify(shown)} ignored: ${(e as Error).message}`);
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
