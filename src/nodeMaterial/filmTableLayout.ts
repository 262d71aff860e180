/**
 * Where (thickness, cos θ_i) sit in the film table, in TSL: the twin of
 * shaders/film/filmTableLayout.glsl. u, v in [0, 1] run from the first to the last texel centre:
 *   d = max · u^thicknessPower,   cos θ_i = v^cosPower
 * (src/settings/filmTableLayout.ts's powers: texels spent on thin films and grazing light).
 */
import { clamp, float, pow, vec2 } from 'three/tsl';
import { type Node } from 'three/webgpu';
import { type FilmTableLayout } from '../settings/filmTableLayout.ts';
import { type FloatNode } from './complex.ts';

export type TablePowers = Pick<FilmTableLayout, 'thicknessPower' | 'cosPower'>;

export const tableThicknessNm = (l: TablePowers, u: FloatNode, maxThicknessNm: FloatNode): FloatNode =>
  maxThicknessNm.mul(pow(u, float(l.thicknessPower)));

export const tableCosIncidence = (l: TablePowers, v: FloatNode): FloatNode => pow(v, float(l.cosPower));

/** The inverse of both maps: (u, v) for a film, clamped to the table. */
export const tableUv = (l: TablePowers, thicknessNm: FloatNode, cosIncidence: FloatNode, maxThicknessNm: FloatNode): Node<'vec2'> =>
  vec2(
    pow(clamp(thicknessNm.div(maxThicknessNm), 0, 1), float(1 / l.thicknessPower)),
    pow(clamp(cosIncidence, 0, 1), float(1 / l.cosPower)),
  );
