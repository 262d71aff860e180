/**
 * The film's and the inside's indices ñ(λ) = n + ik in TSL where either depends on λ: the media's
 * knots (src/film/filmMedia.ts, every MEDIA_KNOT_DEFINES.TFC_MEDIA_STEP_NM from
 * TFC_MEDIA_FIRST_NM, in float64 by mediumIndexAt) as a one-row texture, linear between knots.
 * The node twin of shaders/physics/medium.glsl.
 */
import { clamp, float, int, ivec2, min, mix, textureLoad } from 'three/tsl';
import { type TextureNode } from 'three/webgpu';
import { MEDIA_KNOT, MEDIA_KNOT_DEFINES } from '../film/filmMedia.ts';
import { type ComplexNode, type FloatNode } from './complex.ts';
import { texelVec2 } from './texelRecords.ts';

const KNOTS = MEDIA_KNOT_DEFINES.TFC_MEDIA_KNOTS!;
const FIRST_NM = MEDIA_KNOT_DEFINES.TFC_MEDIA_FIRST_NM!;
const STEP_NM = MEDIA_KNOT_DEFINES.TFC_MEDIA_STEP_NM!;

/** The film's and the inside's ñ at λ from the knots. */
export function mediaAt(knots: TextureNode, lambdaNm: FloatNode): { readonly film: ComplexNode; readonly inside: ComplexNode } {
  const pos = clamp(lambdaNm.sub(FIRST_NM).div(STEP_NM), 0, KNOTS - 1).toVar();
  const i = int(min(pos, KNOTS - 2)).toVar();
  const knot = mix(textureLoad(knots, ivec2(i, int(0))), textureLoad(knots, ivec2(i.add(1), int(0))), pos.sub(float(i))).toVar();
  return { film: texelVec2(knot, MEDIA_KNOT.offsets.FILM), inside: texelVec2(knot, MEDIA_KNOT.offsets.INSIDE) };
}
