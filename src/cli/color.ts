/**
 * `npm run --silent color -- [flags]`: the colour of thin films as JSON (or a CSV table) on
 * stdout; bad input gives exit status 2 and one line on stderr. See usage.ts or `--help`.
 * This file is the only one that touches the process and the file system.
 */
import { readFileSync, renameSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { basename, dirname, join } from 'node:path';
import { ParameterError } from '../physics/validate.ts';
import { describePath } from './inputErrors.ts';
import { runColorCommand } from './runColorCommand.ts';

/** A cases file larger than this is not a list of films. */
export const MAX_CASES_FILE_BYTES = 64 * 1024 * 1024;

function readCasesFile(path: string): string {
  const fail = (why: string): never => {
    const expected = `a readable JSON file of at most ${MAX_CASES_FILE_BYTES} bytes`;
    throw new ParameterError('--cases', `--cases: ${describePath(path)} ${why}; expected ${expected}`);
  };
  try {
    if (statSync(path).size > MAX_CASES_FILE_BYTES) fail('is too large');
    return readFileSync(path, 'utf8');
  } catch (error) {
    if (error instanceof ParameterError) throw error;
    return fail(`cannot be read (${(error as NodeJS.ErrnoException).code ?? 'error'})`);
  }
}

/**
 * Writes `data` to `path` atomically: to a temporary name in the same folder, then renamed over
 * it, so a failed write never leaves half a file. An error is a one-line message naming --out.
 */
function writeFileAtomically(path: string, data: Buffer | string): string | null {
  const temporary = join(dirname(path), `.${basename(path)}.${process.pid}.tmp`);
  try {
    writeFileSync(temporary, data);
    renameSync(temporary, path);
    return null;
  } catch (error) {
    rmSync(temporary, { force: true });
    return `color: --out: ${describePath(path)} cannot be written (${(error as NodeJS.ErrnoException).code ?? 'error'}); expected a path in a writable folder\n`;
  }
}

const computed = runColorCommand(process.argv.slice(2), readCasesFile);
const writeError = computed.file ? writeFileAtomically(computed.file.path, computed.file.data) : null;
const result = writeError === null ? computed : { stdout: '', stderr: writeError, exitCode: 2 };
// A reader that stops early (`| head`) is not an error of ours.
process.stdout.on('error', (error: NodeJS.ErrnoException) => {
  if (error.code !== 'EPIPE') throw error;
});
process.stdout.write(result.stdout);
process.stderr.write(result.stderr);
process.exitCode = result.exitCode;
