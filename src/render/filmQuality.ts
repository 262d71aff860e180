import { AIRY_SERIES_MAX_ORDERS } from '../physics/airySeries.ts';
import { type FilmTableLayout } from './filmTableLayout.ts';

/**
 * How finely the film colour is computed, apart from the scene: the knobs the benchmark
 * (`npm run bench`) compares. The defaults are chosen from its table (README, Benchmarks).
 */
export interface FilmQuality {
  /** spectral bins per fragment in `exact` mode (must divide 450) */
  readonly exactSpectralBins: number;
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
  table: { width: 1024, thickEndCellNm: 8, rows: 128, spectralBins: 90, thicknessPower: 2, cosPower: 2, fill: 'series' },
  tablePrecision: 'auto',
  spectralTailTolerance: 1e-5,
  airySeriesMaxOrders: AIRY_SERIES_MAX_ORDERS,
};
