import { chromium } from '@playwright/test';
import { checkedRenderer, chromiumLaunchOptions } from '../../scripts/chromium.ts';

/**
 * Playwright's global setup: launches the Chromium the tests will use and checks that its WebGL2
 * renderer is the backend TFC_GL names (a silent fall back to another backend, or to no WebGL2,
 * stops the run before any test), and says which one at the head of the report.
 */
export default async function backendCheck(): Promise<void> {
  const browser = await chromium.launch(chromiumLaunchOptions());
  try {
    console.log(await checkedRenderer(browser));
  } finally {
    await browser.close();
  }
}
