/**
 * A field of a one-texel record (src/gpu/texelRecord.ts) read in TSL by its offset, as
 * shaders/gpu/texelRecord.glsl's TFC_TEXEL_* read it: both sides take the offsets from the record.
 */
import { type Node } from 'three/webgpu';

const COMPONENTS = 'xyzw';

/** The float at `offset` of `texel`. */
export const texelFloat = (texel: Node<'vec4'>, offset: number): Node<'float'> => texel.get(COMPONENTS[offset]!) as Node<'float'>;

/** The vec2 at `offset` of `texel`. */
export const texelVec2 = (texel: Node<'vec4'>, offset: number): Node<'vec2'> =>
  texel.get(COMPONENTS.slice(offset, offset + 2)) as Node<'vec2'>;
