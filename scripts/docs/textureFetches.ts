/**
 * The texture fetches a fragment shader makes per fragment, counted from its GLSL text: the
 * `texture(` and `texelFetch(` calls that `main` reaches, through the functions it calls and the
 * loops it runs. An upper bound of what a fragment executes: every call in a function's text
 * counts, both arms of a branch and the rest of a body after an early `return` or `continue`.
 * A `for` loop multiplies its body's fetches by its count of passes; its bounds must be integer
 * expressions of numbers, the shader's defines, the values given (a uniform's value in the draw)
 * and the function's own `int` constants, else the count is an error, as it is for `while` and
 * `do` loops and for overloaded functions.
 */
import { expressionValue, preprocess } from '../harness/glslPreprocessor.ts';

export interface FetchCountOptions {
  /** Values of names a loop bound may hold that are not defines: the uniforms the draw sets. */
  readonly values?: Readonly<Record<string, number>>;
  /**
   * Loops (`function:variable`, e.g. `tfcMarkedCell:i`) whose body runs in one pass at most of
   * the loops around them in their function, so counted once per call of that function rather than
   * once per pass of the loops around them.
   */
  readonly oncePerCall?: ReadonlySet<string>;
}

const FETCH = new Set(['texture', 'texelFetch']);

/** Fetches of a stretch of code: those the loops around it multiply, and those made once per call of its function. */
interface Fetches {
  readonly repeated: number;
  readonly once: number;
}

/** The index just past the bracket that closes the one at `open`. */
function closing(text: string, open: number): number {
  const [o, c] = text[open] === '(' ? ['(', ')'] : ['{', '}'];
  let depth = 0;
  for (let k = open; k < text.length; k++) {
    if (text[k] === o) depth++;
    else if (text[k] === c && --depth === 0) return k + 1;
  }
  throw new Error(`unbalanced ${o} at ${text.slice(open, open + 40)}`);
}

/** The functions defined in `text`, by name: their bodies (between the braces). */
function functionBodies(text: string): Map<string, string> {
  const bodies = new Map<string, string>();
  let start = 0;
  for (let k = 0; k < text.length; k++) {
    if (text[k] === ';' || text[k] === '}') start = k + 1;
    if (text[k] !== '{') continue;
    const end = closing(text, k);
    const header = /(\w+)\s*\([^()]*\)\s*$/.exec(text.slice(start, k));
    if (header) {
      if (bodies.has(header[1]!)) throw new Error(`${header[1]} is overloaded: the count cannot tell its definitions apart`);
      bodies.set(header[1]!, text.slice(k + 1, end - 1));
    }
    k = end - 1;
    start = end;
  }
  return bodies;
}

/** The end of a loop's body starting at `from`: a block, or one statement (a nested loop's included). */
function bodyEnd(text: string, from: number): number {
  let depth = 0;
  for (let k = from; k < text.length; k++) {
    const ch = text[k]!;
    if (ch === '(') depth++;
    else if (ch === ')') depth--;
    else if (depth === 0 && ch === '{') {
      const end = closing(text, k);
      if (/^\s*else\b/.test(text.slice(end))) throw new Error(`an if–else as a loop's body without braces: ${text.slice(from, end)}`);
      return end;
    } else if (depth === 0 && ch === ';') {
      if (/^\s*else\b/.test(text.slice(k + 1))) throw new Error(`an if–else as a loop's body without braces: ${text.slice(from, k + 1)}`);
      return k + 1;
    }
  }
  throw new Error(`a loop without a body: ${text.slice(from, from + 40)}`);
}

/** The passes of `for (header)`: `int k = a; k < b; k++` (or `<=`, `++k`, `k += 1`). */
function loopPasses(header: string, valueOf: (name: string) => number): { variable: string; passes: number } {
  const [init = '', test = '', step = ''] = header.split(';');
  const i = /^\s*(?:int\s+)?(\w+)\s*=\s*(.+?)\s*$/.exec(init);
  const t = /^\s*(\w+)\s*(<=|<)\s*(.+?)\s*$/.exec(test);
  const s = /^\s*(?:\+\+\s*(\w+)|(\w+)\s*\+\+|(\w+)\s*\+=\s*1)\s*$/.exec(step);
  const variable = i?.[1];
  if (!i || !t || !s || t[1] !== variable || (s[1] ?? s[2] ?? s[3]) !== variable) {
    throw new Error(`a loop the count cannot bound: for (${header})`);
  }
  const passes = expressionValue(t[3]!, valueOf) - expressionValue(i[2]!, valueOf) + (t[2] === '<=' ? 1 : 0);
  return { variable: variable!, passes: Math.max(0, passes) };
}

/** Whether `name` is assigned in `body` after its declaration (`=`, `+=`, …, `++`, `--`). */
const reassigned = (body: string, name: string): boolean =>
  new RegExp(`(?<!\\bint\\s+)\\b${name}\\s*(?:[-+*/%]?=(?!=)|\\+\\+|--)|(?:\\+\\+|--)\\s*${name}\\b`).test(body);

/** The `int` constants of a function's body (declared with a value the names give, never assigned again). */
function intConstants(body: string, valueOf: (name: string) => number): Map<string, number> {
  const constants = new Map<string, number>();
  for (const m of body.matchAll(/\bint\s+(\w+)\s*=\s*([^;,]+);/g)) {
    if (reassigned(body, m[1]!)) continue;
    let value: number;
    try {
      value = expressionValue(m[2]!, (name) => constants.get(name) ?? valueOf(name));
    } catch {
      continue;
    }
    if (constants.has(m[1]!) && constants.get(m[1]!) !== value) throw new Error(`int ${m[1]} is declared twice with different values`);
    constants.set(m[1]!, value);
  }
  return constants;
}

/** The comments of `glsl` removed, after the preprocessor with these defines; and the defines then in force. */
function code(glsl: string, defines: Readonly<Record<string, unknown>>): { text: string; defines: ReadonlyMap<string, string> } {
  const { text, defines: known } = preprocess(glsl, defines);
  return { text: text.replace(/\/\*[\s\S]*?\*\//g, ' ').replace(/\/\/.*$/gm, ''), defines: known };
}

/** The loops of `glsl` with these defines, as `function:variable` (the keys of `oncePerCall`). */
export const loopNames = (glsl: string, defines: Readonly<Record<string, unknown>>): string[] =>
  [...functionBodies(code(glsl, defines).text)].flatMap(([fn, body]) =>
    [...body.matchAll(/\bfor\s*\(\s*(?:int\s+)?(\w+)/g)].map((m) => `${fn}:${m[1]}`),
  );

/** The fetches per fragment of a fragment shader's `main` in `glsl` with these defines (see the file's comment). */
export function textureFetchesPerFragment(
  glsl: string,
  defines: Readonly<Record<string, unknown>>,
  options: FetchCountOptions = {},
): number {
  const { text, defines: known } = code(glsl, defines);
  if (/\bdo\s*\{/.test(text)) throw new Error('a do loop cannot be counted');
  const bodies = functionBodies(text);
  const defined = (name: string, depth = 0): number => {
    const value = known.get(name);
    if (value !== undefined && value !== '' && depth < 8) return expressionValue(value, (inner) => defined(inner, depth + 1));
    const given = options.values?.[name];
    if (given !== undefined) return given;
    throw new Error(`a loop bound names ${name}, which is neither an integer define nor a value given`);
  };
  const totals = new Map<string, number>();

  const total = (name: string, calling: readonly string[]): number => {
    if (calling.includes(name)) throw new Error(`recursion: ${[...calling, name].join(' → ')}`);
    const cached = totals.get(name);
    if (cached !== undefined) return cached;
    const body = bodies.get(name)!;
    const constants = intConstants(body, defined);
    const valueOf = (n: string): number => constants.get(n) ?? defined(n);
    const fetches = count(body, name, valueOf, [...calling, name]);
    totals.set(name, fetches.repeated + fetches.once);
    return fetches.repeated + fetches.once;
  };

  function count(part: string, fn: string, valueOf: (name: string) => number, calling: readonly string[]): Fetches {
    let repeated = 0;
    let once = 0;
    const call = /\b(\w+)\s*\(/g;
    for (let m = call.exec(part); m; m = call.exec(part)) {
      const name = m[1]!;
      if (name === 'while') throw new Error(`${fn}: a while loop cannot be counted`);
      if (FETCH.has(name)) repeated++;
      else if (bodies.has(name)) repeated += total(name, calling);
      else if (name === 'for') {
        const open = m.index + m[0].length - 1;
        const headerEnd = closing(part, open);
        const end = bodyEnd(part, headerEnd);
        const { variable, passes } = loopPasses(part.slice(open + 1, headerEnd - 1), valueOf);
        const inner = count(part.slice(headerEnd, end), fn, valueOf, calling);
        if (options.oncePerCall?.has(`${fn}:${variable}`)) once += passes * inner.repeated + inner.once;
        else {
          repeated += passes * inner.repeated;
          once += inner.once;
        }
        call.lastIndex = end;
      }
    }
    return { repeated, once };
  }

  if (!bodies.has('main')) throw new Error('the shader has no main');
  return total('main', []);
}
