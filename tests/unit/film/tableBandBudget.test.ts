/**
 * The table's bands fit in their share of a frame: sized by the measured cost of their kind of
 * pass, or, for a kind not yet measured, by an estimate from the other kind that errs towards
 * smaller bands.
 */
import { describe, expect, it } from 'vitest';
import { BAND_SHARE, COARSE_DIVISOR, TableBandBudget } from '../../../src/film/tableBandBudget.ts';

const ROWS = 16;
const WIDTH = 4096;
/** A frame's own time (ms) and the constant pass's cost per texel (ms) in these tests. */
const FRAME_MS = 190;
const CONSTANT_MS = 0.01;

/** A budget that has seen two constant bands of 1000 texels, FRAME_MS apart. */
function measuredConstant(): TableBandBudget {
  const budget = new TableBandBudget();
  budget.drawn('constant', 1000, 0, 1000 * CONSTANT_MS);
  budget.drawn('constant', 1000, 1000 * CONSTANT_MS + FRAME_MS, 1000 * CONSTANT_MS);
  return budget;
}

describe('the table band budget', () => {
  it('before anything is measured: a sixteenth of the width, and the coarse divisor', () => {
    const budget = new TableBandBudget();
    expect(budget.bandColumns('dispersive', ROWS, WIDTH, WIDTH)).toBe(WIDTH / 16);
    expect(budget.coarseDivisor('dispersive', WIDTH * ROWS)).toBe(COARSE_DIVISOR);
  });

  it("a measured kind's band takes at most its share of the frame, and nearly all of it", () => {
    const columns = measuredConstant().bandColumns('constant', ROWS, WIDTH, WIDTH);
    const ms = columns * ROWS * CONSTANT_MS;
    expect(ms).toBeLessThanOrEqual(BAND_SHARE * FRAME_MS);
    expect(ms).toBeGreaterThan(BAND_SHARE * FRAME_MS - ROWS * CONSTANT_MS);
  });

  it('a dispersive pass not yet measured is sized as if it cost 5× the constant one per texel (the low end of the 4–10× measured on SwiftShader)', () => {
    const budget = measuredConstant();
    const columns = budget.bandColumns('dispersive', ROWS, WIDTH, WIDTH);
    expect(columns * ROWS * 5 * CONSTANT_MS).toBeLessThanOrEqual(BAND_SHARE * FRAME_MS);
    // Its coarse table likewise: its texels at that cost fit the share.
    const divisor = budget.coarseDivisor('dispersive', WIDTH * ROWS);
    expect(((WIDTH * ROWS) / divisor ** 2) * 5 * CONSTANT_MS).toBeLessThanOrEqual(BAND_SHARE * FRAME_MS);
  });

  it('once measured, a kind is sized by its own cost: a dispersive pass at 2× the constant per texel gets half its band', () => {
    const budget = measuredConstant();
    const constant = budget.bandColumns('constant', ROWS, WIDTH, WIDTH);
    budget.drawn('dispersive', 1000, 2 * (1000 * CONSTANT_MS + FRAME_MS), 1000 * 2 * CONSTANT_MS);
    expect(Math.abs(budget.bandColumns('dispersive', ROWS, WIDTH, WIDTH) - constant / 2)).toBeLessThanOrEqual(1);
  });

  it('a frame is the time between the draws of a run less their own, over the whole run: timed frames later, the CPU may run ahead or wait at any one draw', () => {
    const budget = new TableBandBudget();
    const draw = 1000 * CONSTANT_MS;
    // The second draw was asked for late (the CPU waited), the third early: together, two frames.
    budget.drawn('constant', 1000, 0, draw);
    budget.drawn('constant', 1000, 2 * FRAME_MS, draw);
    budget.drawn('constant', 1000, 2 * FRAME_MS + 2 * draw, draw);
    const columns = budget.bandColumns('constant', ROWS, WIDTH, WIDTH);
    expect(columns * ROWS * CONSTANT_MS).toBeLessThanOrEqual(BAND_SHARE * FRAME_MS);
    expect(columns * ROWS * CONSTANT_MS).toBeGreaterThan(BAND_SHARE * FRAME_MS - ROWS * CONSTANT_MS);
  });

  it('a draw asked for before the last one had run (the CPU ahead of the GPU) makes no frame of the gap', () => {
    const budget = new TableBandBudget();
    budget.drawn('constant', 1000, 0, 50);
    budget.drawn('constant', 1000, 5, 50);
    // No frame measured yet: the first band's share, not a band from a frame of −45 ms.
    expect(budget.bandColumns('constant', ROWS, WIDTH, WIDTH)).toBe(WIDTH / 16);
  });

  it('a draw timed at 0 ms tells nothing of the cost', () => {
    const budget = new TableBandBudget();
    budget.drawn('constant', 1000, 0, 0);
    budget.drawn('constant', 1000, FRAME_MS, 0);
    expect(budget.bandColumns('constant', ROWS, WIDTH, WIDTH)).toBe(WIDTH / 16);
  });

  it('a band never exceeds the columns remaining', () => {
    expect(measuredConstant().bandColumns('constant', ROWS, WIDTH, 7)).toBe(7);
  });
});
