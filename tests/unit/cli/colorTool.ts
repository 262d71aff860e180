import { expect } from 'vitest';
import { runColorCommand } from '../../../src/cli/runColorCommand.ts';
import { ParameterError } from '../../../src/input/validate.ts';

/**
 * The colour tool in-process over a table of files (path → text): `run` gives its result, `ok`
 * expects a clean exit and gives the parsed JSON output.
 */
export function colorTool<Output>(files: Readonly<Record<string, string>>) {
  const read = (path: string): string => {
    const text = files[path];
    if (text === undefined) throw new ParameterError('--cases', `--cases: ${path} cannot be read`);
    return text;
  };
  const run = (...args: string[]) => runColorCommand(args, read);
  const ok = (...args: string[]): Output[] => {
    const r = run(...args);
    expect(r.stderr).toBe('');
    expect(r.exitCode).toBe(0);
    return JSON.parse(r.stdout) as Output[];
  };
  return { run, ok };
}
