/**
 * The benchmark's command line, read before anything is started:
 * `[--smoke] [--port <port>] [<text>[|<text>…]]`.
 * A text picks the rows whose name holds it (the floor always runs, as the ratios' base); a text
 * that picks no row, an unknown flag or a second list is an error that names it and lists what is
 * allowed (exit status 2).
 */

export const BENCH_FLAGS: Readonly<Record<string, string>> = {
  '--smoke':
    'every figure and each kind of row once (the costlier variants of a row left out unless named), small and fast, to check that each runs and gives finite figures (results in .scratch/)',
  '--port': "<port>: the Vite dev server's port, and the next one the built demo's preview (else the plan's own)",
  '--help': 'this text',
};

export type BenchArgs =
  | { readonly help: true }
  | {
      readonly help: false;
      readonly smoke: boolean;
      /** the texts that pick rows, or null for every row */
      readonly only: readonly string[] | null;
      /** the dev server's port (the preview's the next), or null for the plan's */
      readonly port: number | null;
    };

/** The ports a `--port` may name: unprivileged, with room for the preview's after it. */
export const PORT_RANGE = { min: 1024, max: 65534 } as const;

export const benchUsage = (rowNames: readonly string[]): string =>
  [
    'usage: npm run bench -- [--smoke] [--port <port>] [<text>[|<text>…]]',
    '',
    'flags:',
    ...Object.entries(BENCH_FLAGS).map(([flag, what]) => `  ${flag}  ${what}`),
    '',
    'rows (a text picks those whose name holds it):',
    ...rowNames.map((name) => `  ${name}`),
  ].join('\n');

/** `argv`: the arguments after the script; `rowNames`: every row that a text may pick. */
export function parseBenchArgs(argv: readonly string[], rowNames: readonly string[]): { args: BenchArgs } | { error: string } {
  let smoke = false;
  let only: string[] | null = null;
  let port: number | null = null;
  for (let i = 0; i < argv.length; i++) {
    const arg = argv[i]!;
    if (arg === '--help' || arg === '-h') return { args: { help: true } };
    if (arg === '--smoke') smoke = true;
    else if (arg === '--port' || arg.startsWith('--port=')) {
      const value = arg === '--port' ? argv[++i] : arg.slice('--port='.length);
      port = Number(value);
      if (value === undefined || !/^\d+$/.test(value) || port < PORT_RANGE.min || port > PORT_RANGE.max)
        return { error: `--port must be an integer from ${PORT_RANGE.min} to ${PORT_RANGE.max} (got ${JSON.stringify(value ?? '')})` };
    } else if (arg.startsWith('-')) return { error: `unknown flag ${JSON.stringify(arg)}\n\n${benchUsage(rowNames)}` };
    else if (only) return { error: `one list of rows at most (got ${JSON.stringify(only.join('|'))} and ${JSON.stringify(arg)})` };
    else {
      only = arg.split('|');
      if (only.includes('')) return { error: `an empty row text in ${JSON.stringify(arg)}\n\n${benchUsage(rowNames)}` };
      const unknown = only.filter((text) => !rowNames.some((name) => name.includes(text)));
      if (unknown.length > 0)
        return { error: `no row named ${unknown.map((t) => JSON.stringify(t)).join(', ')}\n\n${benchUsage(rowNames)}` };
    }
  }
  return { args: { help: false, smoke, only, port } };
}
