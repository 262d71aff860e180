import { mkdirSync, writeFileSync } from 'node:fs';
import type { Page } from '@playwright/test';
import { BOTH_BACKENDS, expect, test } from './fixtures.ts';
import type { Medium } from '../../src/physics/medium.ts';
import { POLARIZATIONS } from '../../src/physics/filmReflectance.ts';
import type { IlluminantSpec } from '../../src/physics/illuminants.ts';
import { DEFAULT_FILM_QUALITY, type FilmQuality } from '../../src/settings/filmQuality.ts';
import { MODES } from '../../src/settings/filmSettings.ts';
import { methodReads } from '../../src/methods/methods.ts';
import type { ParityMode } from '../../scripts/harness/parityCase.ts';
import { mulberry32 } from '../seededRandom.ts';
import {
  MAX_DELTA_E00_FIXED,
  MAX_DELTA_E00_LAMP_EXACT_STRESS,
  MAX_DELTA_E00_METAL_FIXED,
  MAX_DELTA_E00_METAL_STRESS,
  MAX_DELTA_E00_STRESS,
} from '../tolerances.ts';
import { type Case, type Group, compare, fixedDomain, perTable, stressDomain, toParity } from './parityGrids.ts';

/**
 * Shader parity as numbers: the real GLSL (shaders/film/filmColor.glsl, every mode of MODES)
 * renders film XYZ into a float target (tests/e2e/harness/parity.ts); the float64 reference
 * (src/physics/spectralIntegration.ts filmXyz, adaptive and converged) computes the same cases;
 * they are compared by ΔE00 under the case's illuminant white.
 */

async function render(
  page: Page,
  groups: readonly Group[],
  mode: ParityMode,
  quality: FilmQuality = DEFAULT_FILM_QUALITY,
): Promise<number[][][]> {
  return page.evaluate(([g, m, q]) => window.renderFilmXyz!(g, m, q), [groups.map(toParity), mode, quality] as const);
}

/** Keeps a test's figures in tests/e2e/parity-figures/ (git-ignored), one file per test, so the tests can run in any worker. */
function keepFigures(name: string, figures: unknown): void {
  const folder = new URL('./parity-figures/', import.meta.url);
  mkdirSync(folder, { recursive: true });
  writeFileSync(new URL(`${name}.json`, folder), `${JSON.stringify(figures, null, 2)}\n`);
}

for (const mode of MODES) {
  const tag = methodReads(mode, 'table') ? [BOTH_BACKENDS] : [];
  test(
    `${mode} mode matches the reference within ΔE00 ${MAX_DELTA_E00_FIXED} on 0–2000 nm, 0–85°`,
    { tag },
    async ({ parityPage: page }) => {
      test.slow(!methodReads(mode, 'spectralTransform'), 'dispersive films by bins');
      const groups = methodReads(mode, 'table') ? perTable(fixedDomain()) : fixedDomain();
      const { figures, nonFinite } = compare(groups, await render(page, groups, mode));
      keepFigures(`${mode}-fixed`, figures);
      console.log(`parity ${mode} fixed: ${JSON.stringify(figures)}`);
      expect(figures.cases).toBeGreaterThanOrEqual(1000);
      expect(nonFinite).toEqual([]);
      expect(figures.max, figures.worst).toBeLessThanOrEqual(MAX_DELTA_E00_FIXED);
    },
  );

  test(`${mode} mode stays finite and close on thick, grazing and TIR films`, async ({ parityPage: page }) => {
    // The dispersive 20 µm films' tables sum 150 bins per texel over 1024 × 256 texels: over two minutes on a busy CPU rasteriser.
    test.slow(!methodReads(mode, 'spectralTransform'), 'dispersive films by bins');
    const groups = methodReads(mode, 'table') ? perTable(stressDomain()) : stressDomain();
    const { figures, nonFinite } = compare(groups, await render(page, groups, mode));
    keepFigures(`${mode}-stress`, figures);
    console.log(`parity ${mode} stress: ${JSON.stringify(figures)}`);
    expect(nonFinite).toEqual([]);
    expect(figures.max, figures.worst).toBeLessThan(MAX_DELTA_E00_STRESS);
  });
}

/**
 * Lamps and line sources (docs/physics.md#lights): a fluorescent and an LED table in every
 * polarisation over the fixed grid, sodium and a helium–neon line too, and each light on water
 * and on 20 µm films near grazing, where under a line the fringes never wash out (`lampsOnly`: the
 * lamps alone, for the table, which a line source does not draw).
 */
function lightsDomain(lampsOnly: boolean): { fixed: Group[]; stress: Group[] } {
  const next = mulberry32(4);
  const lamps: readonly IlluminantSpec[] = ['FL2', 'LED-V1'];
  const lines: readonly IlluminantSpec[] = ['Na', { lineNm: 632.8 }];
  const lights = lampsOnly ? lamps : [...lamps, ...lines];
  const fixed: Group[] = [];
  for (const illuminant of lights) {
    for (const polarization of POLARIZATIONS) {
      const cases: Case[] = [
        { thicknessNm: 0, angleDeg: 0 },
        { thicknessNm: 2000, angleDeg: 85 },
      ];
      while (cases.length < 16) cases.push({ thicknessNm: 2000 * next(), angleDeg: 85 * next() });
      const normalization = fixed.length % 4 === 3 ? 'paper' : 'white';
      fixed.push({ nOutside: 1, nFilm: 1.2 + 0.4 * next(), nInside: 1, illuminant, polarization, normalization, cases });
    }
  }
  const stress: Group[] = [];
  for (const illuminant of lights) {
    for (const [nFilm, maxNm] of [
      [1.33, 20000],
      ['water', 2000],
    ] as const) {
      const cases: Case[] = [
        { thicknessNm: 0, angleDeg: 90 },
        { thicknessNm: maxNm, angleDeg: 89.9 },
      ];
      while (cases.length < 16) cases.push({ thicknessNm: maxNm * next(), angleDeg: 89.9 * next() });
      stress.push({ nOutside: 1, nFilm, nInside: 1, illuminant, polarization: 'unpolarized', normalization: 'white', cases });
    }
  }
  return { fixed, stress };
}

for (const mode of MODES) {
  // The binned integral per fragment (neither a transform nor a table) draws a lamp's lasting fringes by its bins' windows: its own bound.
  const byBins = methodReads(mode, 'spectralBins') && !methodReads(mode, 'spectralTransform');
  const stressBound = byBins ? MAX_DELTA_E00_LAMP_EXACT_STRESS : MAX_DELTA_E00_STRESS;
  test(`${mode} mode under lamps and lines matches the reference within ΔE00 ${MAX_DELTA_E00_FIXED} (0–2000 nm, 0–85°) and ${stressBound} (to 20 µm, 90°)`, async ({
    parityPage: page,
  }) => {
    // Under a line source a table is not drawn: `exact` sums the lines in its place (drawnFilmMethod).
    const lights = lightsDomain(methodReads(mode, 'table'));
    const fixed = methodReads(mode, 'table') ? perTable(lights.fixed) : lights.fixed;
    const fixedResult = compare(fixed, await render(page, fixed, mode));
    const stressResult = compare(lights.stress, await render(page, lights.stress, mode));
    const figures = { fixed: fixedResult.figures, stress: stressResult.figures };
    keepFigures(`${mode}-lights`, figures);
    console.log(`parity ${mode} lights: ${JSON.stringify(figures)}`);
    expect([...fixedResult.nonFinite, ...stressResult.nonFinite]).toEqual([]);
    expect(fixedResult.figures.max, fixedResult.figures.worst).toBeLessThanOrEqual(MAX_DELTA_E00_FIXED);
    expect(stressResult.figures.max, stressResult.figures.worst).toBeLessThan(stressBound);
  });
}

/**
 * Films on absorbing insides (docs/physics.md#absorbing-media): a constant complex substrate (gold's ñ
 * at 548.6 nm; its series and table rows carry the complex r_bc), tabulated metals under a real film,
 * and absorbing films on metals (Fe3O4 on Fe, TiO2 on Ti), each in one polarisation. The fixed grid
 * covers 0–1000 nm at 0–85°; the stress grid reaches 90° and 10 µm, and a glass outside puts the
 * film's critical angle (62.5°) inside its range, with a case 0.3° short of it. The table's rows
 * interpolate across the kink R has there (R jumps to 1 within a fraction of a row,
 * docs/physics.md#absorbing-media-on-the-gpu), so `table` is held to its bound on the stress grid
 * without that stack (`tirEdge`), whose figures it records.
 */
function metalDomain(): { fixed: Group[]; stress: Group[]; tirEdge: Group[] } {
  const next = mulberry32(3);
  const gold548: Medium = { complex: [0.43, 2.455] };
  const fixedStacks: readonly (Pick<Group, 'nOutside' | 'nFilm' | 'nInside' | 'polarization'> & { readonly illuminant: IlluminantSpec })[] =
    [
      { nOutside: 1, nFilm: 1.38, nInside: gold548, polarization: 'unpolarized', illuminant: 'D65' },
      { nOutside: 1, nFilm: 1.5, nInside: gold548, polarization: 's', illuminant: 'E' },
      { nOutside: 1, nFilm: 1.33, nInside: 'Au', polarization: 'unpolarized', illuminant: 'D65' },
      { nOutside: 1, nFilm: 'Fe3O4', nInside: 'Fe', polarization: 'p', illuminant: 'D55' },
      { nOutside: 1, nFilm: 'TiO2', nInside: 'Ti', polarization: 'unpolarized', illuminant: { daylightCct: 4000 } },
    ];
  const fixed = fixedStacks.map((stack) => {
    const cases: Case[] = [
      { thicknessNm: 0, angleDeg: 0 },
      { thicknessNm: 1000, angleDeg: 85 },
    ];
    while (cases.length < 24) cases.push({ thicknessNm: 1000 * next(), angleDeg: 85 * next() });
    return { ...stack, normalization: 'white' as const, cases };
  });
  const stressStacks: readonly (Pick<Group, 'nOutside' | 'nFilm' | 'nInside' | 'polarization'> & { readonly maxNm: number })[] = [
    { nOutside: 1, nFilm: 2.5, nInside: gold548, polarization: 'unpolarized', maxNm: 10000 },
    { nOutside: 1, nFilm: 1.38, nInside: 'Al', polarization: 'unpolarized', maxNm: 10000 },
    { nOutside: 1, nFilm: 'Fe3O4', nInside: 'Fe', polarization: 'unpolarized', maxNm: 2000 },
    { nOutside: 1.5, nFilm: 1.33, nInside: { complex: [2.6, 3.4] }, polarization: 'p', maxNm: 2000 },
  ];
  const stress = stressStacks.map(({ maxNm, ...stack }) => {
    const cases: Case[] = [
      { thicknessNm: 0, angleDeg: 90 },
      { thicknessNm: maxNm, angleDeg: 89.9 },
      { thicknessNm: maxNm, angleDeg: 90 },
      { thicknessNm: 5, angleDeg: 89 },
      // 0.3° short of the film's critical angle under glass (62.5°), where R has its kink.
      ...(stack.nOutside > 1 ? [{ thicknessNm: 1570, angleDeg: 62.2 }] : []),
    ];
    while (cases.length < 16) cases.push({ thicknessNm: maxNm * next(), angleDeg: 60 + 30 * next() });
    return { ...stack, illuminant: 'D65' as const, normalization: 'white' as const, cases };
  });
  return { fixed, stress: stress.slice(0, -1), tirEdge: stress.slice(-1) };
}

for (const mode of MODES) {
  test(`${mode} mode on absorbing insides matches the reference within ΔE00 ${MAX_DELTA_E00_METAL_FIXED} (0–1000 nm, 0–85°) and ${MAX_DELTA_E00_METAL_STRESS} (to 90°, 10 µm)`, async ({
    parityPage: page,
  }) => {
    test.slow(!methodReads(mode, 'spectralTransform'), 'tabulated media by bins');
    const { fixed, stress, tirEdge } = metalDomain();
    const fixedResult = compare(fixed, await render(page, fixed, mode));
    const stressGroups = methodReads(mode, 'table') ? stress : [...stress, ...tirEdge];
    const stressResult = compare(stressGroups, await render(page, stressGroups, mode));
    const tirResult = methodReads(mode, 'table') ? compare(tirEdge, await render(page, tirEdge, mode)) : null;
    const figures = { fixed: fixedResult.figures, stress: stressResult.figures, tirEdge: tirResult?.figures };
    keepFigures(`${mode}-metal`, figures);
    console.log(`parity ${mode} metal: ${JSON.stringify(figures)}`);
    expect([...fixedResult.nonFinite, ...stressResult.nonFinite, ...(tirResult?.nonFinite ?? [])]).toEqual([]);
    expect(fixedResult.figures.max, fixedResult.figures.worst).toBeLessThanOrEqual(MAX_DELTA_E00_METAL_FIXED);
    expect(stressResult.figures.max, stressResult.figures.worst).toBeLessThanOrEqual(MAX_DELTA_E00_METAL_STRESS);
  });
}

/**
 * GPUs without float render targets get a half-float table (FilmTable picks it). Half floats keep
 * 11 significant bits, ~5e-4 relative: the table's colours must still meet the fixed-grid bound.
 * The storage precision is the same whatever filled the texels, series or bins: here the constant
 * films of both domains (perTable), which the float table's tests also hold.
 */
const constantFilms = (groups: readonly Group[]) => perTable(groups).filter((g) => typeof g.nFilm === 'number');

test(`the half-float table matches the reference within ΔE00 ${MAX_DELTA_E00_FIXED} on 0–2000 nm, 0–85°, and stays finite on the stress cases`, async ({
  parityPage: page,
}) => {
  const half = { ...DEFAULT_FILM_QUALITY, tablePrecision: 'half' } as const;
  const fixed = constantFilms(fixedDomain());
  const fixedResult = compare(fixed, await render(page, fixed, 'table', half));
  const stress = constantFilms(stressDomain());
  const stressResult = compare(stress, await render(page, stress, 'table', half));
  keepFigures('table-half', { fixed: fixedResult.figures, stress: stressResult.figures });
  console.log(`parity half-float table: ${JSON.stringify({ fixed: fixedResult.figures, stress: stressResult.figures })}`);
  expect([...fixedResult.nonFinite, ...stressResult.nonFinite]).toEqual([]);
  expect(fixedResult.figures.max, fixedResult.figures.worst).toBeLessThanOrEqual(MAX_DELTA_E00_FIXED);
  expect(stressResult.figures.max, stressResult.figures.worst).toBeLessThan(MAX_DELTA_E00_STRESS);
});
