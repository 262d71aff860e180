/**
 * What a program driving the demo page (index.html, src/pages/demo.ts) needs to know of it: its ready
 * marks and the parts of it that are interface, not the picture. Used by the render command and
 * the screenshot tests.
 */

/**
 * The ready marks the demo sets on <body data-frames>: its first complete frame is drawn, or —
 * without WebGL2 — the CPU's still image is. The plots follow in a task of their own (PLOTS_DRAWN).
 */
export const FRAME_DRAWN = 'body[data-frames="ready"], body[data-frames="fallback"]';
/** The lil-gui panel. */
export const PANEL = '.lil-gui';
/** The plots' drawer (index.html). */
export const PLOTS_BOX = '#plots-box';
/** The plots' panel (src/plots/plotPanel.ts), and the panel once drawn for a probe (it marks the probe on itself). */
export const PLOT_PANEL = '.tfb-plots';
export const PLOTS_DRAWN = `${PLOT_PANEL}[data-probe]`;
/** The plots: their drawer, and the ring over the bubble where the probe is (src/app/bubbleApp.ts). */
export const PLOTS = `${PLOTS_BOX}, .tfb-probe-marker`;
