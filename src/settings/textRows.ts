import {
  DAYLIGHT_CCT_DOMAIN_K,
  ILLUMINANT_EXPECTED,
  type IlluminantSpec,
  NAMED_ILLUMINANTS,
  illuminantText,
  listedNames,
  parseIlluminant,
} from '../physics/illuminants.ts';
import { LINE_DOMAIN_NM } from '../physics/lightLines.ts';
import { LIGHT_TINT_DOMAIN, LIGHT_TINT_EXPECTED, type LightTint, lightTintText, parseLightTint } from '../physics/lightTint.ts';
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
import {
  ENVIRONMENT_EXPECTED,
  ENVIRONMENT_EXPECTED_VALUES,
  type Environment,
  environmentText,
  readEnvironment,
} from '../environments/environments.ts';
import { EN } from '../i18n/en.ts';
import {
  type Expectation,
  type PanelControl,
  type PanelFolder,
  type ParameterRow,
  type RowNames,
  expectationText,
  named,
} from './parameterRow.ts';

/* The rows of a value of a kind of its own written as text: an illuminant, a tint, an environment, a film index, a medium (and a stack of films, layersRow.ts). */

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

/** An illuminant: a name, `line:NM`, or a number read as a daylight CCT in kelvin. */
export const illuminantRow = <S, K extends keyof S & string>(
  n: RowNames<S, K>,
  defaultValue: S[K] & IlluminantSpec,
  folder: PanelFolder | null,
) =>
  textRow<S, K, IlluminantSpec>(n, defaultValue, folder, {
    expected: ILLUMINANT_EXPECTED,
    expects: {
      key: 'expected.illuminant',
      values: {
        names: listedNames(NAMED_ILLUMINANTS),
        lineMin: LINE_DOMAIN_NM.min,
        lineMax: LINE_DOMAIN_NM.max,
        min: DAYLIGHT_CCT_DOMAIN_K.min,
        max: DAYLIGHT_CCT_DOMAIN_K.max,
      },
    },
    parse: (raw) => {
      const value = parseIlluminant(raw);
      return value === null ? { problem: null } : { value };
    },
    text: illuminantText,
    control: (folder) => ({ folder, kind: 'illuminant' }),
  });

/** A light's tint (lightTint.ts): `R,G,B`, each in its domain. */
export const lightTintRow = <S, K extends keyof S & string>(
  n: RowNames<S, K>,
  defaultValue: S[K] & LightTint,
  folder: PanelFolder | null,
) =>
  textRow<S, K, LightTint>(n, defaultValue, folder, {
    expected: LIGHT_TINT_EXPECTED,
    expects: { key: 'expected.lightTint', values: { min: LIGHT_TINT_DOMAIN.min, max: LIGHT_TINT_DOMAIN.max } },
    parse: (raw) => {
      const value = parseLightTint(raw);
      return value === null ? { problem: null } : { value };
    },
    text: lightTintText,
    control: (folder) => ({ folder, kind: 'tint' }),
  });

/** An environment (environments.ts): a name in the registry, or a uniform colour `color:R,G,B`. */
export const environmentRow = <S, K extends keyof S & string>(
  n: RowNames<S, K>,
  defaultValue: S[K] & Environment,
  folder: PanelFolder | null,
) =>
  textRow<S, K, Environment>(n, defaultValue, folder, {
    expected: ENVIRONMENT_EXPECTED,
    expects: { key: 'expected.environment', values: ENVIRONMENT_EXPECTED_VALUES },
    parse: (raw) => {
      const reading = readEnvironment(raw);
      return 'env' in reading ? { value: reading.env } : reading;
    },
    text: environmentText,
    control: (folder) => ({ folder, kind: 'environment' }),
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
