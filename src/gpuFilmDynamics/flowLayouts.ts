import { HOLE_RAYS, MAX_HOLES } from '../physics/filmDynamics/filmHoles.ts';
import type { AtlasSize } from './flowAtlas.ts';
import { HALO_TAP_TEXELS } from './flowGridTextures.ts';

/**
 * The layouts of the flow's textures whose texels play different parts, written once here and
 * emitted into the passes' GLSL as named defines (flowLayoutDefines), so a shader finds a texel by
 * its name, never at an offset typed as a number; what each texel holds is its record in
 * flowTexels.ts. Each layout is a list of names in order: reordering it moves both sides together.
 */

/**
 * A row of the hole table (shaders/gpuFilmDynamics/filmHoles.glsl), one per hole slot: ray k's rim radius in
 * texel k (a HOLE_RAY) for the HOLE_RAYS rays, then the hole's frame, one texel each in this
 * order: the centre and whether the slot holds a hole (a HOLE_ORIGIN), e1 and e2 (HOLE_AXIS each).
 */
export const HOLE_FRAME = ['center', 'e1', 'e2'] as const;

/** The texel of a row of the hole table that holds a part of the hole's frame. */
export const holeFrameTexel = (part: (typeof HOLE_FRAME)[number]): number => HOLE_RAYS + HOLE_FRAME.indexOf(part);

/** The hole table: a row per hole slot, its rays and then its frame. */
export const HOLE_TABLE: AtlasSize = { width: HOLE_RAYS + HOLE_FRAME.length, height: MAX_HOLES };

/** `TFC_<PREFIX>_<NAME>_<UNIT>` = first + the name's place in the list. */
const namedPlaces = (prefix: string, names: readonly string[], first: number, unit: string): Record<string, number> =>
  Object.fromEntries(names.map((name, k) => [`TFC_${prefix}_${name.toUpperCase()}_${unit}`, first + k]));

/**
 * Every layout above as the defines its GLSL reads (`TFC_HOLE_E1_TEXEL`, …), with the sizes of the
 * hole table and the halo's tap table.
 */
export const flowLayoutDefines = (): Record<string, number> => ({
  TFC_HALO_TAP_TEXELS: HALO_TAP_TEXELS,
  TFC_HOLE_RAYS: HOLE_RAYS,
  TFC_MAX_HOLES: MAX_HOLES,
  ...namedPlaces('HOLE', HOLE_FRAME, HOLE_RAYS, 'TEXEL'),
});
