import { describe, expect, it } from 'vitest';
import { tasksBetweenMarks } from '../../../scripts/bench/traceTasks.ts';

/** A trace of two threads: the page's (pid 1, tid 1, which makes the marks) and another (pid 2), times in µs. */
const task = (pid: number, ts: number, dur: number, tdur: number) => ({
  name: 'ThreadControllerImpl::RunTask',
  cat: 'toplevel',
  ph: 'X',
  pid,
  tid: pid,
  ts,
  dur,
  tdur,
});
const mark = (name: string, ts: number) => ({ name, cat: 'blink.user_timing', ph: 'R', pid: 1, tid: 1, ts });
const trace = JSON.stringify({
  traceEvents: [
    mark('a', 1_000_000),
    mark('a drawn', 2_000_000),
    mark('b', 3_000_000),
    mark('b drawn', 4_000_000),
    // before a: ends inside it (overlaps)
    task(1, 900_000, 200_000, 150_000),
    // inside a: long, mostly waiting
    task(1, 1_500_000, 120_000, 3_000),
    // inside a: short
    task(1, 1_700_000, 40_000, 40_000),
    // another thread's long task inside a
    task(2, 1_500_000, 300_000, 300_000),
    // between the windows
    task(1, 2_500_000, 90_000, 90_000),
    // starts inside b, ends after it
    task(1, 3_950_000, 100_000, 60_000),
  ],
});

describe('tasksBetweenMarks', () => {
  it("keeps the marking thread's tasks that overlap each window, wall and thread time in ms", () => {
    expect(
      tasksBetweenMarks(trace, [
        ['a', 'a drawn'],
        ['b', 'b drawn'],
      ]),
    ).toEqual([
      [
        { wallMs: 200, threadMs: 150 },
        { wallMs: 120, threadMs: 3 },
        { wallMs: 40, threadMs: 40 },
      ],
      [{ wallMs: 100, threadMs: 60 }],
    ]);
  });

  it('names a mark the trace lacks', () => {
    expect(() => tasksBetweenMarks(trace, [['a', 'c drawn']])).toThrow('the trace has no mark "c drawn"');
  });
});
