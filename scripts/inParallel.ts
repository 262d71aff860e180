/**
 * `tsx scripts/inParallel.ts <npm script>...`: runs the named npm scripts at once, each one's
 * output printed whole when it ends (so that the outputs do not interleave), and exits with the
 * first non-zero status among them (0 if all pass). `npm run checks` runs the type check, ESLint
 * and Prettier this way, and `npm test` the checks, the unit tests and the packed library's test:
 * each alone leaves a core idle for much of its time, so together they fill both (docs/testing.md).
 */
import { spawn } from 'node:child_process';
import { fileURLToPath } from 'node:url';

export interface Finished {
  readonly command: readonly string[];
  readonly status: number;
  /** its stdout and stderr, in the order written */
  readonly output: string;
  readonly seconds: number;
}

/** Runs one command, its output kept; a command that cannot start or dies by a signal has status 1. */
function run(command: readonly string[]): Promise<Finished> {
  const started = performance.now();
  return new Promise((resolve) => {
    const child = spawn(command[0]!, command.slice(1), { stdio: ['ignore', 'pipe', 'pipe'] });
    let output = '';
    child.stdout.on('data', (chunk: Buffer) => (output += chunk.toString()));
    child.stderr.on('data', (chunk: Buffer) => (output += chunk.toString()));
    const finish = (status: number) => resolve({ command, status, output, seconds: (performance.now() - started) / 1000 });
    child.on('error', (error) => {
      output += `${error.message}\n`;
      finish(1);
    });
    child.on('close', (code) => finish(code ?? 1));
  });
}

/** Runs the commands at once; `report` is called with each as it ends. The first non-zero status, or 0. */
export async function runInParallel(commands: readonly (readonly string[])[], report: (f: Finished) => void): Promise<number> {
  const finished = await Promise.all(commands.map((c) => run(c).then((f) => (report(f), f))));
  return finished.find((f) => f.status !== 0)?.status ?? 0;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const names = process.argv.slice(2);
  if (names.length === 0) {
    console.error('usage: tsx scripts/inParallel.ts <npm script>...');
    process.exit(2);
  }
  const status = await runInParallel(
    names.map((name) => ['npm', 'run', '--silent', name]),
    (f) => {
      const name = f.command.at(-1)!;
      process.stdout.write(`${f.output}${name}: ${f.status === 0 ? 'passed' : `failed (exit ${f.status})`} in ${f.seconds.toFixed(0)} s\n`);
    },
  );
  process.exit(status);
}
