import { expect, test } from './fixtures.ts';
import { FIELDS } from '../../src/settings/filmSettings.ts';
import { thicknessAt } from '../../src/fields/fields.ts';
import { DEFAULT_SETTINGS } from '../../src/settings/filmParameters.ts';
import { mulberry32 } from '../seededRandom.ts';
import { THICKNESS_TWIN_RELATIVE, THICKNESS_TWIN_TOL_NM } from '../tolerances.ts';
import type { FieldSettings } from './harness/thicknessFieldProbe.ts';

/** Points spread over the unit sphere (seeded), the black-film cap and the poles included. */
function spherePoints(count: number): [number, number, number][] {
  const random = mulberry32(7);
  const points: [number, number, number][] = [
    [0, 1, 0],
    [0, -1, 0],
    [1, 0, 0],
    [0, 0.9, Math.sqrt(1 - 0.81)],
  ];
  while (points.length < count) {
    const y = 2 * random() - 1;
    const a = 2 * Math.PI * random();
    const r = Math.sqrt(1 - y * y);
    points.push([r * Math.cos(a), y, r * Math.sin(a)]);
  }
  return points;
}

/**
 * The flowing film's twin is its film at the start, so its cases run the simulation at speed 0: the
 * seeded start (bumps across face edges and corners) on a small grid checks the shader's sampling.
 */
const SETTINGS: FieldSettings[] = FIELDS.flatMap((field) =>
  [
    { thicknessNm: 550, thicknessRangeNm: 800, swirlSpeed: 0.4, timeSeconds: 0, seed: 3 },
    { thicknessNm: 300, thicknessRangeNm: 2000, swirlSpeed: 3, timeSeconds: 123.4, seed: 11 },
    { thicknessNm: 19000, thicknessRangeNm: 20000, swirlSpeed: 10, timeSeconds: 99, seed: 0 },
  ].map((s) => ({ ...DEFAULT_SETTINGS, field, ...s, simSpeed: 0, gridN: 12 })),
);

test("the thickness field's GLSL twin equals its TypeScript twin at points all over the bubble", async ({ parityPage: page }) => {
  const points = spherePoints(400);
  let worst = 0;
  for (const s of SETTINGS) {
    const shader = await page.evaluate(([p, f]) => window.renderThickness!(p, f), [points, s] as const);
    points.forEach((p, i) => {
      const expected = thicknessAt(p, s);
      const error = Math.abs(shader[i]! - expected);
      worst = Math.max(worst, error);
      expect(error, `${s.field} ${JSON.stringify(s)} at ${p.join(',')}: shader ${shader[i]}, TypeScript ${expected}`).toBeLessThanOrEqual(
        THICKNESS_TWIN_TOL_NM + THICKNESS_TWIN_RELATIVE * expected,
      );
    });
  }
  console.log(`thickness field twins: worst difference ${worst.toFixed(4)} nm`);
});
