/**
 * The most drawing-buffer pixels per CSS pixel a page draws (the demo, its plots, the materials
 * page, the command line's pictures, the governor's ladder): past 2 the buffer's pixels, which grow
 * as the ratio's square, cost more than a screen at arm's length shows.
 */
export const MAX_PIXEL_RATIO = 2;

/** The device's pixel ratio (1 where it has none) as a page draws it: at most MAX_PIXEL_RATIO. */
export const shownPixelRatio = (device: number = globalThis.devicePixelRatio): number => Math.min(MAX_PIXEL_RATIO, device || 1);
