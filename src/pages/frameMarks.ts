/**
 * The User Timing marks (performance.mark) the demo page sets, part of its documented behaviour
 * (docs/browser.md): its first frame drawn, and its first frame drawn in full (not from a coarse
 * table, the HDR environment shown). The benchmark and the suite's time report read them.
 */
export const FRAME_MARKS = { first: 'tfc:first-frame', firstComplete: 'tfc:first-complete-frame' } as const;
