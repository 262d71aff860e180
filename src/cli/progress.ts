/**
 * Progress on long work (the render command's frames, the film command's film seconds), on stderr:
 * how much is done of the total and the time left, extrapolated from the time taken so far. On a
 * terminal one line is redrawn in place; elsewhere (a log, a pipe) nothing is written unless asked
 * for (`--progress`), and then one line per report.
 */

/** What is counted: its name as the line shows it (`frame`, `film seconds`) and the digits after the point. */
export interface ProgressUnit {
  readonly name: string;
  readonly digits: number;
}

/** The time left (ms) at `done` of `total` after `elapsedMs`, the rate so far held; null before anything is done. */
export function timeLeftMs(done: number, total: number, elapsedMs: number): number | null {
  if (done <= 0) return null;
  return Math.max(0, (elapsedMs * (total - done)) / done);
}

/** A duration as a clock shows it: `m:ss`, or `h:mm:ss` from an hour on (rounded up to the second). */
export function clockText(ms: number): string {
  const s = Math.ceil(ms / 1000);
  const [h, m, sec] = [Math.floor(s / 3600), Math.floor((s % 3600) / 60), s % 60];
  const pad = (n: number) => String(n).padStart(2, '0');
  return h > 0 ? `${h}:${pad(m)}:${pad(sec)}` : `${m}:${pad(sec)}`;
}

/**
 * One report: `render: frame 3/20 (15%), 1:05 left`; when all is done, the time it took
 * (`…(100%), done in 4:12`); before anything is done, no time left.
 */
export function progressText(tool: string, unit: ProgressUnit, done: number, total: number, elapsedMs: number): string {
  const count = `${done.toFixed(unit.digits)}/${total.toFixed(unit.digits)}`;
  const percent = total > 0 ? Math.floor((100 * done) / total) : 100;
  const left = timeLeftMs(done, total, elapsedMs);
  const time = done >= total ? `, done in ${clockText(elapsedMs)}` : left === null ? '' : `, ${clockText(left)} left`;
  return `${tool}: ${unit.name} ${count} (${percent}%)${time}`;
}

/** Where reports go: stderr, or a stand-in (a test's). */
export interface ProgressStream {
  readonly isTTY?: boolean;
  write(text: string): unknown;
}

export interface ProgressOptions {
  readonly tool: string;
  readonly unit: ProgressUnit;
  readonly total: number;
  /** Reports even where the stream is not a terminal (`--progress`). */
  readonly asked: boolean;
  /** The least time between two reports (ms); the last one is always made. */
  readonly everyMs: number;
  /** The clock (ms); performance.now by default. */
  readonly now?: () => number;
}

export interface ProgressReporter {
  /** `done` of the total is done: reported if the last report is at least `everyMs` old, or all is done (once). */
  readonly report: (done: number) => void;
}

/** A reporter on `stream`: one line redrawn on a terminal, a line per report elsewhere when asked, else silent. */
export function progressReporter(stream: ProgressStream, options: ProgressOptions): ProgressReporter {
  const tty = stream.isTTY === true;
  if (!tty && !options.asked) return { report: () => undefined };
  const now = options.now ?? (() => performance.now());
  const started = now();
  let last = -Infinity;
  let finished = false;
  return {
    report: (done) => {
      if (finished) return;
      const t = now();
      finished = done >= options.total;
      if (!finished && t - last < options.everyMs) return;
      last = t;
      const line = progressText(options.tool, options.unit, done, options.total, t - started);
      // On a terminal: back to the line's start, the line, the rest of the old one cleared.
      stream.write(tty ? `\r${line}\x1b[K${finished ? '\n' : ''}` : `${line}\n`);
    },
  };
}
