import type { Page } from '@playwright/test';

/**
 * Collects console errors and warnings and uncaught page errors. Chrome's advice to set
 * willReadFrequently, drawn by the tests' own repeated getImageData reads, is not the page's.
 */
export function watchProblems(page: Page): string[] {
  const problems: string[] = [];
  page.on('console', (m) => {
    if ((m.type() === 'error' || m.type() === 'warning') && !m.text().includes('willReadFrequently'))
      problems.push(`${m.type()}: ${m.text()}`);
  });
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  return problems;
}

/** Makes the page's browser one without WebGL (getContext gives null for webgl2 and webgl), from before any script runs. */
export async function withoutWebGL(page: Page): Promise<void> {
  await page.addInitScript(() => {
    // eslint-disable-next-line @typescript-eslint/unbound-method -- wrapped below and called with .call(this)
    const getContext = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function (this: HTMLCanvasElement, kind: string, ...rest: unknown[]) {
      return kind === 'webgl2' || kind === 'webgl' ? null : (getContext as (...a: unknown[]) => unknown).call(this, kind, ...rest);
    } as typeof getContext;
  });
}
