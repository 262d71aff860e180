import { existsSync } from 'node:fs';
import { chromium } from '@playwright/test';

/** Playwright's launch options for a Chromium (executablePath left out: Playwright's own). */
export interface ChromiumLaunchOptions {
  executablePath?: string;
  args: string[];
}

/** The Chromium found, as launch options, or one line saying why none was found and how to get one. */
export type ChromiumSearch = { readonly found: ChromiumLaunchOptions } | { readonly missing: string };

/** WebGL2 headless on SwiftShader (docs/browser.md#launch-flags); the first also enables the timer query. */
export const CHROMIUM_ARGS = ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist', '--disable-quic'];

const found = (executablePath: string | undefined): ChromiumSearch => ({
  found: { ...(executablePath ? { executablePath } : {}), args: CHROMIUM_ARGS },
});
const missing = (why: string): ChromiumSearch => ({
  missing: `${why} Install one (Debian: apt-get install -y chromium; elsewhere: npx playwright install chromium) or set CHROME_PATH.`,
});

/**
 * The Chromium that the browser tests, the benchmark and the render command launch: CHROME_PATH
 * if set, else Debian's /usr/bin/chromium, else the browser Playwright downloads with
 * `npx playwright install chromium`.
 */
export function findChromium(): ChromiumSearch {
  const fromEnv = process.env.CHROME_PATH;
  if (fromEnv) return existsSync(fromEnv) ? found(fromEnv) : missing(`CHROME_PATH=${fromEnv} does not exist.`);
  if (existsSync('/usr/bin/chromium')) return found('/usr/bin/chromium');
  if (existsSync(chromium.executablePath())) return found(undefined);
  return missing('no Chromium found.');
}

/** Launch options for the tests and the benchmark: with no Chromium, the run stops (exit 1) with the line saying how to get one. */
export function chromiumLaunchOptions(): ChromiumLaunchOptions {
  const search = findChromium();
  if ('found' in search) return search.found;
  console.error(search.missing);
  return process.exit(1);
}
