import { expect, type Page } from '@playwright/test';

/** The demo's lil-gui panel title (the button that opens and closes it). */
export const panelTitle = (page: Page) => page.locator('.lil-gui.lil-root > .lil-title');

/** Opens the demo's panel, which starts closed on a view as small as the tests' (index.html's media query). */
export async function openPanel(page: Page): Promise<void> {
  await expect(panelTitle(page)).toHaveAttribute('aria-expanded', 'false');
  await panelTitle(page).click();
  await expect(panelTitle(page)).toHaveAttribute('aria-expanded', 'true');
}
