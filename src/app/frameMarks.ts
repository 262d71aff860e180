/**
 * The User Timing marks (performance.mark) the demo page sets: its first frame drawn, and its first
 * frame drawn in full (not from a coarse table, the HDR environment shown). The benchmark reads them.
 */
export const FRAME_MARKS = { first: 'tfc:first-frame', firstComplete: 'tfc:first-complete-frame' } as const;
