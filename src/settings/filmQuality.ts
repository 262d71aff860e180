import { AIRY_SERIES_MAX_ORDERS } from '../physics/airySeries.ts';
import { isDispersiveMedium } from '../physics/medium.ts';
import type { FilmSettings } from './filmSettings.ts';
import { LAMBDA_SPAN_NM } from '../physics/spectralConventions.ts';
import { type NumberDomain, expectedNumber, isInDomain, oneOf, rejectValue } from '../input/validate.ts';
import { type FilmTableLayout, TABLE_FILLS } from './filmTableLayout.ts';

/**
 * How finely the film colour is computed, apart from the scene: the knobs the benchmark
 * (`npm run bench`) compares. The defaults are chosen from its tables (docs/benchmarks.md).
 */
export interface FilmQuality {
  /** spectral bins per fragment in `exact` mode (must divide 450) */
  readonly exactSpectralBins: number;
  /**
   * spectral bins of a dispersive film in every mode (must divide 450): the Fresnel terms per bin
   * and the bins' own approximation; enough that the binned method stays within ΔE00 0.1 of the
   * reference for water and Cauchy films on 0–2 µm in float64 (tests/unit/physics/filmIndex.test.ts)
   */
  readonly dispersiveSpectralBins: number;
  readonly table: FilmTableLayout;
  /** `auto`: float where the GPU renders to and filters float textures, else half float */
  readonly tablePrecision: 'auto' | 'half';
  /** spectral tails lighter than this fraction of the white are skipped (`significantBins`; 0 keeps all) */
  readonly spectralTailTolerance: number;
  /** the most orders of the Airy series in `fourier` mode (2, 3: the peers' truncations) */
  readonly airySeriesMaxOrders: number;
  /**
   * the most fixed steps the flowing film takes per app frame; a film behind its time takes the
   * frames after (a frame drawn without the app's budget, a test's or the render command's, takes all)
   */
  readonly flowStepsPerFrame: number;
}

export const DEFAULT_FILM_QUALITY: FilmQuality = {
  exactSpectralBins: 90,
  dispersiveSpectralBins: 150,
  table: { width: 1024, thickEndCellNm: 8, rows: 128, spectralBins: 90, thicknessPower: 2, cosPower: 2, fill: 'series' },
  tablePrecision: 'auto',
  spectralTailTolerance: 1e-5,
  airySeriesMaxOrders: AIRY_SERIES_MAX_ORDERS,
  flowStepsPerFrame: 8,
};

/** The spectral bins a film's binned integral takes: a dispersive film's own count, else `constant`'s. */
export const spectralBinsFor = (media: Pick<FilmSettings, 'nFilm' | 'nInside'>, q: FilmQuality, constant: number): number =>
  isDispersiveMedium(media.nFilm) || isDispersiveMedium(media.nInside) ? q.dispersiveSpectralBins : constant;

/** Quality knobs as a caller gives them: any of them, the table's one by one; the rest are the defaults. */
export type FilmQualityOptions = Partial<Omit<FilmQuality, 'table'>> & { readonly table?: Partial<FilmTableLayout> };

/**
 * The table's side limits: at least one step of `filmTableWidth` (64) across, at least two rows
 * (a row at each end of cos θ_i); at most 4096 texels wide and 2 × 1024 high, within what WebGL2
 * GPUs give as their largest texture.
 */
const TABLE_WIDTH = { min: 64, max: 4096, unit: 'texels' } as const;
const TABLE_ROWS = { min: 2, max: 1024, unit: 'rows' } as const;
/** A thick-end cell from 0.1 nm (far finer than colour changes) to 1 µm (one cell over a whole fringe). */
const THICK_END_CELL_NM = { min: 0.1, max: 1000, unit: 'nm' } as const;
/** The texel powers: 1 is linear; above 4 the thin or grazing end takes nearly every texel. */
const TEXEL_POWER = { min: 1, max: 4, unit: '' } as const;
/** Skipped tails: 0 keeps every bin; above 1% of the white a visible part of the spectrum would go. */
const TAIL_TOLERANCE = { min: 0, max: 0.01, unit: '' } as const;
/** Steps per frame: at least one; 1000 steps of ~30 passes are a long frame on any GPU. */
const FLOW_STEPS_PER_FRAME = { min: 1, max: 1000, unit: 'steps' } as const;
const PRECISIONS = ['auto', 'half'] as const satisfies readonly FilmQuality['tablePrecision'][];

function integerIn(field: string, value: unknown, d: NumberDomain): number {
  if (isInDomain(value, d) && Number.isInteger(value)) return value;
  return rejectValue(field, value, `an integer in [${d.min}, ${d.max}] ${d.unit}`);
}

function numberIn(field: string, value: unknown, d: NumberDomain): number {
  return isInDomain(value, d) ? value : rejectValue(field, value, expectedNumber(d));
}

/** Bins split the integral's span into whole nanometres: a count divides it. */
function spectralBinCount(field: string, value: unknown): number {
  if (isInDomain(value, { min: 1, max: LAMBDA_SPAN_NM, unit: '' }) && Number.isInteger(value) && LAMBDA_SPAN_NM % value === 0) return value;
  return rejectValue(field, value, `a whole divisor of ${LAMBDA_SPAN_NM} (spectral bins)`);
}

/**
 * The quality knobs given, each checked (a ParameterError names it as `quality.<knob>` with its
 * allowed values), over the defaults (the bubble's, or a consumer's own): the table's knobs one by
 * one over the default table.
 */
export function filmQualityFrom(o: FilmQualityOptions = {}, defaults: FilmQuality = DEFAULT_FILM_QUALITY): FilmQuality {
  const q = { ...defaults, ...o };
  const t = { ...defaults.table, ...o.table };
  return {
    exactSpectralBins: spectralBinCount('quality.exactSpectralBins', q.exactSpectralBins),
    dispersiveSpectralBins: spectralBinCount('quality.dispersiveSpectralBins', q.dispersiveSpectralBins),
    table: {
      width: integerIn('quality.table.width', t.width, TABLE_WIDTH),
      thickEndCellNm: numberIn('quality.table.thickEndCellNm', t.thickEndCellNm, THICK_END_CELL_NM),
      rows: integerIn('quality.table.rows', t.rows, TABLE_ROWS),
      spectralBins: spectralBinCount('quality.table.spectralBins', t.spectralBins),
      thicknessPower: numberIn('quality.table.thicknessPower', t.thicknessPower, TEXEL_POWER),
      cosPower: numberIn('quality.table.cosPower', t.cosPower, TEXEL_POWER),
      fill: oneOf('quality.table.fill', t.fill, TABLE_FILLS),
    },
    tablePrecision: oneOf('quality.tablePrecision', q.tablePrecision, PRECISIONS),
    spectralTailTolerance: numberIn('quality.spectralTailTolerance', q.spectralTailTolerance, TAIL_TOLERANCE),
    airySeriesMaxOrders: integerIn('quality.airySeriesMaxOrders', q.airySeriesMaxOrders, {
      min: 1,
      max: AIRY_SERIES_MAX_ORDERS,
      unit: 'orders',
    }),
    flowStepsPerFrame: integerIn('quality.flowStepsPerFrame', q.flowStepsPerFrame, FLOW_STEPS_PER_FRAME),
  };
}
