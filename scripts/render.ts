/**
 * `npm run --silent render -- [view options] --out FILE.png …`: pictures of the demo as PNG files
 * (or, with `--time-lapse`, one animation of it at many film times), rendered in headless Chromium
 * (see src/cli/renderUsage.ts or `--help`); the views or frames done on stderr while it runs
 * (src/cli/progress.ts). Exit status: 0 done, 1 a render failed, 2 bad input (nothing written), 3 no Chromium.
 */
import { readCasesFile, outFolderProblem, writeFileAtomically } from '../src/cli/commandFiles.ts';
import { type RenderCommand, type RenderView, parseRenderCases, parseRenderCommandLine } from '../src/cli/renderOptions.ts';
import { RENDER_USAGE } from '../src/cli/renderUsage.ts';
import { type ProgressReporter, progressReporter } from '../src/cli/progress.ts';
import { ParameterError } from '../src/input/validate.ts';
import { findChromium } from './chromium.ts';

/** Stops with one line on stderr. */
function stop(exitCode: 1 | 2 | 3, message: string): never {
  process.stderr.write(`render: ${message.replace(/[\r\n]+/g, ' ')}\n`);
  process.exit(exitCode);
}

type TimeLapse = Extract<RenderCommand, { kind: 'timeLapse' }>;
type Views = { readonly kind: 'views'; readonly views: readonly RenderView[]; readonly progress: boolean };

/**
 * The views asked for, or a time-lapse, every one checked (and every file's folder found) before
 * any is rendered.
 */
function renderAskedFor(): Views | TimeLapse | 'help' {
  try {
    const command = parseRenderCommandLine(process.argv.slice(2));
    if (command.kind === 'help') return 'help';
    if (command.kind === 'timeLapse') {
      const problem = outFolderProblem('--out', command.out);
      if (problem) throw new ParameterError('out', problem);
      return command;
    }
    const views = command.kind === 'views' ? command.views : parseRenderCases(readCasesFile(command.path), command.path, command.defaults);
    views.forEach((view, index) => {
      const problem = outFolderProblem(command.kind === 'views' ? '--out' : `case at index ${index}: out`, view.out);
      if (problem) throw new ParameterError('out', problem);
    });
    return { kind: 'views', views, progress: command.progress };
  } catch (error) {
    if (error instanceof ParameterError) return stop(2, error.message);
    throw error;
  }
}

/** Writes `file` over `out` atomically; a folder that cannot be written to is the user's (exit 2). */
function write(out: string, file: Buffer): void {
  const writeError = writeFileAtomically(out, file);
  if (writeError) throw new ParameterError('--out', writeError);
}

/** Progress on stderr: `total` views or frames, every one reported. */
const progressOf = (asked: Views | TimeLapse, name: string, total: number): ProgressReporter =>
  progressReporter(process.stderr, { tool: 'render', unit: { name, digits: 0 }, total, asked: asked.progress, everyMs: 0 });

const asked = renderAskedFor();
if (asked === 'help') {
  process.stdout.write(RENDER_USAGE);
  process.exit(0);
}
const chromiumSearch = findChromium();
if ('missing' in chromiumSearch) stop(3, chromiumSearch.missing);
try {
  // Vite and the browser session are loaded only when there is something to render.
  if (asked.kind === 'timeLapse') {
    const { renderTimeLapse } = await import('./render/renderTimeLapse.ts');
    const progress = progressOf(asked, 'frames', asked.frames.length);
    const { file, width, height, ms } = await renderTimeLapse(asked, chromiumSearch.found, progress.report);
    write(asked.out, file);
    const line = { out: asked.out, format: asked.format, frames: asked.frames.length, frameMs: asked.frameMs, width, height, ms };
    process.stdout.write(`${JSON.stringify(line)}\n`);
  } else {
    const { renderViews } = await import('./render/renderViews.ts');
    const progress = progressOf(asked, 'views', asked.views.length);
    let done = 0;
    progress.report(done);
    await renderViews(asked.views, chromiumSearch.found, (view, { png, width, height, ms }) => {
      write(view.out, png);
      process.stdout.write(`${JSON.stringify({ out: view.out, width, height, ms })}\n`);
      progress.report(++done);
    });
  }
} catch (error) {
  if (error instanceof ParameterError) stop(2, error.message);
  stop(1, `rendering failed: ${error instanceof Error ? error.message : String(error)}`);
}
