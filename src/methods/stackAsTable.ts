import type { DrawnInstead, FilmMethodSettings } from './filmMethod.ts';

/**
 * The table drawn in the place of a method with no form for a stack of films (a closed-form series
 * or a two-interface fit): the table is filled by the stack's recursion on the GPU
 * (docs/gpu.md#stacks-of-films), and its lookup costs what a single film's does. Null for a single film.
 */
export const stackAsTable = (s: FilmMethodSettings, method: string): DrawnInstead | null =>
  (s.layers?.length ?? 0) > 0
    ? { method: 'table', notice: 'app.stackAsTable', values: { method, layers: String(s.layers!.length) } }
    : null;
