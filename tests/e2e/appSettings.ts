import { expect, type Page } from '@playwright/test';
import type { ViewSettings } from '../../src/settings/viewParameters.ts';

/**
 * Gives the demo page new settings as its panel does (BubbleApp.set, already validated) and waits
 * for the first frame that shows them in full: one page for many views, no reload.
 */
export async function showSettings(page: Page, change: Partial<ViewSettings>, timeout?: number): Promise<void> {
  await page.evaluate((c) => {
    const app = (window as unknown as { bubbleApp: import('../../src/app/bubbleApp.ts').BubbleApp }).bubbleApp;
    document.body.dataset.frames = 'changed';
    app.set({ ...app.current, ...c });
  }, change);
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready', { timeout });
}
