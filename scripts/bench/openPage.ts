/** A fresh page for the benchmark, whose waits allow for a machine far slower or busier than Playwright's 30 s default assumes. */
import type { Browser, BrowserContextOptions, Page } from '@playwright/test';

/** A loaded 2-core machine compiles the per-fragment `exact` programs for minutes. */
export const PAGE_TIMEOUT_MS = 900_000;

export async function openPage(browser: Browser, options?: BrowserContextOptions): Promise<Page> {
  const page = await browser.newPage(options);
  page.setDefaultTimeout(PAGE_TIMEOUT_MS);
  return page;
}
