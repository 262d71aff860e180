import { expect, test } from '@playwright/test';
import { watchProblems, withoutWebGL } from './pageWatch.ts';
import { reference8 } from './referenceColor.ts';

/**
 * Bad links and a browser without WebGL2: the page says what is wrong, in text, and still
 * teaches; nothing reaches the console as an error or warning.
 */

test('several bad URL parameters: a message for each naming its range, defaults used, no console error', async ({ page }) => {
  const problems = watchProblems(page);
  const bad = `thickness=abc&nFilm=9&illuminant=bogus&exposure=1e999&mode=fast&time=-1&speed=${'9'.repeat(5000)}`;
  await page.goto(`/?${bad}&field=uniform&animate=0&env=none&sides=front`);
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready', { timeout: 60_000 });
  const messages = page.locator('#messages p');
  await expect(messages).toHaveCount(7);
  for (const [name, range] of <[string, string][]>[
    ['thickness', '[0, 20000] nm'],
    ['nFilm', '[1, 4]'],
    ['illuminant', '[4000, 25000] K'],
    ['exposure', '[0, 100]'],
    ['mode', 'exact, table'],
    ['time', '[0, 1000000] s'],
    ['speed', '[0, 10]'],
  ]) {
    await expect(messages.filter({ hasText: `${name}=` })).toContainText(range);
  }
  await expect(messages.filter({ hasText: 'speed=' })).toContainText('(5000 characters)');
  const current = await page.evaluate(() => (window as unknown as { bubbleApp: { drawn: { film: object } } }).bubbleApp.drawn.film);
  expect(current).toMatchObject({
    thicknessNm: 550,
    nFilm: 1.33,
    illuminant: 'D65',
    exposure: 1,
    mode: 'table',
    timeSeconds: 0,
    swirlSpeed: 0.4,
  });
  expect(problems).toEqual([]);
});

/** The fallback image's centre is the film head-on; its colour is binned as the shader's (ΔE00 ≤ 0.11): one code. */
const FALLBACK_MAX_CODE_DIFFERENCE = 1;

test('without WebGL2: a message where the canvas was and a CPU image of the bubble with the reference colour', async ({ page }) => {
  const problems = watchProblems(page);
  await withoutWebGL(page);
  await page.goto('/?field=uniform&thickness=450&env=none&sides=front&animate=0');
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'fallback', { timeout: 30_000 });
  await expect(page.locator('body')).toHaveAttribute('data-webgl2', 'no');
  await expect(page.locator('.cpu-fallback figcaption')).toContainText('no WebGL2');
  expect(await page.locator('canvas#bubble').count()).toBe(0);
  const centre = await page.evaluate(() => {
    const image = document.querySelector<HTMLCanvasElement>('.cpu-fallback canvas')!;
    return [...image.getContext('2d')!.getImageData(image.width >> 1, image.height >> 1, 1, 1).data];
  });
  const expected = reference8({ thicknessNm: 450 });
  console.log(`fallback centre ${centre} reference ${expected}`);
  expect(centre[3]).toBe(255);
  for (let i = 0; i < 3; i++)
    expect(Math.abs(centre[i]! - expected[i]!), `${centre} vs ${expected}`).toBeLessThanOrEqual(FALLBACK_MAX_CODE_DIFFERENCE);
  expect(problems).toEqual([]);
});

test('without WebGL2, an HDR environment is fetched and the CPU image reflects it (not the sky, not uniform)', async ({ page }) => {
  const problems = watchProblems(page);
  await withoutWebGL(page);
  const corners = async () => {
    await expect(page.locator('body')).toHaveAttribute('data-frames', 'fallback', { timeout: 60_000 });
    return page.evaluate(() => {
      const image = document.querySelector<HTMLCanvasElement>('.cpu-fallback canvas')!;
      const data = image.getContext('2d')!.getImageData(0, 0, image.width, image.height).data;
      const at = (x: number, y: number) => [...data.slice(4 * (y * image.width + x), 4 * (y * image.width + x) + 3)];
      return [at(5, 5), at(image.width - 5, 5), at(5, image.height - 5), at(image.width - 5, image.height - 5)];
    });
  };
  await page.goto('/?field=swirl&env=park&envRotation=90&animate=0');
  const park = await corners();
  await expect(page.locator('.environment-status')).toHaveCount(0);
  await page.goto('/?field=swirl&env=sky&animate=0');
  const sky = await corners();
  console.log(`fallback corners: park ${JSON.stringify(park)}, sky ${JSON.stringify(sky)}`);
  expect(park).not.toEqual(sky);
  expect(new Set(park.map(String)).size).toBeGreaterThan(1);
  expect(problems).toEqual([]);
});
