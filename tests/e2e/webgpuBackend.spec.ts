import { expect, test } from '@playwright/test';
import { loadOnBackend } from '../../scripts/harness/webgpuAdapter.ts';
import { watchProblems } from './pageWatch.ts';
import {
  MAX_CODE_DIFFERENCE,
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
 * The WebGPU entry (src/nodeMaterial/) on WebGPURenderer's WebGPU backend, in the launch that has
 * WebGPU and no WebGL2 (the `webgpu` project of playwright.config.ts): the pixel cases against the
 * float64 reference, as webgpu.spec.ts holds the WebGL2 backend's against it and the WebGL entry,
 * its table filled by compute, and the node film against the reference on the parity grids.
 */
test("the WebGPU entry on WebGPURenderer's WebGPU backend draws the reference's pixels and holds the parity bounds", async ({ page }) => {
  // Each method's programs for every fill and polarisation, and the tables of both grids, on SwiftShader's Vulkan.
  test.setTimeout(600_000);
  const problems = watchProblems(page);
  await openHarness(page, 'webgpu');
  // The node material's table and exact; the classic material and the thickness node, the same graphs' wiring, on the WebGL2 backend (webgpu.spec.ts).
  const node = await nodePixels(page, false);
  PIXEL_CASES.forEach((c, i) => {
    const expected = caseReference8(c);
    for (const [name, pixel] of Object.entries(node[i]!))
      expect(worstCodeDifference(pixel, expected), `${name} ${JSON.stringify(c)}: ${pixel} vs ${expected}`).toBeLessThanOrEqual(
        MAX_CODE_DIFFERENCE,
      );
  });
  await roomPixels(page);
  await optionChanges(page);
  await tableFillCalls(page, 'webgpu');
  await nodeParity(page, 'exact');
  await nodeParity(page, 'table');
  expect(problems).toEqual([]);
});

test('the materials page on WebGPURenderer (?renderer=webgpu) draws both materials and says which renderer draws them', async ({
  page,
}) => {
  // Every material's program and the environment's PMREM compiled on SwiftShader's Vulkan.
  test.setTimeout(300_000);
  const problems = watchProblems(page);
  await loadOnBackend('WebGPU', async () => {
    await page.goto('/materials.html?renderer=webgpu');
    await expect(page.locator('#readout')).toHaveText(/WebGPURenderer \((WebGPU|WebGL2)\)/);
    return /\((WebGPU|WebGL2)\)/.exec((await page.locator('#readout').textContent())!)![1]!;
  });
  await expect(page.locator('#readout')).toHaveText('WebGPURenderer (WebGPU): the probe reads pixels on WebGLRenderer only.');
  await expect(page.locator('body')).toHaveAttribute('data-frames', /[3-9]|\d\d/);
  expect(problems.filter((p) => !p.includes('WebGPU is not available'))).toEqual([]);
});
