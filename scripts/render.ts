/**
 * `npm run --silent render -- [view options] --out FILE.png …`: pictures of the demo as PNG files,
 * rendered in headless Chromium (see src/cli/renderUsage.ts or `--help`). Exit status: 0 done,
 * 1 a render failed, 2 bad input (nothing written), 3 no Chromium.
 */
import { readCasesFile, outFolderProblem, writeFileAtomically } from '../src/cli/commandFiles.ts';
import { type RenderView, parseRenderCases, parseRenderCommandLine } from '../src/cli/renderOptions.ts';
import { RENDER_USAGE } from '../src/cli/renderUsage.ts';
import { ParameterError } from '../src/input/validate.ts';
import { findChromium } from './chromium.ts';

/** Stops with one line on stderr. */
function stop(exitCode: 1 | 2 | 3, message: string): never {
  process.stderr.write(`render: ${message.replace(/[\r\n]+/g, ' ')}\n`);
  process.exit(exitCode);
}

/** The views asked for, every one checked (and every file's folder found) before any is rendered. */
function viewsAskedFor(): readonly RenderView[] | 'help' {
  try {
    const command = parseRenderCommandLine(process.argv.slice(2));
    if (command.kind === 'help') return 'help';
    const views = command.kind === 'views' ? command.views : parseRenderCases(readCasesFile(command.path), command.path, command.defaults);
    views.forEach((view, index) => {
      const problem = outFolderProblem(command.kind === 'views' ? '--out' : `case at index ${index}: out`, view.out);
      if (problem) throw new ParameterError('out', problem);
    });
    return views;
  } catch (error) {
    if (error instanceof ParameterError) return stop(2, error.message);
    throw error;
  }
}

const views = viewsAskedFor();
if (views === 'help') {
  process.stdout.write(RENDER_USAGE);
  process.exit(0);
}
const chromiumSearch = findChromium();
if ('missing' in chromiumSearch) stop(3, chromiumSearch.missing);
try {
  // Vite and the browser session are loaded only when there is something to render.
  const { renderViews } = await import('./render/renderViews.ts');
  await renderViews(views, chromiumSearch.found, (view, { png, width, height, ms }) => {
    const writeError = writeFileAtomically(view.out, png);
    if (writeError) throw new ParameterError('--out', writeError);
    process.stdout.write(`${JSON.stringify({ out: view.out, width, height, ms })}\n`);
  });
} catch (error) {
  if (error instanceof ParameterError) stop(2, error.message);
  stop(1, `rendering failed: ${error instanceof Error ? error.message : String(error)}`);
}
