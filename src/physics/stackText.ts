import { FIELD_THICKNESS, type FilmLayer, LAYERS_DOMAIN } from './stackFilms.ts';
import { mediumText, readMedium } from './medium.ts';
import { ParameterError, expectedNumber, isInDomain, parseDecimal, quoted } from '../input/validate.ts';

/**
 * A stack of films as URL, attribute and command line write it (docs/physics.md#stacks-of-films):
 * entries `INDEX:NM` from the outside in, separated by `/`. INDEX is anything a film takes as
 * text (`1.46`, `water`, `cauchy:1.45,6000`, `TiO2`, `complex:0.2,3.4`: an entry is split at its
 * last `:`); NM is the film's thickness in nm within LAYERS_DOMAIN.thicknessNm, or FIELD_THICKNESS
 * (`d`) for the thickness field's value. A group `(…)*N` repeats its entries N times (N in LAYERS_DOMAIN.repeat);
 * groups may nest. Whitespace around every token is ignored. At most LAYERS_DOMAIN.count.max films
 * after every group is expanded, and at least one.
 *
 *     (2.35:56.6/1.46:91.1)*8          a quarter-wave mirror at 530 nm: 16 films
 *     1.38:d/(TiO2:50/SiO2:90)*3       a field-thick film over three pairs
 */

const { count: COUNT, repeat: REPEAT, thicknessNm: THICKNESS } = LAYERS_DOMAIN;

/** What the text of a stack is, as every refusal states it (the option `layers`' own words). */
export const LAYERS_EXPECTED =
  `INDEX:NM entries separated by /, outside in (INDEX as nFilm takes it; NM in [${THICKNESS.min}, ${THICKNESS.max}] or ${FIELD_THICKNESS}); ` +
  `(…)*N repeats a group, N in [${REPEAT.min}, ${REPEAT.max}]; at most ${COUNT.max} layers`;

/** The characters that structure the text of a stack; no medium's text holds one. */
const STRUCTURE = /([()/*])/;

/** A group under construction: its films so far, and whether an entry or a group must come next. */
interface Frame {
  readonly films: FilmLayer[];
  expectsItem: boolean;
}

/** The checked films of a text, or what rule it breaks. */
export function readLayers(text: string): { readonly films: readonly FilmLayer[] } | { readonly problem: string } {
  try {
    return { films: parseLayerTokens(text.split(STRUCTURE)) };
  } catch (error) {
    if (error instanceof LayersProblem) return { problem: error.message };
    throw error;
  }
}

/** The films of a text, or a ParameterError naming `name` (the option: `layers`, `--layers`) and the rule broken. */
export function parseLayers(name: string, text: string): readonly FilmLayer[] {
  const reading = readLayers(text);
  if ('films' in reading) return reading.films;
  throw new ParameterError(name, `${name}: ${quoted(text)} is not allowed (${reading.problem}); expected ${LAYERS_EXPECTED}`);
}

class LayersProblem extends Error {}
const refuse = (problem: string): never => {
  throw new LayersProblem(problem);
};

/** The tokens of `text.split(STRUCTURE)`: text between the structure characters, and each of those. */
function parseLayerTokens(tokens: readonly string[]): FilmLayer[] {
  const frames: Frame[] = [{ films: [], expectsItem: true }];
  const top = () => frames[frames.length - 1]!;
  const add = (films: readonly FilmLayer[]) => {
    const frame = top();
    if (!frame.expectsItem) refuse('entries must be separated by /');
    if (frame.films.length + films.length > COUNT.max) refuse(`more than ${COUNT.max} layers after repetition`);
    frame.films.push(...films);
    frame.expectsItem = false;
  };
  for (let i = 0; i < tokens.length; i++) {
    const token = tokens[i]!;
    if (token === '(') {
      if (!top().expectsItem) refuse('entries must be separated by /');
      frames.push({ films: [], expectsItem: true });
    } else if (token === ')') {
      if (frames.length === 1) refuse('unbalanced parentheses: a ")" without its "("');
      const group = frames.pop()!;
      if (group.expectsItem) refuse('an empty entry');
      // The tokens after ")" are "", "*", then N (and whatever text follows it up to the next structure character).
      if (tokens[i + 1]?.trim() !== '' || tokens[i + 2] !== '*') refuse('a group (…) must be followed by *N');
      const times = repeatCount(tokens[i + 3] ?? '');
      i += 3;
      add(Array.from({ length: times }, () => group.films).flat());
    } else if (token === '/') {
      if (top().expectsItem) refuse('an empty entry');
      top().expectsItem = true;
    } else if (token === '*') {
      refuse('*N may only follow a group in parentheses');
    } else if (token.trim() !== '') {
      add([layerOf(token.trim())]);
    }
  }
  if (frames.length > 1) refuse('unbalanced parentheses: a "(" without its ")"');
  if (top().expectsItem) refuse(top().films.length === 0 ? 'no layers' : 'an empty entry');
  return top().films;
}

/** The N of `*N`. */
function repeatCount(text: string): number {
  const n = parseDecimal(text.trim());
  if (!Number.isInteger(n) || !isInDomain(n, REPEAT))
    refuse(`*N with N ${quoted(text.trim())}, not an integer in [${REPEAT.min}, ${REPEAT.max}]`);
  return n;
}

/** One entry `INDEX:THICKNESS`. */
function layerOf(entry: string): FilmLayer {
  const colon = entry.lastIndexOf(':');
  if (colon < 0) return refuse(`the entry ${quoted(entry)} has no :NM`);
  const indexText = entry.slice(0, colon).trim();
  const thicknessText = entry.slice(colon + 1).trim();
  const reading = readMedium(indexText, 'film');
  if (!('medium' in reading)) {
    const why = reading.problem ?? 'not a medium a film takes';
    return refuse(`the index ${quoted(indexText)}: ${why}`);
  }
  if (thicknessText === FIELD_THICKNESS) return { n: reading.medium, thicknessNm: FIELD_THICKNESS };
  const thicknessNm = parseDecimal(thicknessText);
  if (!isInDomain(thicknessNm, THICKNESS)) {
    refuse(`the thickness ${quoted(thicknessText)} is not ${expectedNumber(THICKNESS)} or ${FIELD_THICKNESS}`);
  }
  // -0 reads as 0: the text a film prints back is the same.
  return { n: reading.medium, thicknessNm: thicknessNm + 0 };
}

/** One film's entry. */
const entryText = (film: FilmLayer): string => `${mediumText(film.n)}:${film.thicknessNm}`;

/**
 * The text `readLayers` reads back into these films: their entries, a run of a repeated block
 * written `(…)*N` where that is shorter. An empty list is the empty text (no stack: the single film).
 */
export function layersText(films: readonly FilmLayer[]): string {
  const entries = films.map(entryText);
  const parts: string[] = [];
  let i = 0;
  while (i < entries.length) {
    const run = longestSavingRun(entries, i);
    if (run) {
      parts.push(`(${entries.slice(i, i + run.period).join('/')})*${run.times}`);
      i += run.period * run.times;
    } else parts.push(entries[i++]!);
  }
  return parts.join('/');
}

/** The block starting at `start` whose repetition as `(…)*N` saves the most characters, if any does. */
function longestSavingRun(entries: readonly string[], start: number): { period: number; times: number } | null {
  let best: { period: number; times: number; saved: number } | null = null;
  for (let period = 1; start + 2 * period <= entries.length; period++) {
    const block = entries.slice(start, start + period);
    let times = 1;
    while (times < REPEAT.max && block.every((e, j) => entries[start + times * period + j] === e)) times++;
    if (times < 2) continue;
    const blockChars = block.join('/').length;
    const saved = times * (blockChars + 1) - 1 - (blockChars + 3 + String(times).length);
    if (saved > 0 && (!best || saved > best.saved)) best = { period, times, saved };
  }
  return best;
}
