import { texelRecord, texelRecordDefines } from '../gpu/texelRecord.ts';

/**
 * The texels of the flow's textures and targets as texel records (src/gpu/texelRecord.ts), one
 * texel each: the grid's textures that flowGridTextures.ts uploads, the film's state and each
 * pass's result. TypeScript packs and reads them by these names, the GLSL of shaders/gpuFilmDynamics/ through
 * TFC_TEXEL_* of texelRecord.glsl at the defines they emit (flowTexelDefines), so reordering a
 * record's fields cannot change what is drawn.
 */

/** The film per cell (cell atlas; the padded film the same per padded texel): η, Γ (in η0, Γ0), intact (1 or 0), and the mark of a cell that gave way this step (1 or 0). */
export const FLOW_FILM = texelRecord('TFC_FLOW_FILM', { ETA: 1, GAMMA: 1, INTACT: 1, MARK: 1 });
/** A cell's centre (unit) and area. */
export const CELL_GEOMETRY = texelRecord('TFC_CELL_GEOMETRY', { CENTER: 3, AREA: 1 });
/** A cell's 4 sides (−i, +i, −j, +j): the edge of each as ±(e + 1), + where the cell is the edge's A. */
export const CELL_EDGES = texelRecord('TFC_CELL_EDGES', { SIGNED_EDGES: 4 });
/** A cell's 4 sides: the cell across each. */
export const CELL_NEIGHBORS = texelRecord('TFC_CELL_NEIGHBORS', { CELLS: 4 });
/** An edge's cells A and B, its length and the distance between their centres. */
export const EDGE_CELLS = texelRecord('TFC_EDGE_CELLS', { A: 1, B: 1, LENGTH: 1, DISTANCE: 1 });
/** An edge's unit normal from A to B, and (z_B − z_A)/d, the slope gravity acts along. */
export const EDGE_NORMAL = texelRecord('TFC_EDGE_NORMAL', { NORMAL: 3, Z_SLOPE: 1 });
/** An edge's midpoint (unit). */
export const EDGE_MID = texelRecord('TFC_EDGE_MID', { MID: 3 });
/** Two taps of the halo (cubeSphereSampler.glsl): each a cell and its weight. */
export const HALO_TAPS = texelRecord('TFC_HALO_TAPS', { CELL_0: 1, WEIGHT_0: 1, CELL_1: 1, WEIGHT_1: 1 });
/** An edge's velocity u·n_e (in U). */
export const EDGE_VELOCITY = texelRecord('TFC_EDGE_VELOCITY', { U: 1 });
/** A cell's tangent velocity (in U). */
export const CELL_VELOCITY = texelRecord('TFC_CELL_VELOCITY', { U: 3 });
/** An edge's prediction: u* and c_e, the Marangoni term's coefficient. */
export const PREDICTION = texelRecord('TFC_PREDICTION', { U_STAR: 1, MARANGONI: 1 });
/** A cell's weights w_e of the surfactant system, one per side. */
export const SURFACTANT_WEIGHTS = texelRecord('TFC_SURFACTANT_WEIGHTS', { SIDES: 4 });
/** A cell's row of the surfactant system: its right side b − AΓ and its diagonal. */
export const SURFACTANT_SYSTEM = texelRecord('TFC_SURFACTANT_SYSTEM', { RHS: 1, DIAGONAL: 1 });
/** A Chebyshev sweep's next iterate x_{k+1} and the iterate x_k it read (the next sweep's x_{k−1}); x the increment δ = Γ' − Γ. */
export const SURFACTANT_SWEEP = texelRecord('TFC_SURFACTANT_SWEEP', { X: 1, PREVIOUS_X: 1 });
/** A cell's transport limiter: the fraction of its outflow allowed. */
export const LIMITER = texelRecord('TFC_LIMITER', { FRACTION: 1 });
/** An edge's fluxes of η and Γ from A to B in one sub-step. */
export const FLUX = texelRecord('TFC_FLUX', { ETA: 1, GAMMA: 1 });
/** A row (face, j) of the cell atlas: how many of its cells gave way this step. */
export const RUPTURE_ROW = texelRecord('TFC_RUPTURE_ROW', { MARKS: 1 });
/** A ray of a hole (flowLayouts.ts's hole table): its rim's angular radius. */
export const HOLE_RAY = texelRecord('TFC_HOLE_RAY', { RADIUS: 1 });
/** A hole's centre (unit) and whether its slot holds a hole (1 or 0). */
export const HOLE_ORIGIN = texelRecord('TFC_HOLE_ORIGIN', { CENTER: 3, OPEN: 1 });
/** One of a hole's axes e1, e2 (unit, tangent at its centre). */
export const HOLE_AXIS = texelRecord('TFC_HOLE_AXIS', { AXIS: 3 });
/** The steps since no film was left (renewFilm.ts). */
export const BURST = texelRecord('TFC_BURST', { STEPS: 1 });

/** Every record above, each one texel. */
export const FLOW_TEXELS = [
  FLOW_FILM,
  CELL_GEOMETRY,
  CELL_EDGES,
  CELL_NEIGHBORS,
  EDGE_CELLS,
  EDGE_NORMAL,
  EDGE_MID,
  HALO_TAPS,
  EDGE_VELOCITY,
  CELL_VELOCITY,
  PREDICTION,
  SURFACTANT_WEIGHTS,
  SURFACTANT_SYSTEM,
  SURFACTANT_SWEEP,
  LIMITER,
  FLUX,
  RUPTURE_ROW,
  HOLE_RAY,
  HOLE_ORIGIN,
  HOLE_AXIS,
  BURST,
] as const;

/** The defines of the film's record: what a shader that samples the padded film (the bubble's flow field) reads it by. */
export const flowFilmDefines = (): Record<string, number> => texelRecordDefines(FLOW_FILM);

/** The defines of every record: each field's offset (`TFC_FLOW_FILM_ETA`, …). */
export const flowTexelDefines = (): Record<string, number> =>
  Object.fromEntries(FLOW_TEXELS.flatMap((r) => Object.entries(texelRecordDefines(r))));

/** The one-hot mask that picks field `offset` of a one-texel record by a dot product. */
const channelMask = (offset: number): readonly number[] => [0, 1, 2, 3].map((k) => (k === offset ? 1 : 0));

/** The first sweep's x_0 and x_{−1} (uGuessChannel, uPreviousGuessChannel): no channel, so 0 (δ starts at none). */
export const ZERO_GUESS: readonly number[] = [0, 0, 0, 0];
/** A later sweep's x_k: the x of the sweep before. */
export const SWEEP_GUESS = channelMask(SURFACTANT_SWEEP.offsets.X);
/** A later sweep's x_{k−1}: the iterate the sweep before read. */
export const SWEEP_PREVIOUS_GUESS = channelMask(SURFACTANT_SWEEP.offsets.PREVIOUS_X);
