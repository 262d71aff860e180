/**
 * The WebGPU entry's checks (src/nodeMaterial/, through tests/e2e/harness/webgpu.ts), shared by its
 * two specs: webgpu.spec.ts runs them on WebGPURenderer's WebGL2 backend in the ordinary launch,
 * where the WebGL entry draws beside it; webgpuBackend.spec.ts on its WebGPU backend, in the
 * launch that has WebGPU and no WebGL2 (docs/testing.md#webgpu).
 */
import { methodReads } from '../../src/methods/methods.ts';
import { type Page, expect } from '@playwright/test';
import { type LinearRgb, artistMetalMedium } from '../../src/physics/artistMetal.ts';
import { XYZ_TO_LINEAR_SRGB, applyMatrix3, encode8, srgbDecode } from '../../src/physics/colorConversions.ts';
import { type Medium } from '../../src/physics/medium.ts';
import { parseLayers } from '../../src/physics/stackText.ts';
import { type ResolvedLayer } from '../../src/physics/stackFilms.ts';
import { layersXyz } from '../../src/physics/stackColor.ts';
import { filmXyz } from '../../src/physics/spectralIntegration.ts';
import { type SpectralIridescenceOptions } from '../../src/meshMaterial/spectralIridescenceOptions.ts';
import { MAX_DELTA_E00_FIXED, MAX_DELTA_E00_STRESS } from '../tolerances.ts';
import { loadOnBackend } from '../../scripts/harness/webgpuAdapter.ts';
import { type FilmCase } from './harness/filmCaseScene.ts';
import { type Group, compare, fixedDomain, perTable, stressDomain, toParity } from './parityGrids.ts';
import { MAX_CODE_DIFFERENCE, worstCodeDifference, xyzTo8 } from './referenceColor.ts';

/** The same scene with the WebGL entry on WebGLRenderer and the WebGPU entry on WebGPURenderer: its centre pixel agrees to this. */
export const MAX_RENDERER_CODES = 3;

const SOAP: FilmCase = { thicknessNm: 450, angleDeg: 20, nFilm: 1.33, ior: 1.5 };
const HIGH: FilmCase = { thicknessNm: 280, angleDeg: 50, nFilm: 1.8, ior: 1.4 };
const MIRROR = '(2.35:56.6/1.46:91.1)*8';

/** Single films in each polarisation and under several lights, films on metals (from a colour, named), a stack, no film. */
export const PIXEL_CASES: readonly (readonly [FilmCase, SpectralIridescenceOptions])[] = [
  [SOAP, {}],
  [HIGH, { polarization: 's', illuminant: 'D93' }],
  [HIGH, { polarization: 'p', illuminant: 'E' }],
  [HIGH, { polarization: 'paper', illuminant: { daylightCct: 4000 } }],
  [{ thicknessNm: 300, angleDeg: 30, nFilm: 1.5, ior: 1.5, metalColor: 0xffc356 }, {}],
  [
    { thicknessNm: 120, angleDeg: 10, nFilm: 1.33, ior: 1.5 },
    { base: 'Ti', film: 'TiO2', illuminant: 'D55' },
  ],
  [SOAP, { layers: MIRROR }],
  [{ ...SOAP, thicknessNm: 0 }, {}],
  // line sources (summed over their lines; `exact` draws them, as a table would warn) and a tinted lamp
  [SOAP, { illuminant: 'Na', mode: 'exact' }],
  [HIGH, { illuminant: { lineNm: 532 }, film: 'water', mode: 'exact' }],
  [SOAP, { layers: MIRROR, illuminant: 'Na', mode: 'exact' }],
  [HIGH, { illuminant: 'FL2', lightTint: [1, 0.5, 0.2] }],
];

/** The float64 reference's 8-bit colour of a pixel case (the film over the metal of its colour, or the stack's). */
export const caseReference8 = (pixelCase: readonly [FilmCase, SpectralIridescenceOptions]): number[] =>
  xyzTo8(caseXyz(pixelCase), XYZ_TO_LINEAR_SRGB);

/** The float64 reference's linear sRGB of a pixel case, unclipped. */
const caseLinear = (pixelCase: readonly [FilmCase, SpectralIridescenceOptions]): readonly number[] =>
  applyMatrix3(XYZ_TO_LINEAR_SRGB, caseXyz(pixelCase));

/** The float64 reference's XYZ of a pixel case. */
function caseXyz([c, o]: readonly [FilmCase, SpectralIridescenceOptions]) {
  const illuminant = o.illuminant ?? 'D65';
  const metal = (hex: number): Medium => {
    const rgb = [16, 8, 0].map((shift) => srgbDecode(((hex >> shift) & 0xff) / 255)) as unknown as LinearRgb;
    return artistMetalMedium(rgb, rgb);
  };
  const nInside: Medium = (o.base as Medium | undefined) ?? (c.metalColor === undefined ? c.ior : metal(c.metalColor));
  const nFilm: Medium = (o.film as Medium | undefined) ?? c.nFilm;
  const color = { illuminant, polarization: o.polarization ?? 'unpolarized', lightTint: o.lightTint } as const;
  if (typeof o.layers === 'string') {
    const films = parseLayers('layers', o.layers) as readonly ResolvedLayer[];
    return layersXyz({ nOutside: 1, films, nInside, angleDeg: c.angleDeg }, color);
  }
  return filmXyz({ thicknessNm: c.thicknessNm, angleDeg: c.angleDeg, nOutside: 1, nFilm, nInside }, color);
}

/** Opens the harness on WebGPURenderer's `backend` (loadOnBackend: loaded again where a fresh browser's WebGPU found no adapter). */
export async function openHarness(page: Page, backend: 'webgpu' | 'webgl'): Promise<void> {
  const started = await loadOnBackend(backend, async () => {
    await page.goto('/tests/e2e/harness/webgpu.html');
    await expect(page.locator('body')).toHaveAttribute('data-ready', 'yes');
    return page.evaluate((b) => window.webgpuHarness!.start(b), backend);
  });
  if (!started) throw new Error(`WebGPURenderer found no ${backend} backend`);
}

/**
 * Each pixel case in `table` (the default) and `exact` on a node material: 8-bit codes. `wiring`:
 * also on a classic material (drawn through three's node copy of it) and in `exact` with its
 * thickness a node (iridescenceThicknessNode). Those two differ from the node material only in
 * the graph that reaches the film, which is the same on either backend: one backend checks them.
 */
export async function nodePixels(page: Page, wiring: boolean) {
  return page.evaluate(
    async ([cases, wiring]) => {
      const h = window.webgpuHarness!;
      const out: Record<string, number[]>[] = [];
      for (const [c, o] of cases) {
        const pixels: Record<string, number[]> = {
          table: (await h.nodePixel(c, 'node', o)).codes,
          exact: (await h.nodePixel(c, 'node', { ...o, mode: 'exact' })).codes,
        };
        if (wiring) {
          pixels.classic = (await h.nodePixel(c, 'classic', o)).codes;
          pixels.thicknessNode = (await h.nodePixel(c, 'thicknessNode', { ...o, mode: 'exact' })).codes;
        }
        out.push(pixels);
      }
      return out;
    },
    [PIXEL_CASES, wiring] as const,
  );
}

/**
 * In a uniform coloured room (scene.environment) the node material reflects the room's light
 * through the film's environment matrix: the reference under the light tinted by that colour, in
 * `table` and `exact`, for a soap film, a high-index film and a film on a gold-coloured metal. The
 * product of RGB triples is told apart there.
 */
export async function roomPixels(page: Page): Promise<void> {
  const room = [0.9, 0.3, 0.1] as const;
  let productOff = 0;
  for (const [c] of [PIXEL_CASES[0]!, PIXEL_CASES[1]!, PIXEL_CASES[4]!]) {
    const expected = caseReference8([c, { lightTint: room }]);
    const product = caseLinear([c, {}]).map((v, i) => encode8(Math.min(1, Math.max(0, v * room[i]!))));
    productOff = Math.max(productOff, worstCodeDifference(product, expected));
    for (const mode of ['table', 'exact'] as const) {
      const pixel = await page.evaluate(([c, room, mode]) => window.webgpuHarness!.nodePixel(c, 'node', { mode }, room), [
        c,
        room,
        mode,
      ] as const);
      console.log(`node ${mode} ${JSON.stringify(c)} in a room of ${room}: ${pixel.codes}, reference ${expected}, RGB product ${product}`);
      expect(worstCodeDifference(pixel.codes, expected), `${mode} ${JSON.stringify(c)}: ${pixel.codes} vs ${expected}`).toBeLessThanOrEqual(
        MAX_CODE_DIFFERENCE,
      );
    }
  }
  expect(productOff).toBeGreaterThan(3 * MAX_CODE_DIFFERENCE);
}

/**
 * One material's options changed between frames (a light, a method, a polarisation): each frame
 * draws what a material made with those options draws, and no change builds a program in one piece
 * inside a render (a new program is built ahead, stage by stage, by three's compileAsync), not
 * even where a second object draws the material for the first time meanwhile.
 */
export async function optionChanges(page: Page): Promise<void> {
  const [c] = PIXEL_CASES[1]!;
  const changes = [{ illuminant: 'D93' }, { mode: 'exact' }, { polarization: 's' }, { mode: 'table' }] as const;
  const { changed, fresh } = await page.evaluate(
    async ([c, changes]) => {
      const h = window.webgpuHarness!;
      const fresh = [];
      let options = {};
      for (const change of changes) {
        options = { ...options, ...change };
        fresh.push((await h.nodePixel(c, 'node', options)).codes);
      }
      return { changed: await h.changedPixels(c, changes), fresh };
    },
    [c, changes] as const,
  );
  expect(changed.codes.slice(1)).toEqual(fresh);
  expect(changed.builtInPlace).toBe(0);
}

/**
 * The table is filled by compute on the WebGPU backend and by a render pass on WebGL2: a `table`
 * material's first frame takes one compute call (WebGPU) or one render call (WebGL2) more than an
 * `exact` material's, all its colour planes at once (the film case's scene has an environment,
 * reflected through the film's matrix: three); its second frame, which draws the table it holds,
 * as many as exact's.
 */
export async function tableFillCalls(page: Page, backend: 'webgpu' | 'webgl'): Promise<void> {
  const [c] = PIXEL_CASES[0]!;
  const [exact, table] = await page.evaluate(async (c) => {
    const h = window.webgpuHarness!;
    return [await h.frameCalls(c, { mode: 'exact' }), await h.frameCalls(c, { mode: 'table' })];
  }, c);
  const fill = backend === 'webgpu' ? { compute: 1, render: 0 } : { compute: 0, render: 1 };
  expect(table[0]).toEqual({ compute: exact[0]!.compute + fill.compute, render: exact[0]!.render + fill.render });
  expect(table[1]).toEqual(exact[1]);
}

/** The node film against the float64 reference on the parity harness's fixed and stress grids, in `mode`. */
export async function nodeParity(page: Page, mode: 'exact' | 'table') {
  const grid = async (groups: Group[]) => {
    const rendered = await page.evaluate(([g, m]) => window.webgpuHarness!.nodeFilmXyz(g, m), [groups.map(toParity), mode] as const);
    return compare(groups, rendered);
  };
  const fixed = await grid(methodReads(mode, 'table') ? perTable(fixedDomain()) : fixedDomain());
  const stress = await grid(methodReads(mode, 'table') ? perTable(stressDomain()) : stressDomain());
  console.log(`node parity ${mode}: ${JSON.stringify({ fixed: fixed.figures, stress: stress.figures })}`);
  expect([...fixed.nonFinite, ...stress.nonFinite]).toEqual([]);
  expect(fixed.figures.max, fixed.figures.worst).toBeLessThanOrEqual(MAX_DELTA_E00_FIXED);
  expect(stress.figures.max, stress.figures.worst).toBeLessThan(MAX_DELTA_E00_STRESS);
}

export { MAX_CODE_DIFFERENCE, worstCodeDifference };
