import type { Page } from '@playwright/test';
import { expect, test } from './fixtures.ts';
import type { IlluminantSpec } from '../../src/physics/illuminants.ts';
import { MODES } from '../../src/settings/filmSettings.ts';
import { methodReads } from '../../src/methods/methods.ts';
import type { ParityMode } from '../../scripts/harness/parityCase.ts';
import { mulberry32 } from '../seededRandom.ts';
import { MAX_DELTA_E00_FIXED } from '../tolerances.ts';
import { type Case, type Group, compare, toParity } from './parityGrids.ts';

/**
 * A film's reflection of a coloured environment through the real shaders: each method computes the
 * film's environment matrix M (shaders/physics/environmentMatrix.glsl) and the harness renders
 * M · c for a colour c, in float (tests/e2e/harness/parity.ts). The reference is the float64 film
 * under the light tinted by c (src/physics/spectralIntegration.ts filmXyz with lightTint c): the
 * same product of two spectra, computed without any matrix. Held to the bound the film's own colour
 * is held to on the fixed grid.
 */

/** Colours an environment shows, linear sRGB: a sunset's orange, a sky's blue, a red sign, a teal, a park's green. */
const COLOURS: readonly (readonly [number, number, number])[] = [
  [1, 0.45, 0.1],
  [0.3, 0.55, 1],
  [0.85, 0.04, 0.03],
  [0.02, 0.45, 0.42],
  [0.15, 0.45, 0.08],
];

/**
 * Every colour over soap-like films under daylight and a fluorescent tube in every polarisation, a
 * water film, a film on gold, and (`lines`) sodium light: 0–2000 nm (1000 on gold), 0–85°.
 */
function colouredDomain(lines: boolean): Group[] {
  const next = mulberry32(7);
  const lights: readonly IlluminantSpec[] = lines ? ['D65', 'FL2', 'Na'] : ['D65', 'FL2'];
  const groups: Group[] = [];
  const cases = (maxNm: number): Case[] => {
    const c: Case[] = [
      { thicknessNm: 0, angleDeg: 0 },
      { thicknessNm: maxNm, angleDeg: 85 },
    ];
    while (c.length < 12) c.push({ thicknessNm: maxNm * next(), angleDeg: 85 * next() });
    return c;
  };
  COLOURS.forEach((environmentColor, k) => {
    for (const illuminant of lights) {
      const polarization = (['unpolarized', 's', 'p'] as const)[k % 3]!;
      groups.push({
        nOutside: 1,
        nFilm: 1.2 + 0.4 * next(),
        nInside: 1,
        illuminant,
        polarization,
        normalization: 'white',
        environmentColor,
        cases: cases(2000),
      });
    }
    groups.push({
      nOutside: 1,
      nFilm: 'water',
      nInside: 1,
      illuminant: 'D65',
      polarization: 'unpolarized',
      normalization: 'white',
      environmentColor,
      cases: cases(2000),
    });
    groups.push({
      nOutside: 1,
      nFilm: 1.38,
      nInside: 'Au',
      illuminant: 'D65',
      polarization: 'unpolarized',
      normalization: 'white',
      environmentColor,
      cases: cases(1000),
    });
  });
  return groups;
}

async function render(page: Page, groups: readonly Group[], mode: ParityMode): Promise<number[][][]> {
  return page.evaluate(([g, m]) => window.renderFilmXyz!(g, m), [groups.map(toParity), mode] as const);
}

for (const mode of MODES) {
  test(`${mode} mode reflects a coloured environment as the reference's product of two spectra, within ΔE00 ${MAX_DELTA_E00_FIXED}`, async ({
    parityPage: page,
  }) => {
    test.slow(!methodReads(mode, 'spectralTransform'), 'dispersive and tabulated films by bins');
    // Under a line source a table is not drawn (`exact` sums the lines in its place): the table's grid holds the lamps.
    const groups = colouredDomain(!methodReads(mode, 'table'));
    const { figures, nonFinite } = compare(groups, await render(page, groups, mode));
    console.log(`parity ${mode} coloured environment: ${JSON.stringify(figures)}`);
    expect(figures.cases).toBeGreaterThanOrEqual(240);
    expect(nonFinite).toEqual([]);
    expect(figures.max, figures.worst).toBeLessThanOrEqual(MAX_DELTA_E00_FIXED);
  });
}
