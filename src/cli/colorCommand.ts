import { readCasesFile, writeFileAtomically } from './commandFiles.ts';
import { type CommandResult, runColorCommand } from './runColorCommand.ts';

/**
 * The colour command with its files: a `--cases` file read, a chart's `--out` file written
 * atomically (a failed write is exit status 2 with nothing on stdout). What is left to color.ts
 * is the process: printing and the exit status.
 */
export function colorCommand(argv: readonly string[]): Omit<CommandResult, 'file'> {
  const computed = runColorCommand(argv, readCasesFile);
  const writeError = computed.file ? writeFileAtomically(computed.file.path, computed.file.data) : null;
  return writeError === null ? computed : { stdout: '', stderr: `color: ${writeError}\n`, exitCode: 2 };
}
