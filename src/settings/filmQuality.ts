import { AIRY_SERIES_MAX_ORDERS } from '../physics/airySeries.ts';
import { type FilmIndex, isDispersive } from '../physics/filmIndex.ts';
import { type FilmTableLayout } from './filmTableLayout.ts';

/**
 * How finely the film colour is computed, apart from the scene: the knobs the benchmark
 * (`npm run bench`) compares. The defaults are chosen from its table (README, Benchmarks).
 */
export interface FilmQuality {
  /** spectral bins per fragment in `exact` mode (must divide 450) */
  readonly exactSpectralBins: number;
  /**
   * spectral bins of a dispersive film in every mode (must divide 450): the Fresnel terms per bin
   * and the bins' own approximation; 90 bins are ΔE00 0.10 off in float64 on 0–2 µm, 150 are 0.04
   */
  readonly dispersiveSpectralBins: number;
  readonly table: FilmTableLayout;
  /** `auto`: float where the GPU renders to and filters float textures, else half float */
  readonly tablePrecision: 'auto' | 'half';
  /** spectral tails lighter than this fraction of the white are skipped (`significantBins`; 0 keeps all) */
  readonly spectralTailTolerance: number;
  /** the most orders of the Airy series in `fourier` mode (2, 3: the peers' truncations) */
  readonly airySeriesMaxOrders: number;
}

export const DEFAULT_FILM_QUALITY: FilmQuality = {
  exactSpectralBins: 90,
  dispersiveSpectralBins: 150,
  table: { width: 1024, thickEndCellNm: 8, rows: 128, spectralBins: 90, thicknessPower: 2, cosPower: 2, fill: 'series' },
  tablePrecision: 'auto',
  spectralTailTolerance: 1e-5,
  airySeriesMaxOrders: AIRY_SERIES_MAX_ORDERS,
};

/** The spectral bins a film's binned integral takes: a dispersive film's own count, else `constant`'s. */
export const spectralBinsFor = (index: FilmIndex, q: FilmQuality, constant: number): number =>
  isDispersive(index) ? q.dispersiveSpectralBins : constant;
