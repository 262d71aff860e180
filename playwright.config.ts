import { defineConfig } from '@playwright/test';
import { chromiumLaunchOptions } from './scripts/chromium.ts';

import { BUILT_PORT, BUILT_URL, DEV_PORT } from './tests/e2e/servers.ts';

const port = DEV_PORT;

export default defineConfig({
  testDir: 'tests/e2e',
  timeout: 120_000,
  // Assertions wait for their condition (a frame drawn, a table built), returning as soon as it
  // holds. Here the slowest first frame takes ~3 s; 60 s leaves room for a machine many times slower.
  expect: { timeout: 60_000 },
  fullyParallel: false,
  workers: 1,
  reporter: [['list']],
  use: {
    baseURL: `http://127.0.0.1:${port}`,
    viewport: { width: 640, height: 480 },
    launchOptions: chromiumLaunchOptions(),
  },
  webServer: [
    {
      command: `npx vite --port ${port} --strictPort --host 127.0.0.1`,
      url: `http://127.0.0.1:${port}`,
      reuseExistingServer: !process.env.CI,
      timeout: 60_000,
    },
    {
      // The built site and element, served statically (tests/e2e/element.spec.ts).
      command: `npx vite build && npx vite build --mode element && npx vite preview --port ${BUILT_PORT} --strictPort --host 127.0.0.1`,
      url: `${BUILT_URL}/thin-film-bubble.js`,
      reuseExistingServer: !process.env.CI,
      timeout: 180_000,
    },
  ],
});
