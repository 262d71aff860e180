/** The parts of a bubble's page that can start closed on a small view. */
export type ClosablePart = 'panel' | 'plots';

/**
 * Whether a part starts closed, as the page's CSS decides for the size it is laid out at: the
 * custom property `--tfb-panel-start` / `--tfb-plots-start` is `closed` (set by a media query in
 * the demo's index.html, by a container query in the element's style), read from `el` (the part
 * itself or an element inside the box the query measures). The breakpoints live in CSS only.
 */
export function startsClosed(el: Element, part: ClosablePart): boolean {
  return getComputedStyle(el).getPropertyValue(`--tfb-${part}-start`).trim() === 'closed';
}
