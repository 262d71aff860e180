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
}

export const DEFAULT_FILM_QUALITY: FilmQuality = {
  exactSpectralBins: 90,
  table: { width: 1024, rows: 128, spectralBins: 90, thicknessPower: 2, cosPower: 2 },
  tablePrecision: 'auto',
  spectralTailTolerance: 1e-5,
};
