/**
 * The command lines' files: reading a `--cases` file and writing an `--out` file atomically. With
 * the commands' entry points (color.ts, scripts/render.ts) the only code that touches the file system.
 */
import { readFileSync, renameSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { basename, dirname, join } from 'node:path';
import { ParameterError } from '../input/validate.ts';
import { describePath } from './inputErrors.ts';

/** A cases file larger than this is not a list of films. */
export const MAX_CASES_FILE_BYTES = 64 * 1024 * 1024;

const errorCode = (error: unknown): string => (error as NodeJS.ErrnoException).code ?? 'error';

/** The text of a `--cases` file, or a ParameterError naming --cases and saying why it cannot be read. */
export function readCasesFile(path: string): string {
  const fail = (why: string): never => {
    const expected = `a readable JSON file of at most ${MAX_CASES_FILE_BYTES} bytes`;
    throw new ParameterError('--cases', `--cases: ${describePath(path)} ${why}; expected ${expected}`);
  };
  try {
    if (statSync(path).size > MAX_CASES_FILE_BYTES) fail('is too large');
    return readFileSync(path, 'utf8');
  } catch (error) {
    if (error instanceof ParameterError) throw error;
    return fail(`cannot be read (${errorCode(error)})`);
  }
}

/** Why `path` cannot be written, naming `field` (its folder is missing or not a folder), or null. */
export function outFolderProblem(field: string, path: string): string | null {
  const folder = dirname(path);
  try {
    if (statSync(folder).isDirectory()) return null;
  } catch {
    // missing: said below
  }
  return `${field}: ${describePath(path)} cannot be written (no folder ${describePath(folder)}); expected a path in a writable folder`;
}

/**
 * Writes `data` to `path` atomically: to a temporary name in the same folder, then renamed over
 * it, so a failed write never leaves half a file. An error is a one-line message naming --out.
 */
export function writeFileAtomically(path: string, data: Buffer | string): string | null {
  const temporary = join(dirname(path), `.${basename(path)}.${process.pid}.tmp`);
  try {
    writeFileSync(temporary, data);
    renameSync(temporary, path);
    return null;
  } catch (error) {
    rmSync(temporary, { force: true });
    return `--out: ${describePath(path)} cannot be written (${errorCode(error)}); expected a path in a writable folder`;
  }
}
