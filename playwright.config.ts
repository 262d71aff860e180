import { defineConfig } from '@playwright/test';
import { chromiumLaunchOptions, glBackendName, otherGlBackend, webgpuLaunchOptions } from './scripts/chromium.ts';

import { BOTH_BACKENDS } from './tests/e2e/fixtures.ts';
import { BUILT_PORT, BUILT_URL } from './tests/e2e/servers.ts';

const WEBGPU_SPEC = /webgpuBackend\.spec\.ts/;

export default defineConfig({
  testDir: 'tests/e2e',
  // Checks both WebGL2 backends before any test, and names them in the report.
  globalSetup: './tests/e2e/backendCheck.ts',
  metadata: { glBackend: glBackendName(), otherGlBackend: otherGlBackend() },
  // A test's own limit: the slowest here take ~1 min alone, ~2 min beside another worker on a busy machine.
  timeout: 300_000,
  // Assertions wait for their condition (a frame drawn, a table built), returning as soon as it
  // holds. Here the slowest first frame takes ~3 s; 60 s leaves room for a machine many times slower.
  expect: { timeout: 60_000 },
  // Tests, not files, are shared out between the workers, so the slow ones do not pile up at the end.
  fullyParallel: true,
  workers: process.env.E2E_WORKERS ? Number(process.env.E2E_WORKERS) : 2,
  // E2E_REPORT=file.json adds a JSON report (per-test times), which `npm run suite-times -- file.json` reads.
  reporter: process.env.E2E_REPORT ? [['list'], ['json', { outputFile: process.env.E2E_REPORT }]] : [['list']],
  use: {
    baseURL: BUILT_URL,
    viewport: { width: 640, height: 480 },
    launchOptions: chromiumLaunchOptions(),
  },
  // `webgl`: every spec but WebGPU's on the backend TFC_GL names. `webgpu`: WebGPU runs in a launch of
  // its own, which has no WebGL2 (docs/testing.md#webgpu): its specs alone there. `webgl-other`: the
  // tests tagged BOTH_BACKENDS on the other backend, so that neither backend rots; in the same run,
  // so that its tests share the workers, the build and the server with the rest.
  // The workers take tests in the projects' order: the longest first (WebGPU's first test is the
  // suite's longest, the other backend's are parity grids on SwiftShader), so that none of them,
  // started last, runs alone at the end.
  projects: [
    { name: 'webgpu', testMatch: WEBGPU_SPEC, use: { launchOptions: webgpuLaunchOptions() } },
    {
      name: 'webgl-other',
      testIgnore: WEBGPU_SPEC,
      grep: new RegExp(BOTH_BACKENDS),
      use: { launchOptions: chromiumLaunchOptions(otherGlBackend()) },
    },
    { name: 'webgl', testIgnore: WEBGPU_SPEC },
  ],
  webServer: {
    // One build (~5 s), then static files: no dependency optimisation or on-the-fly transforms per
    // page, as a user's browser gets the site. The element is built into the same folder.
    command: `npx vite build --mode e2e && npx vite build --mode element --outDir dist-e2e && npx vite preview --mode e2e --port ${BUILT_PORT} --strictPort --host 127.0.0.1`,
    url: `${BUILT_URL}/thin-film-bubble.js`,
    reuseExistingServer: !process.env.CI,
    timeout: 180_000,
  },
});
