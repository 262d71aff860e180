import AxeBuilder from '@axe-core/playwright';
import { expect, test, type Page } from '@playwright/test';
import { type FilmStack, filmReflectance } from '../../src/physics/filmReflectance.ts';
import { watchProblems } from './pageWatch.ts';
import { BUILT_URL } from './servers.ts';
import { GOLDEN_TOL } from '../tolerances.ts';

/**
 * <thin-film-diagram> from the built element bundle (thin-film-bubble.js) on plain pages at the
 * built site's origin. Expected values come from the float64 reference run here in Node, and the
 * golden film of docs/physics.md.
 */

/** A plain page in `lang` holding `body`, loading the element bundle with one line. */
async function plainPage(page: Page, body: string, lang = 'en'): Promise<void> {
  await page.route(`${BUILT_URL}/diagram.html`, (route) =>
    route.fulfill({
      contentType: 'text/html',
      body: `<!doctype html><html lang="${lang}"><meta charset="utf-8"><title>diagram</title>
<script type="module" src="/thin-film-bubble.js"></script><main><h1>Thin film</h1>${body}</main></html>`,
    }),
  );
  await page.goto(`${BUILT_URL}/diagram.html`);
  await page.locator('thin-film-diagram .tfd-summary').first().waitFor();
}

const reflectanceOf = (page: Page) =>
  page.locator('thin-film-diagram').evaluate((e) => (e as HTMLElement & { reflectance: number }).reflectance);
const soap = (thicknessNm: number, angleDeg: number): FilmStack => ({ nOutside: 1, nFilm: 1.33, nInside: 1, thicknessNm, angleDeg });

test('the diagram renders the golden film, follows its attributes, and names a bad one with its range as text', async ({ page }) => {
  const problems = watchProblems(page);
  await plainPage(page, '<thin-film-diagram thickness="250" nfilm="1.5" angle="0" wavelength="555" polarization="s"></thin-film-diagram>');
  const el = page.locator('thin-film-diagram');
  expect(Math.abs((await reflectanceOf(page)) - 0.1215919)).toBeLessThan(GOLDEN_TOL);
  await expect(el.locator('.tfd-summary')).toContainText('R = 0.1216');
  await expect(el.locator('.tfd-summary')).toContainText('3 beams drawn');
  await expect(el.locator('svg[role="img"] > title').first()).toContainText('thin-film interference');
  expect(await el.locator('svg line[data-beam]').count()).toBeGreaterThanOrEqual(3 + 3); // the figure's beams and the phasors'

  await el.evaluate((e) => {
    e.setAttribute('thickness', '300');
    e.setAttribute('angle', '40');
    e.setAttribute('polarization', 'unpolarized');
    e.setAttribute('nfilm', '1.33');
  });
  expect(Math.abs((await reflectanceOf(page)) - filmReflectance(555, soap(300, 40)))).toBeLessThan(1e-9);
  expect(await el.locator('.tfd-phasors svg').count()).toBe(2);

  await el.evaluate((e) => e.setAttribute('thickness', '<b>-5</b>'));
  await expect(el.locator('.tfd-errors')).toContainText('thickness');
  await expect(el.locator('.tfd-errors')).toContainText('from 0 to 20000 nm');
  expect(await el.locator('.tfd-errors b').count()).toBe(0);
  expect(Math.abs((await reflectanceOf(page)) - filmReflectance(555, soap(300, 40)))).toBeLessThan(1e-9); // the last good value kept
  expect(problems).toEqual([]);
});

test('lang=ja shows the labels, the summary and the errors in Japanese', async ({ page }) => {
  await plainPage(page, '<thin-film-diagram lang="ja" angle="95"></thin-film-diagram>');
  const el = page.locator('thin-film-diagram');
  for (const term of ['膜厚', '入射角', '偏光']) await expect(el.locator('.tfd-controls')).toContainText(term);
  await expect(el.locator('.tfd-summary')).toContainText('反射率');
  await expect(el.locator('.tfd-errors')).toContainText('angle');
  await expect(el.locator('.tfd-errors')).toContainText('使えない');
  await expect(el.locator('svg > title').first()).toContainText('薄膜干渉');
  // Without its own lang, the element speaks the page's.
  await plainPage(page, '<thin-film-diagram></thin-film-diagram>', 'ja');
  await expect(page.locator('thin-film-diagram .tfd-controls')).toContainText('膜厚');
});

test('for= follows the probe of a bubble: its thickness and angle set the diagram', async ({ page }) => {
  const problems = watchProblems(page);
  await plainPage(
    page,
    `<thin-film-bubble id="b" field="uniform" thickness="450" env="none" sides="front" animate="0" style="display:block;width:240px;height:240px"></thin-film-bubble>
<thin-film-diagram for="b" wavelength="500"></thin-film-diagram><thin-film-diagram for="nowhere"></thin-film-diagram>`,
  );
  const diagram = page.locator('thin-film-diagram').first();
  await expect(diagram).toHaveAttribute('data-reflectance', /./);
  const followed = () =>
    page.evaluate(() => {
      const bubble = document.getElementById('b') as HTMLElement & { probeReading: { thicknessNm: number; angleDeg: number } | null };
      const d = document.querySelector('thin-film-diagram') as HTMLElement & {
        settings: { thicknessNm: number; angleDeg: number };
        reflectance: number;
      };
      return { probe: bubble.probeReading, shown: d.settings, reflectance: d.reflectance };
    });
  await expect.poll(async () => (await followed()).shown.thicknessNm).toBe(450);
  const centre = await followed();
  expect(centre.shown.angleDeg).toBe(centre.probe!.angleDeg);
  expect(Math.abs(centre.reflectance - filmReflectance(500, soap(450, centre.shown.angleDeg)))).toBeLessThan(1e-9);

  await page.locator('#b').evaluate((b) => b.setAttribute('probe', '0.5,0.2'));
  await expect.poll(async () => (await followed()).shown.angleDeg).toBeGreaterThan(20);
  const rim = await followed();
  expect(rim.shown).toMatchObject(rim.probe!);
  expect(Math.abs(rim.reflectance - filmReflectance(500, soap(450, rim.shown.angleDeg)))).toBeLessThan(1e-9);
  console.log(
    `probe at the centre: θi ${centre.shown.angleDeg.toFixed(3)}°, R ${centre.reflectance}; near the rim: θi ${rim.shown.angleDeg.toFixed(2)}°`,
  );

  await expect(page.locator('thin-film-diagram').nth(1).locator('.tfd-errors')).toContainText('for="nowhere"');
  expect(problems).toEqual([]);
});

test('accessible: no axe violations, keyboard-operable controls with a visible focus, fits 390 px', async ({ page }) => {
  await page.setViewportSize({ width: 390, height: 844 });
  await plainPage(page, '<thin-film-diagram thickness="120" angle="60"></thin-film-diagram>');
  const scan = await new AxeBuilder({ page }).analyze();
  expect(scan.violations.map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`)).toEqual([]);

  const before = await reflectanceOf(page);
  const slider = page.getByLabel('wavelength λ (nm)');
  await slider.focus();
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('ArrowRight');
  await expect(slider).toHaveValue('552');
  expect(await reflectanceOf(page)).not.toBe(before);
  await page.keyboard.press('Tab');
  const focused = page.locator(':focus');
  await expect(focused).toHaveAttribute('data-attribute', 'polarization');
  expect(await focused.evaluate((e) => getComputedStyle(e).outlineStyle)).toBe('solid');
  await page.keyboard.press('Tab');
  await page.keyboard.press('Space');
  await expect(page.locator('thin-film-diagram svg').first()).toContainText('no phase flip');

  expect(await page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(390);
  const ja = await (async () => {
    await plainPage(page, '<thin-film-diagram></thin-film-diagram>', 'ja');
    return new AxeBuilder({ page }).analyze();
  })();
  expect(ja.violations.map((v) => v.id)).toEqual([]);
});
