/**
 * Progress on long work (src/cli/progress.ts). Expected values are worked by hand: at a steady rate
 * the time left is the time so far times what is left over what is done.
 */
import { describe, expect, it } from 'vitest';
import { clockText, progressReporter, progressText, timeLeftMs } from '../../../src/cli/progress.ts';

const FRAMES = { name: 'frames', digits: 0 };

describe('progress text', () => {
  it('extrapolates the time left at the rate so far: 5 of 20 in 10 s leaves 15 × 2 s', () => {
    expect(timeLeftMs(5, 20, 10_000)).toBe(30_000);
    expect(timeLeftMs(20, 20, 10_000)).toBe(0);
    expect(timeLeftMs(0, 20, 10_000)).toBeNull();
  });

  it('writes a duration as a clock, rounded up to the second', () => {
    expect(clockText(0)).toBe('0:00');
    expect(clockText(65_000)).toBe('1:05');
    expect(clockText(59_001)).toBe('1:00');
    expect(clockText(3_600_000)).toBe('1:00:00');
    expect(clockText(3_661_000)).toBe('1:01:01');
  });

  it('says what is done of the total, the share and the time left (none before anything is done), then the time it took', () => {
    expect(progressText('render', FRAMES, 0, 20, 3000)).toBe('render: frames 0/20 (0%)');
    // 3 frames in 6 s: 17 more at 2 s each.
    expect(progressText('render', FRAMES, 3, 20, 6000)).toBe('render: frames 3/20 (15%), 0:34 left');
    expect(progressText('film', { name: 'film seconds', digits: 2 }, 0.5, 2, 60_000)).toBe('film: film seconds 0.50/2.00 (25%), 3:00 left');
    expect(progressText('render', FRAMES, 20, 20, 252_000)).toBe('render: frames 20/20 (100%), done in 4:12');
  });
});

describe('progress reporter', () => {
  const run = (isTTY: boolean, asked: boolean, everyMs: number, reports: [number, number][]) => {
    const written: string[] = [];
    let t = 0;
    const reporter = progressReporter(
      { isTTY, write: (text: string) => written.push(text) },
      { tool: 'render', unit: FRAMES, total: 4, asked, everyMs, now: () => t },
    );
    for (const [at, done] of reports) {
      t = at;
      reporter.report(done);
    }
    return written;
  };
  const reports: [number, number][] = [
    [0, 0],
    [1000, 1],
    [1500, 2],
    [3000, 3],
    [4000, 4],
  ];

  it('is silent where stderr is not a terminal unless asked, then writes a line per report', () => {
    expect(run(false, false, 0, reports)).toEqual([]);
    expect(run(false, true, 0, reports)).toEqual([
      'render: frames 0/4 (0%)\n',
      'render: frames 1/4 (25%), 0:03 left\n',
      'render: frames 2/4 (50%), 0:02 left\n',
      'render: frames 3/4 (75%), 0:01 left\n',
      'render: frames 4/4 (100%), done in 0:04\n',
    ]);
  });

  it('redraws one line on a terminal, asked or not, and ends it when all is done', () => {
    const written = run(true, false, 0, reports);
    expect(written).toHaveLength(5);
    expect(written[1]).toBe('\rrender: frames 1/4 (25%), 0:03 left\x1b[K');
    expect(written[4]).toBe('\rrender: frames 4/4 (100%), done in 0:04\x1b[K\n');
  });

  it('reports at most once every everyMs, the last report always, and nothing after it', () => {
    const written = run(false, true, 1000, [...reports, [5000, 4]]);
    // 1500 ms is 500 ms after the report at 1000 ms: skipped.
    expect(written.map((line) => line.split(' ')[2])).toEqual(['0/4', '1/4', '3/4', '4/4']);
  });
});
