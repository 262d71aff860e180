/**
 * A field of a one-texel record (src/gpu/texelRecord.ts) read in TSL by its offset, as
 * shaders/gpu/texelRecord.glsl's TFC_TEXEL_* read it: both sides take the offsets from the record.
 */
import { type Node } from 'three/webgpu';

const COMPONENTS = 'xyzw';

/** The swizzle of `width` components at `offset` of `texel` (TSL's swizzles are properties of a node). */
const swizzle = <T>(texel: Node<'vec4'>, offset: number, width: number): T =>
  (texel as unknown as Record<string, T>)[COMPONENTS.slice(offset, offset + width)]!;

/** The float at `offset` of `texel`. */
export const texelFloat = (texel: Node<'vec4'>, offset: number): Node<'float'> => swizzle(texel, offset, 1);

/** The vec2 at `offset` of `texel`. */
export const texelVec2 = (texel: Node<'vec4'>, offset: number): Node<'vec2'> => swizzle(texel, offset, 2);
