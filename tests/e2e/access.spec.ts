import AxeBuilder from '@axe-core/playwright';
import { expect, test, type Page } from '@playwright/test';
import { englishLeftIn } from '../latinInJapanese.ts';
import { openPanel } from './panel.ts';
import { BUILT_URL } from './servers.ts';

/**
 * Access (WCAG 2.2 AA, axe's rules as the floor) and the Japanese pages: no axe violation on each
 * page; the demo by keyboard alone; no English left in the Japanese UI; reduced motion.
 */

/** A quick view for the demo: the table, no motion, no HDR map. */
const QUICK = 'mode=table&animate=0&env=none&field=uniform';

const ready = (page: Page) => expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');

async function noAxeViolations(page: Page): Promise<void> {
  const scan = await new AxeBuilder({ page }).analyze();
  expect(scan.violations.map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`)).toEqual([]);
}

/** Every text a user meets: visible text nodes, aria-labels, titles, alt texts, placeholders. */
const shownTexts = (page: Page) =>
  page.evaluate(() => {
    const texts: string[] = [];
    const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
    // Text marked as in another language (a link to the English page) is left out.
    const foreign = (e: Element) => !(e.closest('[lang]')?.getAttribute('lang') ?? '').startsWith('ja');
    for (let n = walker.nextNode(); n; n = walker.nextNode()) {
      const parent = n.parentElement!;
      if (parent.closest('script, style') || !parent.checkVisibility() || foreign(parent)) continue;
      if (n.textContent!.trim()) texts.push(n.textContent!.trim());
    }
    for (const e of document.querySelectorAll('[aria-label], [title], [alt], [placeholder]'))
      if (!foreign(e)) for (const a of ['aria-label', 'title', 'alt', 'placeholder']) if (e.getAttribute(a)) texts.push(e.getAttribute(a)!);
    // The live description, read by screen readers though not shown.
    for (const e of document.querySelectorAll('.tfb-live')) if (e.textContent) texts.push(e.textContent);
    return texts;
  });

/**
 * The texts holding English: a URL parameter and its value as typed (`thickness="abc"`) are
 * quoted as they are, so they are left out first.
 */
async function englishIn(page: Page): Promise<string[]> {
  return (await shownTexts(page)).map((t) => t.replace(/\w+="[^"]*"/g, '')).filter((t) => englishLeftIn(t).length > 0);
}

test('the demo has no axe violation with its panel, plots and spectrum table open, and none in Japanese', async ({ page }) => {
  await page.goto(`/?${QUICK}`);
  await ready(page);
  await openPanel(page);
  await page.locator('#plots-box > summary').click();
  await page.getByRole('button', { name: 'show the spectrum as a table' }).click();
  await expect(page.locator('.tfb-spectrum-table tbody tr')).toHaveCount(46);
  await noAxeViolations(page);
});

test('in Japanese the demo shows no English beyond units and symbols, with a refusal in Japanese', async ({ page }) => {
  await page.goto(`/?${QUICK}&lang=ja&thickness=abc`);
  await ready(page);
  await expect(page.locator('html')).toHaveAttribute('lang', 'ja');
  await expect(page.locator('#messages')).toContainText('thickness="abc" は使えない');
  await expect(page.locator('#messages')).toContainText('[0, 20000] nm の数値');
  await openPanel(page);
  await page.locator('#plots-box > summary').click();
  await page.getByRole('button', { name: 'スペクトルを表で見る' }).click();
  // The probe moved by a key: the live description speaks, in Japanese.
  await page.locator('#bubble').press('ArrowLeft');
  await expect(page.locator('.tfb-live')).toContainText('膜厚');
  await expect(page.getByRole('combobox', { name: '膜厚の分布' })).toBeVisible();
  expect(await englishIn(page)).toEqual([]);
  await noAxeViolations(page);
});

test('by keyboard alone: Tab reaches the bubble and every panel control, each kind is used, the arrows move the probe', async ({
  page,
}) => {
  await page.goto(`/?${QUICK}`);
  await ready(page);
  const focusedId = () =>
    page.evaluate(() => {
      const e = document.activeElement as HTMLElement | null;
      if (!e || e === document.body) return null;
      e.dataset.walk ??= String(Math.random());
      return e.dataset.walk;
    });
  // Tab to the panel's title and open it with Enter; then Tab through everything until focus comes back round.
  const seen = new Set<string>();
  let opened = false;
  for (let i = 0; i < 80; i++) {
    await page.keyboard.press('Tab');
    const id = await focusedId();
    if (id === null) continue;
    if (seen.has(id) && opened) break;
    seen.add(id);
    if (!opened && (await page.evaluate(() => document.activeElement?.matches('.lil-root > .lil-title') ?? false))) {
      await page.keyboard.press('Enter');
      await expect(page.locator('.lil-root > .lil-title')).toHaveAttribute('aria-expanded', 'true');
      await expect(page.locator('.lil-gui select').last()).toBeVisible(); // its opening transition has run
      opened = true;
    }
  }
  expect(opened).toBe(true);
  const reachable = await page.evaluate(() => {
    const all = [
      document.querySelector<HTMLElement>('#bubble')!,
      ...document.querySelectorAll<HTMLElement>('.lil-gui input, .lil-gui select, .lil-gui button, .lil-gui .lil-title'),
    ];
    return all.filter((e) => e.checkVisibility() && e.tabIndex >= 0).map((e) => e.dataset.walk ?? `${e.tagName} ${e.textContent}`);
  });
  expect(reachable.length).toBeGreaterThan(20);
  expect(reachable.filter((id) => !seen.has(id))).toEqual([]);

  // A slider moved by the arrow keys of its number field (lil-gui's keyboard way), shown focused;
  // a list changed, a checkbox toggled: the URL follows each.
  const thickness = page.getByRole('textbox', { name: 'thickness (nm)' });
  await page.getByRole('combobox', { name: 'thickness field' }).focus();
  await page.keyboard.press('Tab');
  await expect(thickness).toBeFocused();
  expect(await thickness.evaluate((e) => getComputedStyle(e).outlineStyle)).toBe('solid');
  await page.keyboard.press('ArrowUp');
  await expect(page).toHaveURL(/thickness=551/);
  await page.getByRole('combobox', { name: 'thickness field' }).focus();
  await page.keyboard.press('ArrowDown');
  await expect(page).toHaveURL(/field=drainage/);
  await page.getByRole('checkbox', { name: 'animate' }).focus();
  await page.keyboard.press('Space');
  await expect(page).toHaveURL(/^(?!.*animate=0)/);

  // The arrow keys on the bubble move the probe (Shift: further); the URL and the live description follow.
  const bubble = page.getByRole('application');
  await bubble.focus();
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('Shift+ArrowDown');
  await expect(page).toHaveURL(/probe=0\.51%2C0\.55/);
  await expect(page.locator('.tfb-live')).toHaveText(
    /^Probe at 51% across, 55% down: film \d+ nm thick, θi [\d.]+°, [a-z ]+ \(#[0-9a-f]{6}\)\.$/,
  );
  expect(await bubble.evaluate((e) => getComputedStyle(e).outlineStyle)).toBe('solid');
});

test('the teaching page in both languages and the materials page have no axe violation; the Japanese one no English', async ({ page }) => {
  for (const path of ['/teaching.html', '/teaching.ja.html']) {
    await page.goto(path);
    // Every element built (its panel, plots and messages are in the page before the first frame).
    const elements = await page.locator('thin-film-bubble').count();
    expect(elements).toBeGreaterThanOrEqual(9);
    await expect(page.locator('thin-film-bubble .tfb-layout')).toHaveCount(elements);
    await page.locator('thin-film-diagram .tfd-summary').waitFor();
    await noAxeViolations(page);
  }
  expect(await englishIn(page)).toEqual([]);
  await page.goto('/materials.html');
  await expect(page.locator('body')).toHaveAttribute('data-frames', /\d+/);
  await noAxeViolations(page);
});

test("reduced motion leaves the swirl still on the demo and in the element unless animate is asked for; arrow keys move the element's probe", async ({
  page,
}) => {
  await page.emulateMedia({ reducedMotion: 'reduce' });
  await page.goto('/?mode=table&env=none&field=swirl');
  await ready(page);
  const animate = () =>
    page.evaluate(() => (window as unknown as { bubbleApp: { current: { animate: boolean } } }).bubbleApp.current.animate);
  expect(await animate()).toBe(false);
  await page.route(`${BUILT_URL}/motion.html`, (route) =>
    route.fulfill({
      contentType: 'text/html',
      body: `<!doctype html><html lang="en"><meta charset="utf-8"><title>motion</title><script type="module" src="/thin-film-bubble.js"></script>
<main><thin-film-bubble env="none" style="width:160px;height:160px"></thin-film-bubble><thin-film-bubble env="none" animate="1" style="width:160px;height:160px"></thin-film-bubble></main></html>`,
    }),
  );
  await page.goto(`${BUILT_URL}/motion.html`);
  const settings = page.locator('thin-film-bubble');
  await expect(settings.nth(1)).toHaveAttribute('data-frames', /\d+/);
  expect(
    await settings.evaluateAll((els) => els.map((e) => (e as HTMLElement & { settings: { animate: boolean } }).settings.animate)),
  ).toEqual([false, true]);
});
