/**
 * A page's main-thread tasks from a Chrome trace (Playwright's browser.startTracing with
 * TRACE_CATEGORIES): each task's wall time and the time its thread ran in it. A task can last long
 * while its thread does not run: a synchronous GL call waiting on the GPU process, or, on a CPU
 * rasteriser, the rasteriser's threads holding the cores. The thread time tells the two apart.
 */

/** What the trace must record: the scheduler's tasks, the page's performance marks, the threads' names. */
export const TRACE_CATEGORIES = ['toplevel', 'blink.user_timing', '__metadata'];

/** The scheduler's event for one task of a thread (category `toplevel`). */
const TASK_EVENT = 'ThreadControllerImpl::RunTask';

/** A task: its wall time and its thread's time in it, ms. */
export interface TracedTask {
  readonly wallMs: number;
  readonly threadMs: number;
}

/** The fields of a trace event read here (times in µs). */
interface TraceEvent {
  readonly name: string;
  readonly cat?: string;
  readonly ph: string;
  readonly pid: number;
  readonly tid: number;
  readonly ts: number;
  readonly dur?: number;
  readonly tdur?: number;
}

/**
 * For each window [mark `from`, mark `to`] (performance.mark names), the tasks of the thread that
 * made the marks which overlap it, in their order. A mark missing from the trace is an error
 * naming it.
 */
export function tasksBetweenMarks(traceJson: string, windows: readonly (readonly [string, string])[]): TracedTask[][] {
  const events = (JSON.parse(traceJson) as { traceEvents: TraceEvent[] }).traceEvents;
  const marks = new Map(events.filter((e) => e.cat?.includes('blink.user_timing')).map((e) => [e.name, e]));
  const at = (name: string): TraceEvent => {
    const mark = marks.get(name);
    if (!mark) throw new Error(`the trace has no mark "${name}"`);
    return mark;
  };
  return windows.map(([from, to]) => {
    const [start, end] = [at(from), at(to)];
    return events
      .filter((e) => e.name === TASK_EVENT && e.ph === 'X' && e.pid === start.pid && e.tid === start.tid)
      .filter((e) => e.ts < end.ts && e.ts + (e.dur ?? 0) > start.ts)
      .sort((a, b) => a.ts - b.ts)
      .map((e) => ({ wallMs: (e.dur ?? 0) / 1000, threadMs: (e.tdur ?? 0) / 1000 }));
  });
}
