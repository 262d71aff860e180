/**
 * The benchmark's rows: every method and setting worth comparing, the two that are not ours
 * (three.js's iridescence, a plain textured sphere), and the before/after of each way the cost
 * follows the scene. Every row draws the demo's default view (swirl, both walls, sky, sRGB)
 * unless its settings say otherwise.
 */
import { DEFAULT_FILM_QUALITY, type FilmQuality } from '../../src/render/filmQuality.ts';
import { DEFAULT_SETTINGS, type FilmSettings } from '../../src/render/filmSettings.ts';
import type { FilmTableLayout } from '../../src/render/filmTableLayout.ts';

export interface BenchRow {
  readonly name: string;
  readonly kind: 'bubble' | 'textured';
  readonly settings: FilmSettings;
  readonly quality: FilmQuality;
  /** whether the error columns apply (the film colour is ours or the peer's) */
  readonly measuresError: boolean;
}

const q = DEFAULT_FILM_QUALITY;
const view = (mode: FilmSettings['mode'], more: Partial<FilmSettings> = {}) => ({ ...DEFAULT_SETTINGS, mode, ...more });
const exact = (bins: number, tails: 'skipped' | 'kept' = 'skipped'): BenchRow => ({
  name: `exact, ${bins} bins${tails === 'kept' ? ', tails kept (before)' : ''}`,
  kind: 'bubble',
  settings: view('exact'),
  quality: { ...q, exactSpectralBins: bins, spectralTailTolerance: tails === 'kept' ? 0 : q.spectralTailTolerance },
  measuresError: true,
});
const layoutName = (l: FilmTableLayout) =>
  `${l.width}×${l.rows}×2, ${l.spectralBins} bins, ${l.thicknessPower === 1 ? 'linear d' : `d ∝ u^${l.thicknessPower}`}, ${l.cosPower === 1 ? 'linear cos θ' : `cos θ ∝ v^${l.cosPower}`}`;
const table = (l: Partial<FilmTableLayout>, note = '', precision: FilmQuality['tablePrecision'] = 'auto'): BenchRow => {
  const layout = { ...q.table, ...l };
  return {
    name: `table ${layoutName(layout)}${precision === 'half' ? ', half float' : ''}${note}`,
    kind: 'bubble',
    settings: view('table'),
    quality: { ...q, table: layout, tablePrecision: precision },
    measuresError: true,
  };
};
const sceneStep = (name: string, more: Partial<FilmSettings>): BenchRow => ({
  name,
  kind: 'bubble',
  settings: view('table', more),
  quality: q,
  measuresError: false,
});

export const ROWS: readonly BenchRow[] = [
  { name: 'plain textured sphere (the floor)', kind: 'textured', settings: view('table'), quality: q, measuresError: false },
  { name: 'three.js iridescence (evalIridescence, soap film)', kind: 'bubble', settings: view('three-iridescence'), quality: q, measuresError: true },
  exact(45, 'kept'),
  exact(45),
  exact(90),
  table({ width: 1024, rows: 64, thicknessPower: 1, cosPower: 1 }, ' (before: main)'),
  table({ width: 1024, rows: 64, thicknessPower: 1, cosPower: 2 }),
  table({ width: 1024, rows: 64, thicknessPower: 2, cosPower: 2 }),
  table({ width: 2048, rows: 64, cosPower: 1.5 }, ' (the previous default)'),
  table({ width: 2048, rows: 128, cosPower: 1.5 }),
  table({ width: 1024, rows: 128, cosPower: 1.5 }),
  table({}, ' (default)'),
  table({ width: 512, rows: 32, spectralBins: 45, cosPower: 1.5 }),
  table({}, ' (default layout)', 'half'),
  sceneStep('default table, uniform field (swirl off)', { field: 'uniform' }),
  sceneStep('default table, drainage field (swirl off)', { field: 'drainage' }),
  sceneStep('default table, front wall only', { sides: 'front' }),
];
