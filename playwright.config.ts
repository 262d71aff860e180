import { existsSync } from 'node:fs';
import { defineConfig, chromium } from '@playwright/test';
import { BUILT_PORT, BUILT_URL, DEV_PORT } from './tests/e2e/servers.ts';

/**
 * Finds a Chromium by itself: CHROME_PATH if set, else Debian's /usr/bin/chromium, else the
 * browser Playwright downloads with `npx playwright install chromium`. With none of them, the
 * run stops with one line saying how to get one.
 */
function chromiumExecutable(): string | undefined {
  const fromEnv = process.env.CHROME_PATH;
  if (fromEnv) {
    if (!existsSync(fromEnv)) fail(`CHROME_PATH=${fromEnv} does not exist.`);
    return fromEnv;
  }
  if (existsSync('/usr/bin/chromium')) return '/usr/bin/chromium';
  if (existsSync(chromium.executablePath())) return undefined; // Playwright's own
  return fail('no Chromium found.');
}

function fail(why: string): never {
  console.error(
    `${why} Install one (Debian: apt-get install -y chromium; elsewhere: npx playwright install chromium) or set CHROME_PATH.`,
  );
  process.exit(1);
}

const executablePath = chromiumExecutable();
const port = DEV_PORT;

export default defineConfig({
  testDir: 'tests/e2e',
  timeout: 120_000,
  fullyParallel: false,
  workers: 1,
  reporter: [['list']],
  use: {
    baseURL: `http://127.0.0.1:${port}`,
    viewport: { width: 640, height: 480 },
    launchOptions: {
      ...(executablePath ? { executablePath } : {}),
      args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist', '--disable-quic'],
    },
  },
  webServer: [
    {
      command: `npx vite --port ${port} --strictPort --host 127.0.0.1`,
      url: `http://127.0.0.1:${port}`,
      reuseExistingServer: !process.env.CI,
      timeout: 60_000,
    },
    {
      // The built site and element, served statically (tests/e2e/built.spec.ts).
      command: `npx vite build && npx vite build --mode element && npx vite preview --port ${BUILT_PORT} --strictPort --host 127.0.0.1`,
      url: `${BUILT_URL}/thin-film-bubble.js`,
      reuseExistingServer: !process.env.CI,
      timeout: 180_000,
    },
  ],
});
