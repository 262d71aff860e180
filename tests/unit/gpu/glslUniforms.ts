/**
 * The uniforms a GLSL text declares, read from the text itself (the independent side of a test
 * against the TypeScript that sets them: a uniform declared and never set reads 0 on the GPU).
 */

/** The names of the uniforms declared anywhere in `glsl`, `uniform <type> <name>` (an array's name without its size). */
export const declaredUniforms = (glsl: string): string[] => [
  ...new Set([...glsl.matchAll(/^[ \t]*uniform\s+(?:(?:lowp|mediump|highp)\s+)?\w+\s+(\w+)/gm)].map((m) => m[1]!)),
];

/** Binary operators of a preprocessor condition, loosest first. */
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
  const tokens = text.match(/\d+(?:\.\d+)?|[A-Za-z_]\w*|\|\||&&|[=!<>]=|[()!<>+\-*/%]/g) ?? [];
  let at = 0;
  const unary = (): number => {
    const t = tokens[at++];
    if (t === '!') return +(unary() === 0);
    if (t === '-') return -unary();
    if (t === '(') {
      const v = binary(0);
      if (tokens[at++] !== ')') throw new Error(`unbalanced condition: ${expression}`);
      return v;
    }
    if (t === undefined) throw new Error(`incomplete condition: ${expression}`);
    return /^\d/.test(t) ? Number(t) : valueOf(t);
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
  if (at !== tokens.length) throw new Error(`not a preprocessor condition: ${expression}`);
  return value !== 0;
}

/**
 * The text a GLSL compiler sees of `glsl` with these defines: the lines of the branches of
 * `#if`, `#ifdef`, `#ifndef`, `#elif` and `#else` taken, `#define`s in them included (include guards).
 */
export function preprocessed(glsl: string, defines: Readonly<Record<string, unknown>>): string {
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
      known.set(name!, value!.trim());
    } else kept.push(line);
  }
  return kept.join('\n');
}
