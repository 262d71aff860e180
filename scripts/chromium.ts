import { existsSync } from 'node:fs';
import { chromium } from '@playwright/test';

/**
 * The Chromium that the browser tests and the benchmark launch, found by itself: CHROME_PATH if
 * set, else Debian's /usr/bin/chromium, else the browser Playwright downloads with
 * `npx playwright install chromium` (undefined: Playwright's own). With none of them, the run
 * stops with one line saying how to get one.
 */
export function chromiumExecutable(): string | undefined {
  const fromEnv = process.env.CHROME_PATH;
  if (fromEnv) {
    if (!existsSync(fromEnv)) fail(`CHROME_PATH=${fromEnv} does not exist.`);
    return fromEnv;
  }
  if (existsSync('/usr/bin/chromium')) return '/usr/bin/chromium';
  if (existsSync(chromium.executablePath())) return undefined;
  return fail('no Chromium found.');
}

/** WebGL2 headless on SwiftShader (docs/browser.md#launch-flags); the first also enables the timer query. */
export const CHROMIUM_ARGS = ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist', '--disable-quic'];

/** Playwright launch options for that Chromium. */
export function chromiumLaunchOptions(): { executablePath?: string; args: string[] } {
  const executablePath = chromiumExecutable();
  return { ...(executablePath ? { executablePath } : {}), args: CHROMIUM_ARGS };
}

function fail(why: string): never {
  console.error(`${why} Install one (Debian: apt-get install -y chromium; elsewhere: npx playwright install chromium) or set CHROME_PATH.`);
  process.exit(1);
}
