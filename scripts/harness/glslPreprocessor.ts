/**
 * A small GLSL preprocessor: the text a compiler sees of a shader with given defines (the branches
 * of `#if`/`#ifdef`/`#ifndef`/`#elif`/`#else` taken, `#define`s in them collected), and the
 * integer expressions of its conditions and of loop bounds. Enough for the shaders of shaders/:
 * no function-like macros and no macro substitution in the text.
 */

/** Binary operators of an integer expression, loosest first. */
const LEVELS: readonly (readonly string[])[] = [['||'], ['&&'], ['==', '!='], ['<=', '>=', '<', '>'], ['+', '-'], ['*', '/', '%']];
const APPLY: Readonly<Record<string, (a: number, b: number) => number>> = {
  '||': (a, b) => +(a !== 0 || b !== 0),
  '&&': (a, b) => +(a !== 0 && b !== 0),
  '==': (a, b) => +(a === b),
  '!=': (a, b) => +(a !== b),
  '<=': (a, b) => +(a <= b),
  '>=': (a, b) => +(a >= b),
  '<': (a, b) => +(a < b),
  '>': (a, b) => +(a > b),
  '+': (a, b) => a + b,
  '-': (a, b) => a - b,
  '*': (a, b) => a * b,
  '/': (a, b) => Math.trunc(a / b),
  '%': (a, b) => a % b,
};

/**
 * The value of an integer expression of numbers, names, `!`, unary `-`, parentheses and the
 * operators above (C's precedence), each name's value given by `valueOf`; an error if the text is
 * not such an expression.
 */
export function expressionValue(expression: string, valueOf: (name: string) => number): number {
  const tokens = expression.match(/\d+(?:\.\d+)?|[A-Za-z_]\w*|\|\||&&|[=!<>]=|[()!<>+\-*/%]|\S/g) ?? [];
  let at = 0;
  const unary = (): number => {
    const t = tokens[at++];
    if (t === '!') return +(unary() === 0);
    if (t === '-') return -unary();
    if (t === '(') {
      const v = binary(0);
      if (tokens[at++] !== ')') throw new Error(`unbalanced expression: ${expression}`);
      return v;
    }
    if (t === undefined) throw new Error(`incomplete expression: ${expression}`);
    if (/^\d/.test(t)) return Number(t);
    if (/^[A-Za-z_]/.test(t)) return valueOf(t);
    throw new Error(`not an integer expression: ${expression}`);
  };
  const binary = (level: number): number => {
    if (level === LEVELS.length) return unary();
    let v = binary(level + 1);
    while (at < tokens.length && LEVELS[level]!.includes(tokens[at]!)) {
      const op = tokens[at++]!;
      v = APPLY[op]!(v, binary(level + 1));
    }
    return v;
  };
  const value = binary(0);
  if (at !== tokens.length) throw new Error(`not an integer expression: ${expression}`);
  return value;
}

/** The value of a `#if` condition with these defines (an undefined name is 0, as the preprocessor takes it). */
function condition(expression: string, defines: ReadonlyMap<string, string>): boolean {
  const valueOf = (name: string, depth = 0): number => {
    const value = defines.get(name);
    if (value === undefined) return 0;
    if (value === '') return 1;
    return /^[A-Za-z_]\w*$/.test(value) && depth < 8 ? valueOf(value, depth + 1) : Number(value);
  };
  const text = expression
    .replace(/\/\/.*$/, '')
    .replace(/defined\s*\(\s*(\w+)\s*\)|defined\s+(\w+)/g, (_, a?: string, b?: string) => (defines.has((a ?? b)!) ? '1' : '0'));
  return expressionValue(text, (name) => valueOf(name)) !== 0;
}

/** A shader as a compiler sees it: its text, and every define in force at its end (given or `#define`d in a branch taken). */
export interface Preprocessed {
  readonly text: string;
  readonly defines: ReadonlyMap<string, string>;
}

/**
 * `glsl` with these defines: the lines of the branches of `#if`, `#ifdef`, `#ifndef`, `#elif` and
 * `#else` taken, and the defines, with the `#define`s in them (include guards, a file's constants).
 */
export function preprocess(glsl: string, defines: Readonly<Record<string, unknown>>): Preprocessed {
  const known = new Map(Object.entries(defines).map(([k, v]) => [k, String(v)]));
  const kept: string[] = [];
  /** Per open `#if`: whether the enclosing text is taken, whether this branch is, whether one was. */
  const stack: { outer: boolean; taking: boolean; taken: boolean }[] = [];
  const taking = () => stack.every((s) => s.taking);
  for (const line of glsl.split('\n')) {
    const d = /^\s*#\s*(\w+)\s*(.*)$/.exec(line);
    const [directive, rest] = d ? [d[1]!, d[2]!.trim()] : ['', ''];
    if (directive === 'if' || directive === 'ifdef' || directive === 'ifndef') {
      const outer = taking();
      const value =
        directive === 'if'
          ? condition(rest, known)
          : directive === 'ifdef'
            ? known.has(rest.split(/\s/)[0]!)
            : !known.has(rest.split(/\s/)[0]!);
      stack.push({ outer, taking: outer && value, taken: value });
    } else if (directive === 'elif' || directive === 'else') {
      const top = stack[stack.length - 1]!;
      const value = !top.taken && (directive === 'else' || condition(rest, known));
      top.taking = top.outer && value;
      top.taken ||= value;
    } else if (directive === 'endif') stack.pop();
    else if (!taking()) continue;
    else if (directive === 'define') {
      const [, name, value] = /^(\w+)\s*(.*)$/.exec(rest)!;
      known.set(name!, value!.replace(/\/\/.*$/, '').trim());
    } else kept.push(line);
  }
  return { text: kept.join('\n'), defines: known };
}

/** The text a GLSL compiler sees of `glsl` with these defines (preprocess's text). */
export const preprocessed = (glsl: string, defines: Readonly<Record<string, unknown>>): string => preprocess(glsl, defines).text;
