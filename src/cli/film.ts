/**
 * `npm run --silent film -- [options] --seconds T --json`: the flowing soap film of a bubble,
 * simulated for T seconds, as one JSON object on stdout; bad input gives exit status 2 and one line
 * on stderr; progress on stderr while it runs (see progress.ts). See runFilmCommand.ts or `--help`.
 * This file is the only one that touches the process.
 */
import { runFilmCommand } from './runFilmCommand.ts';

const result = runFilmCommand(process.argv.slice(2), process.stderr);
process.stdout.on('error', (error: NodeJS.ErrnoException) => {
  if (error.code !== 'EPIPE') throw error;
});
process.stdout.write(result.stdout);
process.stderr.write(result.stderr);
process.exitCode = result.exitCode;
