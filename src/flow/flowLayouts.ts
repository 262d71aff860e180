import { HOLE_RAYS, MAX_HOLES } from '../physics/flow/filmHoles.ts';
import type { AtlasSize } from './flowAtlas.ts';
import { HALO_TAP_TEXELS } from './flowGridTextures.ts';

/**
 * The texel layouts of the flow's passes that TypeScript and GLSL share, each written once here
 * and emitted into the passes' GLSL as named defines (flowLayoutDefines), so a shader reads a
 * texel or a channel by its name, never at an offset typed as a number. Each layout is a list of
 * names in order: reordering it moves both sides together.
 */

/**
 * A row of the hole table (shaders/flow/filmHoles.glsl), one per hole slot: ray k's rim radius in
 * texel k (r) for the HOLE_RAYS rays, then the hole's frame, one texel each in this order: the
 * centre (xyz, and w = 1 while the slot holds a hole), e1 and e2 (w = 0).
 */
export const HOLE_FRAME = ['center', 'e1', 'e2'] as const;

/** The texel of a row of the hole table that holds a part of the hole's frame. */
export const holeFrameTexel = (part: (typeof HOLE_FRAME)[number]): number => HOLE_RAYS + HOLE_FRAME.indexOf(part);

/** The hole table: a row per hole slot, its rays and then its frame. */
export const HOLE_TABLE: AtlasSize = { width: HOLE_RAYS + HOLE_FRAME.length, height: MAX_HOLES };

/**
 * The channels of the surfactant solve's cell texels (shaders/flow/solveSurfactant.glsl), in order
 * from r: the system's right side b − AΓ and its diagonal; a Chebyshev sweep's next iterate
 * x_{k+1}, the iterate x_k it read (the next sweep's x_{k−1}) and the (b − Ax_k)² of it (x the
 * increment δ = Γ' − Γ).
 */
export const SURFACTANT_SYSTEM_TEXEL = ['rhs', 'diagonal'] as const;
export const SURFACTANT_SWEEP_TEXEL = ['x', 'previousX', 'residualSquared'] as const;

/** The one-hot mask that picks channel `channel` of a texel by a dot product. */
const channelMask = (channel: number): readonly number[] => [0, 1, 2, 3].map((k) => (k === channel ? 1 : 0));

/** The first sweep's x_0 and x_{−1} (uGuessChannel, uPreviousGuessChannel): no channel, so 0 (δ starts at none). */
export const ZERO_GUESS: readonly number[] = [0, 0, 0, 0];
/** A later sweep's x_k: the x of the sweep before. */
export const SWEEP_GUESS = channelMask(SURFACTANT_SWEEP_TEXEL.indexOf('x'));
/** A later sweep's x_{k−1}: the iterate the sweep before read. */
export const SWEEP_PREVIOUS_GUESS = channelMask(SURFACTANT_SWEEP_TEXEL.indexOf('previousX'));

/** `residualSquared` → `RESIDUAL_SQUARED`. */
const constantCase = (name: string): string => name.replace(/([a-z0-9])([A-Z])/g, '$1_$2').toUpperCase();

/** `TFC_<PREFIX>_<NAME>_<UNIT>` = first + the name's place in the list. */
const namedPlaces = (prefix: string, names: readonly string[], first: number, unit: string): Record<string, number> =>
  Object.fromEntries(names.map((name, k) => [`TFC_${prefix}_${constantCase(name)}_${unit}`, first + k]));

/**
 * Every layout above as the defines its GLSL reads (`TFC_HOLE_E1_TEXEL`,
 * `TFC_SURFACTANT_SYSTEM_DIAGONAL_CHANNEL`, …), with the sizes of the hole table and the halo's tap table.
 */
export const flowLayoutDefines = (): Record<string, number> => ({
  TFC_HALO_TAP_TEXELS: HALO_TAP_TEXELS,
  TFC_HOLE_RAYS: HOLE_RAYS,
  TFC_MAX_HOLES: MAX_HOLES,
  ...namedPlaces('HOLE', HOLE_FRAME, HOLE_RAYS, 'TEXEL'),
  ...namedPlaces('SURFACTANT_SYSTEM', SURFACTANT_SYSTEM_TEXEL, 0, 'CHANNEL'),
  ...namedPlaces('SURFACTANT_SWEEP', SURFACTANT_SWEEP_TEXEL, 0, 'CHANNEL'),
});
