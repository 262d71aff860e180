import type { FilmMethod } from './filmMethod.ts';

/**
 * `table`: one filtered lookup per fragment in a table of the film's XYZ over thickness and
 * cos θ, built on the GPU by the exact integral (for a stack of films, by its recursion per bin;
 * the lookup is the same). The lookup does not depend on the polarisation or the stack (the
 * table's pass does), so changing them compiles no bubble.
 */
export const tableMethod = {
  glsl: 'tableMethod.glsl',
  reads: ['table'],
  offered: true,
  fills: ['constant', 'dispersive', 'stack'],
  frameCost: { constant: 1, dispersive: 1 },
} as const satisfies FilmMethod;
