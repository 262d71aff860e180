import {
  DAYLIGHT_CCT_DOMAIN_K,
  ILLUMINANT_EXPECTED,
  type IlluminantSpec,
  NAMED_ILLUMINANTS,
  illuminantText,
  parseIlluminant,
} from '../physics/illuminants.ts';
import {
  DISPERSION_CHECK_NM,
  FILM_INDEX_EXPECTED,
  FILM_MATERIALS,
  type FilmIndex,
  filmIndexText,
  readFilmIndex,
} from '../physics/filmIndex.ts';
import { COMPLEX_INDEX_DOMAIN, FILM_STACK_DOMAIN } from '../physics/filmReflectance.ts';
import { type Medium, type MediumRole, mediumText, readMedium } from '../physics/medium.ts';
import { NAMED_MEDIA } from '../physics/namedMedia.ts';
import { type NumberDomain, expectedNumber, isInDomain, parseDecimal } from '../input/validate.ts';
import { type Catalogue, EN, type MessageKey } from '../i18n/en.ts';
import { message } from '../i18n/messages.ts';

/** Where a parameter sits in the control panel, and how it is shown there. */
export type PanelControl =
  | { readonly folder: PanelFolder; readonly kind: 'slider'; readonly min: number; readonly max: number; readonly step: number }
  | { readonly folder: PanelFolder; readonly kind: 'choice'; readonly choices: readonly string[] }
  | { readonly folder: PanelFolder; readonly kind: 'toggle' }
  /** A named illuminant or a daylight CCT: a list of names plus a CCT slider. */
  | { readonly folder: PanelFolder; readonly kind: 'illuminant' }
  /** A film index: a constant (slider), a named material, or a Cauchy film (text A,B[,C]). */
  | { readonly folder: PanelFolder; readonly kind: 'filmIndex' }
  /** A medium (medium.ts): a film index's controls, a named medium (a metal, an oxide) or a complex constant (text n,k). */
  | { readonly folder: PanelFolder; readonly kind: 'medium'; readonly role: Exclude<MediumRole, 'outside'> }
  /** A stack of films as text (layersText.ts); while it holds layers, the film's own index is not used. */
  | { readonly folder: PanelFolder; readonly kind: 'layers' }
  /** `auto` (a toggle) or a number (a slider over the whole domain, shown while the toggle is off, starting at `start`). */
  | {
      readonly folder: PanelFolder;
      readonly kind: 'auto';
      readonly min: number;
      readonly max: number;
      readonly step: number;
      readonly start: number;
    };

export const PANEL_FOLDERS = ['film', 'flow', 'light and colour', 'view'] as const;
export type PanelFolder = (typeof PANEL_FOLDERS)[number];

/**
 * One user-facing parameter of a settings object `S`: one row of the schema from which the URL
 * parser and printer, the element's attributes, the control panel and the command lines' usage
 * are derived.
 */
export interface ParameterRow<S> {
  /** The settings field it sets. */
  readonly key: keyof S & string;
  /** Its name in the URL query and the render command (`--name`). */
  readonly url: string;
  /** Its `<thin-film-bubble>` attribute (HTML attribute names are lower case). */
  readonly attribute: string;
  /** Its flag in the colour tool (`--name`), where the tool takes it. */
  readonly cli: string | null;
  /** Its label in the panel and usage texts, unit included (the English catalogue's `param.<key>`). */
  readonly label: string;
  /** What it accepts, as every refusal states it (in English; `expects` says it in any language). */
  readonly expected: string;
  /** What it accepts as a catalogue text and its values, for a refusal in the page's language. */
  readonly expects: Expectation;
  /** The default. */
  readonly defaultValue: S[keyof S];
  /** The default, as the URL writes it. */
  readonly defaultText: string;
  /** Its reading of a URL value, or null when refused. */
  readonly read: (raw: string) => Partial<S> | null;
  /** Why a refused value is wrong, where the row can say more than `expected` (else undefined). */
  readonly problem?: (raw: string) => string | null;
  /** The longest value the URL reads, where a row takes more than settingsQuery's MAX_VALUE_LENGTH. */
  readonly maxLength?: number;
  /** The URL value that `read` turns back into `s`'s value. */
  readonly write: (s: S) => string;
  /** How the panel shows it; null: not in the panel. */
  readonly control: PanelControl | null;
}

/** What a row accepts as one catalogue text (`expected.*`) and the values it is filled in with; `unit` a `unit.*` key's suffix. */
export interface Expectation {
  readonly key: MessageKey;
  readonly values?: Readonly<Record<string, string | number>>;
  readonly unit?: string;
}

/** An expectation in a catalogue's language. */
export const expectationText = (e: Expectation, cat: Catalogue): string =>
  message(cat, e.key, { ...e.values, unit: e.unit === undefined ? '' : cat[`unit.${e.unit}` as MessageKey] });

/** A catalogue's key for a row's label: `param.<settings key>`. */
export const labelKey = (key: string): MessageKey => {
  const k = `param.${key}`;
  if (!Object.hasOwn(EN, k)) throw new Error(`the catalogue has no label ${k} for the schema's row ${key}`);
  return k as MessageKey;
};

/** A catalogue's key for a choice's label in the panel: `choice.<settings key>.<value>`. */
export const choiceKey = (key: string, value: string): MessageKey => `choice.${key}.${value}` as MessageKey;

/** What every builder takes: the field and its names (its label is the catalogue's), and where the panel shows it. */
interface RowNames<S, K extends keyof S & string> {
  readonly key: K;
  readonly url: string;
  readonly cli?: string;
}

/** The fields common to every row. */
const named = <S, K extends keyof S & string>(n: RowNames<S, K>, defaultValue: S[K], write: (s: S) => string) => ({
  key: n.key,
  url: n.url,
  attribute: n.url.toLowerCase(),
  cli: n.cli ?? null,
  label: EN[labelKey(n.key)],
  defaultValue,
  defaultText: write({ [n.key]: defaultValue } as S),
  write,
});

/** A row of a kind of its own (what it accepts, how it reads and writes), its default text derived. */
export function customRow<S, K extends keyof S & string>(
  n: RowNames<S, K>,
  defaultValue: S[K],
  kind: Pick<ParameterRow<S>, 'expects' | 'read' | 'write' | 'control'>,
): ParameterRow<S> {
  return { ...named(n, defaultValue, kind.write), ...kind, expected: expectationText(kind.expects, EN) };
}

/**
 * A number in a closed domain (a whole number if `step` is 'integer'); the panel's slider spans the
 * whole domain in steps of `step` (1 for an integer).
 */
export function numberRow<S, K extends keyof S & string>(
  n: RowNames<S, K>,
  domain: NumberDomain,
  defaultValue: S[K],
  folder: PanelFolder | null,
  step: number | 'integer' = 0,
): ParameterRow<S> {
  const integer = step === 'integer';
  const values = { min: domain.min, max: domain.max };
  return {
    ...named(n, defaultValue, (s) => String(s[n.key])),
    expected: integer ? `an integer in [${domain.min}, ${domain.max}]${domain.unit ? ` ${domain.unit}` : ''}` : expectedNumber(domain),
    expects: { key: integer ? 'expected.integer' : 'expected.number', values, unit: domain.unit },
    read: (raw) => {
      const v = parseDecimal(raw);
      return isInDomain(v, domain) && (!integer || Number.isInteger(v)) ? ({ [n.key]: v } as Partial<S>) : null;
    },
    control: folder && { folder, kind: 'slider', min: domain.min, max: domain.max, step: integer ? 1 : step },
  };
}

/** A knob a user may leave to the page (the frame governor, docs/governor.md) or give a value honoured exactly. */
export const AUTO = 'auto';
export type Auto<T> = T | typeof AUTO;

/**
 * `auto` (the default) or a number in a closed domain (a whole number if `step` is 'integer'); the
 * panel shows a toggle for `auto` and a slider over the whole domain in steps of `step`, starting
 * at `start` (what a view draws with `auto` and no governor).
 */
export function autoNumberRow<S, K extends keyof S & string>(
  n: RowNames<S, K>,
  domain: NumberDomain,
  folder: PanelFolder | null,
  step: number | 'integer',
  start: number,
): ParameterRow<S> {
  const integer = step === 'integer';
  const number = numberRow<S, K>(n, domain, AUTO as S[K], null, step);
  const values = { auto: AUTO, min: domain.min, max: domain.max };
  return {
    ...named(n, AUTO as S[K], (s) => String(s[n.key])),
    expected: `${AUTO} or ${number.expected}`,
    expects: { key: integer ? 'expected.autoInteger' : 'expected.autoNumber', values, unit: domain.unit },
    read: (raw) => (raw === AUTO ? ({ [n.key]: AUTO } as Partial<S>) : number.read(raw)),
    control: folder && { folder, kind: 'auto', min: domain.min, max: domain.max, step: integer ? 1 : step, start },
  };
}

/** One of a list of names. */
export function choiceRow<S, K extends keyof S & string>(
  n: RowNames<S, K>,
  choices: readonly S[K][] & readonly string[],
  defaultValue: S[K],
  folder: PanelFolder | null,
): ParameterRow<S> {
  return {
    ...named(n, defaultValue, (s) => String(s[n.key])),
    expected: `one of ${choices.join(', ')}`,
    expects: { key: 'expected.choice', values: { choices: choices.join(', ') } },
    read: (raw) => (choices.includes(raw) ? ({ [n.key]: raw } as Partial<S>) : null),
    control: folder && { folder, kind: 'choice', choices },
  };
}

/** On or off, written 1 or 0. */
export function flagRow<S, K extends keyof S & string>(n: RowNames<S, K>, defaultValue: S[K], folder: PanelFolder | null): ParameterRow<S> {
  return {
    ...named(n, defaultValue, (s) => (s[n.key] ? '1' : '0')),
    expected: '0 or 1',
    expects: { key: 'expected.flag' },
    read: (raw) => (raw === '0' || raw === '1' ? ({ [n.key]: raw === '1' } as Partial<S>) : null),
    control: folder && { folder, kind: 'toggle' },
  };
}

/** A value of a kind of its own written as text: how it reads (a value, or why not) and writes. */
export interface TextKind<V> {
  readonly expected: string;
  readonly expects: Expectation;
  readonly parse: (raw: string) => { readonly value: V } | { readonly problem: string | null };
  readonly text: (value: V) => string;
  readonly control: (folder: PanelFolder) => PanelControl;
}

export function textRow<S, K extends keyof S & string, V>(
  n: RowNames<S, K>,
  defaultValue: S[K] & V,
  folder: PanelFolder | null,
  k: TextKind<V>,
): ParameterRow<S> {
  return {
    ...named(n, defaultValue, (s) => k.text(s[n.key] as V)),
    expected: k.expected,
    expects: k.expects,
    read: (raw) => {
      const reading = k.parse(raw);
      return 'value' in reading ? ({ [n.key]: reading.value } as Partial<S>) : null;
    },
    problem: (raw) => {
      const reading = k.parse(raw);
      return 'problem' in reading ? reading.problem : null;
    },
    control: folder && k.control(folder),
  };
}

/** An illuminant: a name, or a number read as a daylight CCT in kelvin. */
export const illuminantRow = <S, K extends keyof S & string>(
  n: RowNames<S, K>,
  defaultValue: S[K] & IlluminantSpec,
  folder: PanelFolder | null,
) =>
  textRow<S, K, IlluminantSpec>(n, defaultValue, folder, {
    expected: ILLUMINANT_EXPECTED,
    expects: {
      key: 'expected.illuminant',
      values: { names: NAMED_ILLUMINANTS.join(', '), min: DAYLIGHT_CCT_DOMAIN_K.min, max: DAYLIGHT_CCT_DOMAIN_K.max },
    },
    parse: (raw) => {
      const value = parseIlluminant(raw);
      return value === null ? { problem: null } : { value };
    },
    text: illuminantText,
    control: (folder) => ({ folder, kind: 'illuminant' }),
  });

/** A film index (filmIndex.ts): a number, a material's name or `cauchy:A,B[,C]`, within its domain over the band. */
export const filmIndexRow = <S, K extends keyof S & string>(
  n: RowNames<S, K>,
  defaultValue: S[K] & FilmIndex,
  folder: PanelFolder | null,
) =>
  textRow<S, K, FilmIndex>(n, defaultValue, folder, {
    expected: FILM_INDEX_EXPECTED,
    expects: { key: 'expected.filmIndex', values: FILM_INDEX_VALUES },
    parse: (raw) => {
      const reading = readFilmIndex(raw);
      return 'index' in reading ? { value: reading.index } : reading;
    },
    text: filmIndexText,
    control: (folder) => ({ folder, kind: 'filmIndex' }),
  });

/** What a film index accepts, as a catalogue's values (expected.filmIndex, expected.medium). */
const FILM_INDEX_VALUES = {
  ...FILM_STACK_DOMAIN.nFilm,
  materials: FILM_MATERIALS.join(', '),
  from: DISPERSION_CHECK_NM.min,
  to: DISPERSION_CHECK_NM.max,
};

/**
 * A medium (medium.ts) for the film or the inside: what a film index accepts, a named medium
 * (NAMED_MEDIA), or `complex:n,k` (ñ = n + ik within COMPLEX_INDEX_DOMAIN: n > 0, k ≥ 0).
 */
export function mediumRow<S, K extends keyof S & string>(
  n: RowNames<S, K>,
  defaultValue: S[K] & Medium,
  folder: PanelFolder | null,
  role: Exclude<MediumRole, 'outside'>,
): ParameterRow<S> {
  const { n: nDomain, k: kDomain } = COMPLEX_INDEX_DOMAIN;
  const expects: Expectation = {
    key: 'expected.medium',
    values: {
      ...FILM_STACK_DOMAIN.nFilm,
      materials: FILM_MATERIALS.join(', '),
      names: NAMED_MEDIA.join(', '),
      nMin: nDomain.min,
      nMax: nDomain.max,
      kMin: kDomain.min,
      kMax: kDomain.max,
    },
  };
  return textRow<S, K, Medium>(n, defaultValue, folder, {
    expected: expectationText(expects, EN),
    expects,
    parse: (raw) => {
      const reading = readMedium(raw, role);
      return 'medium' in reading ? { value: reading.medium } : reading;
    },
    text: mediumText,
    control: (folder) => ({ folder, kind: 'medium', role }),
  });
}

/** The settings that every row's default makes. */
export const defaultsOf = <S>(rows: readonly ParameterRow<S>[]): S =>
  Object.fromEntries(rows.map((row) => [row.key, row.defaultValue])) as S;
