import { chromium } from '@playwright/test';
import { checkedRenderer, chromiumLaunchOptions, glBackendName, otherGlBackend } from '../../scripts/chromium.ts';

/**
 * Playwright's global setup: launches the Chromium the tests will use on each WebGL backend they
 * run on (the one TFC_GL names, and the other for the `@both-backends` tests) and checks that its
 * WebGL2 renderer is that backend (a silent fall back to another backend, or to no WebGL2, stops
 * the run before any test), and says which at the head of the report.
 */
export default async function backendCheck(): Promise<void> {
  for (const backend of [glBackendName(), otherGlBackend()]) {
    const browser = await chromium.launch(chromiumLaunchOptions(backend));
    try {
      console.log(await checkedRenderer(browser, backend));
    } finally {
      await browser.close();
    }
  }
}
