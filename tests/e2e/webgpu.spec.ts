import { expect, test } from '@playwright/test';
import { watchProblems } from './pageWatch.ts';
import {
  MAX_CODE_DIFFERENCE,
  MAX_RENDERER_CODES,
  PIXEL_CASES,
  caseReference8,
  nodeParity,
  optionChanges,
  roomPixels,
  nodePixels,
  openHarness,
  tableFillCalls,
  worstCodeDifference,
} from './webgpuChecks.ts';

/**
 * The WebGPU entry (src/nodeMaterial/) on WebGPURenderer's WebGL2 backend, beside the WebGL entry
 * on WebGLRenderer in the same page: the same scene's centre pixel, its table filled by a render
 * pass, and the node film against the float64 reference on the parity grids. Its WebGPU backend:
 * webgpuBackend.spec.ts.
 */
test("the WebGPU entry on WebGPURenderer's WebGL2 backend draws the WebGL entry's pixels and holds the parity bounds", async ({ page }) => {
  // Each method's programs for every fill and polarisation, and the tables of both grids, on a CPU rasteriser.
  test.setTimeout(600_000);
  const problems = watchProblems(page);
  await openHarness(page, 'webgl');
  // three's own iridescence in this scene: the same on both renderers, so any difference below is the entries'.
  const threes = await page.evaluate(async (c) => {
    const h = window.webgpuHarness!;
    return [(await h.nodePixel(c, 'three')).codes, (await h.webglPixel(c, null)).codes];
  }, PIXEL_CASES[0]![0]);
  expect(threes[0]).toEqual(threes[1]);
  const node = await nodePixels(page, true);
  const webgl = await page.evaluate(async (cases) => {
    const out = [];
    for (const [c, o] of cases) out.push((await window.webgpuHarness!.webglPixel(c, o)).codes);
    return out;
  }, PIXEL_CASES);
  PIXEL_CASES.forEach((c, i) => {
    const label = JSON.stringify(c);
    for (const [name, pixel] of Object.entries(node[i]!))
      expect(worstCodeDifference(pixel, webgl[i]!), `${name} ${label}: ${pixel} vs the WebGL entry's ${webgl[i]}`).toBeLessThanOrEqual(
        MAX_RENDERER_CODES,
      );
    expect(worstCodeDifference(node[i]!.exact!, caseReference8(c)), `${label}: ${node[i]!.exact}`).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
  });
  await roomPixels(page);
  await optionChanges(page);
  await tableFillCalls(page, 'webgl');
  await nodeParity(page, 'exact');
  await nodeParity(page, 'table');
  expect(problems).toEqual([]);
});
