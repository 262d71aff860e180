import type { MediumRole } from '../physics/medium.ts';
import { type Catalogue, EN, type MessageKey } from '../i18n/en.ts';
import { message } from '../i18n/messages.ts';

/** Where a parameter sits in the control panel, and how it is shown there. */
export type PanelControl =
  | { readonly folder: PanelFolder; readonly kind: 'slider'; readonly min: number; readonly max: number; readonly step: number }
  | { readonly folder: PanelFolder; readonly kind: 'choice'; readonly choices: readonly string[] }
  | { readonly folder: PanelFolder; readonly kind: 'toggle' }
  /** A named illuminant or a daylight CCT: a list of names plus a CCT slider. */
  | { readonly folder: PanelFolder; readonly kind: 'illuminant' }
  /** A tint (lightTint.ts): a slider for each of R, G and B over the tint's domain. */
  | { readonly folder: PanelFolder; readonly kind: 'tint' }
  /** An environment: a list of the registry's names plus a uniform colour, whose R, G and B sliders show while it is chosen. */
  | { readonly folder: PanelFolder; readonly kind: 'environment' }
  /** A film index: a constant (slider), a named material, or a Cauchy film (text A,B[,C]). */
  | { readonly folder: PanelFolder; readonly kind: 'filmIndex' }
  /** A medium (medium.ts): a film index's controls, a named medium (a metal, an oxide) or a complex constant (text n,k). */
  | { readonly folder: PanelFolder; readonly kind: 'medium'; readonly role: Exclude<MediumRole, 'outside'> }
  /** A stack of films as text (stackText.ts); while it holds films, the film's own index is not used. */
  | { readonly folder: PanelFolder; readonly kind: 'stack' }
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
  /** Its name in the URL query (and in a render command's cases file). */
  readonly url: string;
  /** Its `<thin-film-bubble>` attribute (HTML attribute names are lower case). */
  readonly attribute: string;
  /** Its flag in every command-line tool that takes it (`--flag`): the URL name in kebab case. */
  readonly flag: string;
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

/** What every builder takes: the settings field and its URL name (its other names and its label are derived). */
export interface RowNames<S, K extends keyof S & string> {
  readonly key: K;
  readonly url: string;
}

/** A URL name (`thicknessRange`) in kebab case (`thickness-range`): its command-line flag. */
export const flagOf = (url: string): string => url.replace(/[A-Z]/g, (c) => `-${c.toLowerCase()}`);

/** The fields common to every row. */
export const named = <S, K extends keyof S & string>(n: RowNames<S, K>, defaultValue: S[K], write: (s: S) => string) => ({
  key: n.key,
  url: n.url,
  attribute: n.url.toLowerCase(),
  flag: flagOf(n.url),
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

/** A knob a user may leave to the page (the frame governor, docs/governor.md) or give a value honoured exactly. */
export const AUTO = 'auto';
export type Auto<T> = T | typeof AUTO;

/** The settings that every row's default makes. */
export const defaultsOf = <S>(rows: readonly ParameterRow<S>[]): S =>
  Object.fromEntries(rows.map((row) => [row.key, row.defaultValue])) as S;
