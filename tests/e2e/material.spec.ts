import { expect, test } from '@playwright/test';
import type { WebGLInfo } from 'three';
import { MAX_CODE_DIFFERENCE, reference8, worstCodeDifference, xyzTo8 } from './referenceColor.ts';
import { PHYSICAL_MATERIAL_CODES } from '../tolerances.ts';
import { watchProblems } from './pageWatch.ts';
import type { FilmCase } from './harness/filmCaseScene.ts';
import { FILM_STACK_DOMAIN } from '../../src/physics/filmReflectance.ts';
import { type LinearRgb, artistMetalMedium } from '../../src/physics/artistMetal.ts';
import { XYZ_TO_LINEAR_SRGB, applyMatrix3, encode8, srgbDecode } from '../../src/physics/colorConversions.ts';
import { filmXyz } from '../../src/physics/spectralIntegration.ts';
import { type Medium } from '../../src/physics/medium.ts';
import { WEBGPU_ENTRY } from '../../src/meshMaterial/nodeRendererWarning.ts';

/**
 * The spectral iridescence (src/meshMaterial/spectralIridescence.ts) in three.js scenes, one harness
 * page (tests/e2e/harness/material.ts) for every check: the film's pixel against the float64
 * reference on a box, through a glTF round trip, the rest of the physical material untouched, and
 * the programs and textures as materials come and go, and a table rebuilt after a lost context.
 */

/**
 * A soap film on glass, a higher-index film on a lower-index base (a minimum at normal incidence),
 * and a film on a gold-coloured metal (metalness 1: the metal from its colour, edge tint the colour).
 */
const CASES: readonly FilmCase[] = [
  { thicknessNm: 450, angleDeg: 20, nFilm: 1.33, ior: 1.5 },
  { thicknessNm: 280, angleDeg: 50, nFilm: 1.8, ior: 1.4 },
  { thicknessNm: 300, angleDeg: 30, nFilm: 1.5, ior: 1.5, metalColor: 0xffc356 },
];
const insideOf = (c: FilmCase): Medium => {
  if (c.metalColor === undefined) return c.ior;
  const rgb = [16, 8, 0].map((shift) => srgbDecode(((c.metalColor! >> shift) & 0xff) / 255)) as unknown as LinearRgb;
  return artistMetalMedium(rgb, rgb);
};
const referenceOf = (c: FilmCase) =>
  reference8({ thicknessNm: c.thicknessNm, angleDeg: c.angleDeg, nOutside: 1, nFilm: c.nFilm, nInside: insideOf(c) });

test('the spectral iridescence on three.js meshes: reference colour, glTF, the physical material kept, programs, as a three.js user, context restore', async ({
  page,
}) => {
  // SwiftShader compiles each mode's program, the soak's, the three.js user's and again after the context restore: room for a slower machine.
  test.setTimeout(300_000);
  const problems = watchProblems(page);
  await page.goto('/tests/e2e/harness/material.html');
  await expect(page.locator('body')).toHaveAttribute('data-ready', 'yes');

  // The page's first spectral material: once whenSpectralReady is kept (the film's drawing loaded
  // apart), the next frame shows the settled film, the reference's colour, as later frames do.
  const ready = await page.evaluate((c) => window.materialHarness!.readyPixels(c), CASES[0]!);
  expect(ready.next, `after ${ready.waited} frames waiting`).toEqual(ready.settled);
  expect(worstCodeDifference(ready.next, referenceOf(CASES[0]!))).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);

  // A uniform film on a box's face, lit by constant radiance (env=none's white), in every mode.
  for (const c of CASES) {
    const expected = referenceOf(c);
    for (const mode of ['table', 'fourier', 'exact'] as const) {
      const pixel = await page.evaluate(([c, mode]) => window.materialHarness!.filmPixel(c, { mode }), [c, mode] as const);
      expect(worstCodeDifference(pixel, expected), `${JSON.stringify(c)} ${mode}: ${pixel} vs ${expected}`).toBeLessThanOrEqual(
        MAX_CODE_DIFFERENCE,
      );
    }
  }

  // In a uniform coloured room (scene.environment) the film reflects the room's light through its
  // environment matrix: the reference under the light tinted by that colour, a spectrum, where
  // three's lighting would take the film's colour times the room's per channel.
  const room = [0.9, 0.3, 0.1] as const;
  let productOff = 0;
  for (const c of CASES) {
    const stack = { thicknessNm: c.thicknessNm, angleDeg: c.angleDeg, nOutside: 1, nFilm: c.nFilm, nInside: insideOf(c) };
    const expected = xyzTo8(filmXyz(stack, { lightTint: room }), XYZ_TO_LINEAR_SRGB);
    const product = applyMatrix3(XYZ_TO_LINEAR_SRGB, filmXyz(stack)).map((v, i) => encode8(Math.min(1, Math.max(0, v * room[i]!))));
    productOff = Math.max(productOff, worstCodeDifference(product, expected));
    for (const mode of ['table', 'fourier', 'exact'] as const) {
      const spectral = await page.evaluate(([c, room, mode]) => window.materialHarness!.roomPixel(c, room, { mode }), [
        c,
        room,
        mode,
      ] as const);
      console.log(`${JSON.stringify(c)} ${mode} in a room of ${room}: ${spectral}, reference ${expected}, RGB product ${product}`);
      expect(
        worstCodeDifference(spectral, expected),
        `${JSON.stringify(c)} ${mode} in a room of ${room}: ${spectral} vs ${expected}`,
      ).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
    }
  }

  // The product of RGB triples is told apart from the spectral product here.
  expect(productOff).toBeGreaterThan(3 * MAX_CODE_DIFFERENCE);

  // The same film written as KHR_materials_iridescence by GLTFExporter, loaded by GLTFLoader, upgraded with one call.
  const gltf = await page.evaluate((c) => window.materialHarness!.gltfPixel(c), CASES[0]!);
  expect(gltf.extension).toBe(true);
  expect(gltf.upgraded).toBe(1);
  expect(worstCodeDifference(gltf.pixel, referenceOf(CASES[0]!))).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);

  // Everything else of the physical material is three's: lights, shadows, normal map, clearcoat, environment, tone mapping.
  for (const [iridescence, maximumNm] of [
    [0, 400],
    [1, 0],
  ] as const) {
    const worst = await page.evaluate(([i, d]) => window.materialHarness!.againstPhysical(i, d), [iridescence, maximumNm] as const);
    expect(worst, `iridescence ${iridescence}, thickness ${maximumNm} nm`).toBeLessThanOrEqual(PHYSICAL_MATERIAL_CODES);
  }

  // One program per configuration (4 table materials: theirs and the table pass's; then one per
  // other mode); after dispose, none left; and a soak of 12 materials of every mode and light.
  const counts = await page.evaluate(() => window.materialHarness!.programCounts(4, 12));
  expect(counts.sameFilm.programs - counts.before.programs).toBe(2);
  expect(counts.threeModes.programs - counts.before.programs).toBe(4);
  expect(counts.disposed).toEqual(counts.before);
  expect(counts.most - counts.before.programs).toBeLessThanOrEqual(4);
  expect(counts.after).toEqual(counts.before);

  // As a three.js user: a material chained through two other onBeforeCompile users draws the film
  // (both users' edits compiled with it); an option change and back keeps its program and table
  // with no dispose event; its clone and its JSON loaded back draw the same; an out-of-range
  // iridescenceIOR is drawn as its range's end, with one warning, and nothing thrown.
  const ior = { given: 5, drawn: FILM_STACK_DOMAIN.nFilm.max };
  const user = await page.evaluate(([c, ior]) => window.materialHarness!.threeJsUserPixels(c, ior), [CASES[0]!, ior] as const);
  expect(user.ran).toEqual(['first', 'second']);
  expect(worstCodeDifference(user.chained, referenceOf(CASES[0]!)), `chained: ${user.chained}`).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
  expect(user.change).toEqual({ versions: 2, programs: 0, sameTable: true, disposed: [] });
  for (const pixel of [user.changed, user.cloned, user.load.pixel]) expect(pixel).toEqual(user.chained);
  expect(user.load.isThinFilmMaterial).toBe(true);
  expect(user.thrown).toBe('');
  expect(user.outOfRange).toEqual(user.atDomainEnd);
  expect(worstCodeDifference(user.atDomainEnd, user.chained)).toBeGreaterThan(MAX_CODE_DIFFERENCE); // the index is drawn
  const clampWarning = (p: string) => p.startsWith('warning: spectralIridescence: iridescenceIOR 5 ');
  expect(problems.filter(clampWarning)).toHaveLength(1);
  problems.splice(0, problems.length, ...problems.filter((p) => !clampWarning(p)));

  // Drawn by three's WebGPURenderer (its WebGL2 backend here), which calls none of the material's
  // hooks: the material says so once, naming the WebGPU entry; three's own material says nothing.
  const node = await page.evaluate((c) => window.materialHarness!.nodeRendererWarnings(c), CASES[0]!);
  expect(node.spectral).toHaveLength(1);
  expect(node.spectral[0]).toContain(WEBGPU_ENTRY);
  expect(node.threes).toEqual([]);

  // After a lost and restored context, a table-mode material draws its film again (its table
  // rebuilt; left empty it would draw black), with no change to the film.
  const restored = await page.evaluate((c) => window.materialHarness!.contextRestorePixels(c), CASES[0]!);
  expect(worstCodeDifference(restored.before, referenceOf(CASES[0]!))).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
  expect(worstCodeDifference(restored.after, referenceOf(CASES[0]!)), `after restore: ${restored.after}`).toBeLessThanOrEqual(
    MAX_CODE_DIFFERENCE,
  );

  // The example page draws both materials under its HDR environment and reports their ΔE00 at the probe.
  await page.goto('/materials.html');
  await expect(page.locator('body')).toHaveAttribute('data-frames', /\d+/);
  await expect(page.locator('#readout')).toHaveText(/three\.js\s+#[0-9a-f]{6}, spectral\s+#[0-9a-f]{6}; ΔE00 \d+\.\d/);
  // Its stacks of films, a coated lens and a nacre shell, drawn by the spectral material with `layers`
  // in every view (three.js has no stack): the stack's table pass compiled without a diagnostic (any
  // warning would also be among `problems`); the lens reflects little (R ≈ 1 %: measured #020200
  // against the bright park behind it), the shell its table's colour (an empty table draws black).
  const stacks = await page.evaluate(() => {
    const materials = window.materialsPage!;
    const pixels = (view: 'three.js' | 'spectral') => {
      materials.draw(view);
      return ['coated lens', 'nacre shell'].map((name) => materials.pixelOf(name));
    };
    const [threes, ours] = [pixels('three.js'), pixels('spectral')];
    // The page's default renderer: WebGLRenderer.
    const passes = (materials.renderer.info as WebGLInfo).programs!.filter((p) => p.cacheKey.includes('TFC_FILM_LAYERS'));
    return { threes, ours, passes: passes.map((p) => (p as { diagnostics?: unknown }).diagnostics ?? null) };
  });
  expect(stacks.threes).toEqual(stacks.ours);
  const [lens, shell] = stacks.ours;
  expect(Math.max(...lens!), `coated lens ${lens}`).toBeLessThanOrEqual(16);
  expect(Math.max(...shell!), `nacre shell ${shell}`).toBeGreaterThan(40);
  expect(stacks.passes).toEqual([null]);
  expect(problems).toEqual([]);
});

test("the materials page's films on metals: the titanium slider, by keyboard, thickens the oxide, recolours the coin and says the voltage", async ({
  page,
}) => {
  const problems = watchProblems(page);
  await page.goto('/materials.html');
  await expect(page.locator('#readout')).toHaveText(/ΔE00/);
  const slider = page.getByRole('slider', { name: 'anodized titanium, oxide thickness' });
  await expect(slider).toHaveValue('60');
  // 60 nm at 2 nm/V: 30 V; at 2.8 and 1.6 nm/V, 21 and 38 V (rounded to whole volts)
  await expect(page.locator('#titanium-value')).toHaveText('TiO₂ 60 nm ≈ 30 V (21–38 V for 1.6–2.8 nm/V)');
  const coin = () => page.evaluate(() => (window.materialsPage!.draw('side by side'), window.materialsPage!.pixelOf('anodized titanium')));
  const before = await coin();
  const frames = Number(await page.locator('body').getAttribute('data-frames'));
  await slider.focus();
  for (let i = 0; i < 40; i++) await page.keyboard.press('ArrowRight');
  await expect(slider).toHaveValue('100');
  await expect(slider).toHaveAttribute('aria-valuetext', 'TiO₂ 100 nm ≈ 50 V (36–63 V for 1.6–2.8 nm/V)');
  await expect(page.locator('body')).not.toHaveAttribute('data-frames', String(frames));
  const after = await coin();
  // The reference's colours of TiO₂ on Ti head-on: blue at 60 nm (#5580b5), pale at 100 nm (#c2cec1).
  expect(after[0]! - before[0]!, `${before} → ${after}`).toBeGreaterThan(30);
  expect(problems).toEqual([]);
});
