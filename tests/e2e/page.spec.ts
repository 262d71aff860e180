import { test, expect } from '@playwright/test';
import { centrePixel } from './drawingBuffer.ts';
import { openPanel } from './panel.ts';
import { watchProblems } from './pageWatch.ts';
import { MAX_CODE_DIFFERENCE, reference8, worstCodeDifference, xyzTo8 } from './referenceColor.ts';
import { XYZ_TO_LINEAR_SRGB } from '../../src/physics/colorConversions.ts';
import { SOAP_FILM_IN_AIR } from '../../src/physics/filmReflectance.ts';
import { filmXyz } from '../../src/physics/spectralIntegration.ts';
import { DISPERSIVE_FIRST_FRAME_MS } from './waits.ts';
import { DEMO_VIEW_CHANGES } from '../../src/settings/demoView.ts';

test('the demo page loads with its title and WebGL2; a bad URL parameter shows a message naming it and its range, uses the default, and logs no error', async ({
  page,
}) => {
  const problems = watchProblems(page);
  await page.goto('/?nFilm=<img src=x onerror=alert(1)>&field=uniform&animate=0&env=none');
  await expect(page).toHaveTitle(/thin-film-color/);
  await expect(page.locator('body')).toHaveAttribute('data-webgl2', 'yes');
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready', { timeout: 60_000 });
  await expect(page.locator('#messages')).toContainText('nFilm');
  await expect(page.locator('#messages')).toContainText('[1, 4]');
  expect(await page.locator('#messages img').count()).toBe(0);
  expect(
    await page.evaluate(() => (window as unknown as { bubbleApp: { drawn: { film: { nFilm: number } } } }).bubbleApp.drawn.film.nFilm),
  ).toBe(1.33);
  expect(problems).toEqual([]);
});

test('fourier with a dispersive film draws with the table and says why; the URL keeps mode=fourier', async ({ page }) => {
  const problems = watchProblems(page);
  await page.goto('/?nFilm=water&mode=fourier&field=uniform&animate=0&env=none');
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready', { timeout: DISPERSIVE_FIRST_FRAME_MS });
  await expect(page.locator('#messages .frame-notice')).toContainText('nFilm=water');
  await expect(page.locator('#messages .frame-notice')).toContainText('mode=table');
  const modes = () =>
    page.evaluate(() => {
      const w = window as unknown as {
        bubbleView: { table: { coarse: boolean; bind(u: Record<string, { value: unknown }>): void } };
        bubbleApp: { current: { mode: string }; drawn: { film: { mode: string } } };
      };
      // The grid the table binds: one texel until a table is built.
      const bound = {
        uFilmTable: { value: null },
        uFilmTable1: { value: null },
        uFilmTable2: { value: null },
        uTableMaxThicknessNm: { value: 0 },
        uFilmTableWidth: { value: 0 },
        uFilmTableRows: { value: 0 },
      };
      w.bubbleView.table.bind(bound);
      const table = { width: bound.uFilmTableWidth.value, coarse: w.bubbleView.table.coarse };
      return { shown: w.bubbleApp.drawn.film.mode, asked: w.bubbleApp.current.mode, table };
    });
  expect(await modes()).toMatchObject({ shown: 'table', asked: 'fourier', table: { coarse: false } });
  expect((await modes()).table.width).toBeGreaterThan(1);
  // A change through the panel keeps the mode asked for in the URL.
  await openPanel(page);
  await page.getByRole('combobox', { name: 'illuminant' }).selectOption('D93');
  await expect(page).toHaveURL(/illuminant=D93/);
  expect(page.url()).toContain('mode=fourier');
  expect(problems).toEqual([]);
});

test("the demo opens on the flowing film on black: what the URL leaves out is the demo's default, and the panel shows the flow's controls", async ({
  page,
}) => {
  // A small grid, frozen at its start: quick on a CPU rasteriser; every other value is left out.
  await page.goto('/?grid=16&animate=0');
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
  const current = await page.evaluate(() => (window as unknown as { bubbleApp: { current: Record<string, unknown> } }).bubbleApp.current);
  expect(current).toMatchObject({ ...DEMO_VIEW_CHANGES, gridN: 16 });
  await openPanel(page);
  const controller = (label: string) => page.locator('.lil-controller', { hasText: label });
  await expect(controller('swirl speed')).toBeHidden();
  await expect(controller('range (nm)')).toBeHidden();
  await expect(page.locator('.lil-gui .lil-title', { hasText: /^flow$/ })).toBeVisible();
  // A change writes what differs from the demo's defaults, and nothing the URL left out.
  const thickness = page.locator('.lil-controller', { hasText: 'thickness (nm)' }).locator('input');
  await thickness.fill('600');
  await thickness.press('Enter');
  await expect(page).toHaveURL(/thickness=600/);
  expect(new URL(page.url()).searchParams.has('field')).toBe(false);
  expect(new URL(page.url()).searchParams.has('env')).toBe(false);
});

test('the panel changes the view and the URL, and the URL restores the state', async ({ page }) => {
  test.setTimeout(DISPERSIVE_FIRST_FRAME_MS + 120_000);
  await page.goto('/?field=swirl&animate=0&env=none&sides=front');
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready', { timeout: 60_000 });
  await openPanel(page);
  const field = page.getByRole('combobox', { name: 'thickness field' });
  await field.selectOption('uniform');
  await expect(page).toHaveURL(/field=uniform/);
  // The thickness slider's number box: the centre becomes the reference colour of that film.
  const thickness = page.locator('.lil-controller', { hasText: 'thickness (nm)' }).locator('input');
  await thickness.fill('300');
  await thickness.press('Enter');
  await expect(page).toHaveURL(/thickness=300/);
  const current = () =>
    page.evaluate(
      () =>
        (window as unknown as { bubbleApp: { drawn: { film: { field: string; env: string; thicknessNm: number; nFilm: unknown } } } })
          .bubbleApp.drawn.film,
    );
  expect(await current()).toMatchObject({ field: 'uniform', env: 'none', thicknessNm: 300 });
  expect(worstCodeDifference(await centrePixel(page), reference8({ thicknessNm: 300 }))).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
  // The tint's B slider: the URL and the centre follow the tinted light.
  const tintBlue = page.locator('.lil-controller', { hasText: 'light tint B (linear sRGB)' }).locator('input');
  await tintBlue.fill('0.2');
  await tintBlue.press('Enter');
  await expect(page).toHaveURL(/lightTint=1(,|%2C)1(,|%2C)0\.2/);
  const tinted = xyzTo8(filmXyz({ ...SOAP_FILM_IN_AIR, angleDeg: 0, thicknessNm: 300 }, { lightTint: [1, 1, 0.2] }), XYZ_TO_LINEAR_SRGB);
  // A new light is shown once its transform has arrived from the worker (lightChange.spec): until then the previous one.
  await expect
    .poll(async () => worstCodeDifference(await centrePixel(page), tinted), { timeout: 30_000 })
    .toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
  await tintBlue.fill('1');
  await tintBlue.press('Enter');
  await expect(page).toHaveURL(/^(?!.*lightTint=)/);

  // The panel shows only what applies: the swirl's speed and range under the swirl, the flow folder
  // under the flow; what it hides keeps its value in the URL.
  const controller = (label: string) => page.locator('.lil-controller', { hasText: label });
  const flowFolder = page.locator('.lil-gui .lil-title', { hasText: /^flow$/ });
  await field.selectOption('swirl');
  await expect(controller('swirl speed')).toBeVisible();
  await expect(controller('range (nm)')).toBeVisible();
  await expect(flowFolder).toBeHidden();
  await field.selectOption('flowing film');
  // The flow is the demo's default field: the URL leaves it out.
  await expect(page).toHaveURL(/^(?!.*field=)/);
  await expect(controller('swirl speed')).toBeHidden();
  await expect(controller('range (nm)')).toBeHidden();
  await expect(flowFolder).toBeVisible();
  expect(page.url()).toMatch(/thickness=300/);
  await field.selectOption('swirl');
  await expect(controller('swirl speed')).toBeVisible();
  await expect(controller('range (nm)')).toBeVisible();
  await expect(flowFolder).toBeHidden();
  await field.selectOption('uniform');
  await expect(page).toHaveURL(/field=uniform/);

  // A medium's list: a name from it, then a kind chosen and typed in its text field, which shows
  // only while its kind is chosen; each shows in the URL.
  const pickThenType = async (
    list: string,
    name: string,
    nameInUrl: RegExp,
    textLabel: string,
    text: string,
    kind: string,
    inUrl: RegExp,
  ) => {
    const combobox = page.getByRole('combobox', { name: list });
    await combobox.selectOption(name);
    await expect(page).toHaveURL(nameInUrl);
    const field = page.locator('.lil-controller', { hasText: textLabel }).locator('input');
    await expect(field).toBeHidden();
    await combobox.selectOption(kind);
    await expect(field).toBeVisible();
    await field.fill(text);
    await field.press('Enter');
    await expect(page).toHaveURL(inUrl);
    return field;
  };
  // The film's material: water, then a Cauchy film typed as A,B; one outside the index domain is not taken.
  const cauchyText = await pickThenType(
    'film material',
    'water',
    /nFilm=water/,
    'Cauchy A,B[,C]',
    '1.45,6000',
    'cauchy',
    /nFilm=cauchy%3A1.45%2C6000/,
  );
  await cauchyText.fill('3.9,20000');
  await cauchyText.press('Enter');
  await expect(cauchyText.locator('xpath=ancestor::div[contains(@class, "lil-controller")]')).toHaveAttribute(
    'title',
    'not taken: n at 380 nm is 4.0385, above 4',
  );
  const cauchy = { cauchy: [1.45, 6000, 0] } as const;
  expect(await current()).toMatchObject({ nFilm: cauchy });

  await page.goto(page.url()); // a Cauchy film: dispersive
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready', { timeout: DISPERSIVE_FIRST_FRAME_MS });
  expect(await current()).toMatchObject({ field: 'uniform', env: 'none', thicknessNm: 300, nFilm: cauchy });
  await openPanel(page);
  await expect(page.getByRole('combobox', { name: 'thickness field' })).toHaveValue('uniform');
  await expect(page.getByRole('combobox', { name: 'film material' })).toHaveValue('cauchy');
  const expected = reference8({ thicknessNm: 300, nFilm: cauchy });
  expect(worstCodeDifference(await centrePixel(page), expected)).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);

  // The inside's medium: a named metal from the list, then a complex constant typed as n,k.
  await pickThenType('inside medium', 'Au', /nInside=Au/, 'complex n,k', '2.6,3.4', 'complex', /nInside=complex%3A2.6%2C3.4/);
  expect(await current()).toMatchObject({ nInside: { complex: [2.6, 3.4] } });
});
