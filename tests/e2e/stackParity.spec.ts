import { BOTH_BACKENDS, expect, test } from './fixtures.ts';
import { deltaE00 } from '../../src/physics/colorDifference.ts';
import { type FilmLayer, resolveLayers } from '../../src/physics/stackFilms.ts';
import type { Polarization } from '../../src/physics/filmReflectance.ts';
import { cosDeg } from '../../src/physics/snell.ts';
import { layersXyz } from '../../src/physics/stackColor.ts';
import { whiteXyz } from '../../src/physics/spectralIntegration.ts';
import type { Xyz } from '../../src/physics/spectralWeights.ts';
import { deltaStats } from '../../scripts/harness/deltaStats.ts';
import type { ParityGroup } from '../../scripts/harness/parityCase.ts';
import { MAX_DELTA_E00_STACK } from '../tolerances.ts';

/**
 * Stacks of films on the GPU as numbers: `exact` (shaders/physics/transferMatrix.glsl per
 * fragment) and `table` (the table pass filled by the same recursion, then the bubble's lookup)
 * render XYZ into a float target (tests/e2e/harness/parity.ts); the float64 transfer matrix
 * (src/physics/transferMatrix.ts) gives the reference; they are compared by ΔE00 under D65's white.
 */

const repeat = (layers: readonly FilmLayer[], times: number): FilmLayer[] => Array.from({ length: times }, () => layers).flat();

/**
 * A TiO₂/SiO₂-like Bragg mirror, a quarter-wave MgF₂ coating, a nacre-like stack that follows the
 * field: at 400 nm, and between the table's columns below it (the table's grid ends at the
 * largest thickness of a group, as the bubble's ends at its field's).
 */
const STACKS: readonly { name: string; layers: FilmLayer[]; nInside: number; thicknessesNm: number[]; polarizations: Polarization[] }[] = [
  {
    name: 'Bragg (2.35:56.6/1.46:91.1)*8 on 1.52',
    layers: repeat(
      [
        { n: 2.35, thicknessNm: 56.6 },
        { n: 1.46, thicknessNm: 91.1 },
      ],
      8,
    ),
    nInside: 1.52,
    thicknessesNm: [0, 1000],
    polarizations: ['unpolarized', 'p'],
  },
  {
    name: 'MgF₂ 1.38:99.6 on 1.52',
    layers: [{ n: 1.38, thicknessNm: 99.6 }],
    nInside: 1.52,
    thicknessesNm: [500],
    polarizations: ['unpolarized', 's'],
  },
  {
    name: 'nacre (1.68:d/1.43:30)*10 on 1.53 at d = 333–400',
    layers: repeat(
      [
        { n: 1.68, thicknessNm: 'd' },
        { n: 1.43, thicknessNm: 30 },
      ],
      10,
    ),
    nInside: 1.53,
    thicknessesNm: [400, 361.3, 333.3],
    polarizations: ['unpolarized'],
  },
];

const ANGLES_DEG = Array.from({ length: 18 }, (_, i) => 5 * i); // 0–85°

interface Group extends ParityGroup {
  readonly name: string;
  readonly cases: readonly { thicknessNm: number; angleDeg: number }[];
}

const GROUPS: readonly Group[] = STACKS.flatMap(({ name, layers, nInside, thicknessesNm, polarizations }) =>
  polarizations.map((polarization) => {
    const cases = thicknessesNm.flatMap((thicknessNm) => ANGLES_DEG.map((angleDeg) => ({ thicknessNm, angleDeg })));
    return {
      name: `${name}, ${polarization}`,
      nOutside: 1,
      nFilm: 1.33,
      nInside,
      layers,
      illuminant: 'D65',
      polarization,
      normalization: 'white',
      cases,
      inputs: cases.map((c) => [c.thicknessNm, cosDeg(c.angleDeg)] as const),
    } as const;
  }),
);

/** The float64 reference: the stack's XYZ by the transfer matrix, sampled by its adaptive rule (layersXyz). */
const referenceXyz = (g: Group, thicknessNm: number, angleDeg: number): Xyz =>
  layersXyz({ nOutside: g.nOutside, films: resolveLayers(g.layers!, thicknessNm), nInside: g.nInside, angleDeg }, g);

const REFERENCE = GROUPS.map((g) => g.cases.map((c) => referenceXyz(g, c.thicknessNm, c.angleDeg)));

for (const mode of ['exact', 'table'] as const) {
  // Cheap on a CPU rasteriser (a second or so: a few hundred texels of the table), so both backends run it.
  test(
    `${mode} draws stacks of films within ΔE00 ${MAX_DELTA_E00_STACK} of the transfer matrix, 0–85°`,
    { tag: [BOTH_BACKENDS] },
    async ({ parityPage: page }) => {
      const rendered = await page.evaluate(([g, m]) => window.renderFilmXyz!(g, m), [
        GROUPS.map(({ cases: _, name: __, ...p }) => p),
        mode,
      ] as const);
      const deltas: number[] = [];
      const labels: string[] = [];
      const white = whiteXyz('D65', 'white');
      GROUPS.forEach((g, gi) =>
        g.cases.forEach((c, ci) => {
          const shader = rendered[gi]![ci]! as unknown as Xyz;
          const reference = REFERENCE[gi]![ci]!;
          deltas.push(deltaE00(shader, reference, white));
          labels.push(
            `${g.name} at d ${c.thicknessNm} nm, ${c.angleDeg}°: shader ${shader.map((v) => v.toFixed(5))} reference ${reference.map((v) => v.toFixed(5))}`,
          );
        }),
      );
      const stats = deltaStats(deltas);
      const worst = deltas.indexOf(stats.max);
      const perStack = GROUPS.map((g, gi) => {
        const offset = GROUPS.slice(0, gi).reduce((n, h) => n + h.cases.length, 0);
        return `${g.name}: ${Math.max(...deltas.slice(offset, offset + g.cases.length)).toFixed(4)}`;
      });
      console.log(`stack parity ${mode}: ${JSON.stringify(stats)}\n  ${perStack.join('\n  ')}`);
      expect(deltas.every(Number.isFinite)).toBe(true);
      expect(stats.max, `ΔE00 ${stats.max.toFixed(3)} at ${labels[worst]}`).toBeLessThanOrEqual(MAX_DELTA_E00_STACK);
    },
  );
}
