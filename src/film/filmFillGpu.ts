import { type FilmFill, filmFill } from '../methods/filmFills.ts';
import { optionFilmsOf } from '../methods/filmStacks.ts';
import type { FilmQuality } from '../settings/filmQuality.ts';
import { type FilmMedia, MEDIA_KNOT_DEFINES, filmIndexMax, opaqueInsideDefines, setFilmMediaIndices, setMediaKnots } from './filmMedia.ts';
import { FILM_STACK_DEFINES, type StackedSettings, clearFilmStackUniforms, holdFilmStackTexture, stackFieldIndex } from './filmStack.ts';

type Uniforms = Record<string, { value: unknown }>;

/** What a fill (src/methods/filmFills.ts) takes on the GPU: its bins, its defines and textures, its table's grid. */
interface FillGpu {
  /** The spectral bins its integral takes; `constant` is the count the caller takes for constant media. */
  readonly spectralBins: (q: FilmQuality, constant: number) => number;
  /** The media's defines (the knots per bin, shaders/physics/medium.glsl) beside TFC_OPAQUE_INSIDE. */
  readonly mediaDefines: Readonly<Record<string, number>>;
  /** Sets the media's knots (filmMedia.ts) where its shaders read them. */
  readonly setMediaKnots: (u: Uniforms, s: StackedSettings) => void;
  /** Whether the table pass's row terms are the dispersive film's per row and bin (dispersiveRows.ts), else the series' (airySeriesRows.ts). */
  readonly dispersiveRows: boolean;
  /** The transfer matrix's defines (shaders/physics/transferMatrix.glsl). */
  readonly stackDefines: Readonly<Record<string, number>>;
  /** Points the stack's uniforms at its texture over `bins` bins for `holder`, or at none. */
  readonly updateStack: (u: Uniforms, s: StackedSettings, bins: number, holder: object) => void;
  /** The real index whose fringes in the field's thickness its table resolves; null: the same at every thickness. */
  readonly fieldIndex: (s: StackedSettings, bins: number) => number | null;
}

const none = (): void => {};
const noStack = (u: Uniforms, _s: StackedSettings, _bins: number, holder: object): void => clearFilmStackUniforms(u, holder);
const filmIndex = (s: StackedSettings): number => filmIndexMax(s.nFilm);

/**
 * Each fill's GPU side, one entry per fill. A stack has no closed-form mean over a bin's phase
 * window, so each bin is sampled at its centre, over the dispersive film's finer bins
 * (docs/gpu.md#stacks-of-films gives the figures that chose it), and each film's ñ per bin comes
 * from the stack's texture, not the media's knots. A stack's table resolves the fringes of the sum
 * of its field-following films' indices (stackFieldIndex).
 */
const FILL_GPU: Readonly<Record<FilmFill, FillGpu>> = {
  constant: {
    spectralBins: (_, constant) => constant,
    mediaDefines: {},
    setMediaKnots: none,
    dispersiveRows: false,
    stackDefines: {},
    updateStack: noStack,
    fieldIndex: filmIndex,
  },
  dispersive: {
    spectralBins: (q) => q.dispersiveSpectralBins,
    mediaDefines: MEDIA_KNOT_DEFINES,
    setMediaKnots,
    dispersiveRows: true,
    stackDefines: {},
    updateStack: noStack,
    fieldIndex: filmIndex,
  },
  stack: {
    spectralBins: (q) => q.dispersiveSpectralBins,
    mediaDefines: {},
    setMediaKnots: none,
    dispersiveRows: false,
    stackDefines: FILM_STACK_DEFINES,
    updateStack: holdFilmStackTexture,
    fieldIndex: (s, bins) => stackFieldIndex(optionFilmsOf(s), bins),
  },
};

/** The GPU side of the fill of `s`. */
export const fillGpu = (s: StackedSettings): FillGpu => FILL_GPU[filmFill(s)];

/** The spectral bins a film's integral takes (`constant`: the count for constant media). */
export const filmSpectralBins = (s: StackedSettings, q: FilmQuality, constant: number): number => fillGpu(s).spectralBins(q, constant);

/** The defines of a film-colour shader for these media: its fill's, and TFC_OPAQUE_INSIDE where the inside absorbs. */
export const filmMediaDefines = (s: StackedSettings): Record<string, number> => ({ ...fillGpu(s).mediaDefines, ...opaqueInsideDefines(s) });

/** The defines of transferMatrix.glsl for the fill of `s` (none for a single film). */
export const filmStackDefines = (s: StackedSettings): Record<string, number> => ({ ...fillGpu(s).stackDefines });

/** Sets the media's uniforms (filmMediaUniforms) to `s`: the three indices at the D line, and the knots where its fill reads them. */
export function updateFilmMediaUniforms(u: Uniforms, s: FilmMedia & StackedSettings): void {
  setFilmMediaIndices(u, s);
  fillGpu(s).setMediaKnots(u, s);
}

/** Points transferMatrix.glsl's uniforms at the stack of `s` over `bins` bins, held for `holder`, or at none for a single film. */
export const updateFilmStackUniforms = (u: Uniforms, s: StackedSettings, bins: number, holder: object): void =>
  fillGpu(s).updateStack(u, s, bins, holder);
