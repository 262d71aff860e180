import { test, expect } from '@playwright/test';

test('the demo page loads with its title and a WebGL2 context', async ({ page }) => {
  await page.goto('/');
  await expect(page).toHaveTitle(/thin-film-color/);
  await expect(page.locator('body')).toHaveAttribute('data-webgl2', 'yes');
});
