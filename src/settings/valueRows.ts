import { type NumberDomain, expectedNumber, isInDomain, parseDecimal } from '../input/validate.ts';
import { AUTO, type PanelFolder, type ParameterRow, type RowNames, named } from './parameterRow.ts';

/* The rows of a plain value: a number (or `auto`), one of a list of names, or a switch. */

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
