/**
 * `npm run --silent color -- [flags]`: the colour of thin films as JSON (or a CSV table) on
 * stdout; bad input gives exit status 2 and one line on stderr. See usage.ts or `--help`.
 * This file is the only one that touches the process; colorCommand.ts reads and writes the files.
 */
import { colorCommand } from './colorCommand.ts';

const result = colorCommand(process.argv.slice(2));
// A reader that stops early (`| head`) is not an error of ours.
process.stdout.on('error', (error: NodeJS.ErrnoException) => {
  if (error.code !== 'EPIPE') throw error;
});
process.stdout.write(result.stdout);
process.stderr.write(result.stderr);
process.exitCode = result.exitCode;
