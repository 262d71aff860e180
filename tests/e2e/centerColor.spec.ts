import type { Page } from '@playwright/test';
import { expect, test } from './fixtures.ts';
import { parseSettings } from '../../src/settings/settingsQuery.ts';
import { methodReads } from '../../src/methods/methods.ts';
import { XYZ_TO_LINEAR_DISPLAY_P3, XYZ_TO_LINEAR_SRGB, applyMatrix3, encode8 } from '../../src/physics/colorConversions.ts';
import { showSettings } from './appSettings.ts';
import { centrePixel } from './drawingBuffer.ts';
import { MAX_CODE_DIFFERENCE, reference8, stackReference8, worstCodeDifference, xyzTo8 } from './referenceColor.ts';
import { DISPERSIVE_FIRST_FRAME_MS, STACK_FIRST_FRAME_MS } from './waits.ts';
import { MAX_CODE_DIFFERENCE_STACK, MAX_CODE_DIFFERENCE_TINT } from '../tolerances.ts';
import { SOAP_FILM_IN_AIR } from '../../src/physics/filmReflectance.ts';
import { filmXyz } from '../../src/physics/spectralIntegration.ts';
import { EN } from '../../src/i18n/en.ts';
import { message } from '../../src/i18n/messages.ts';
import { type FilmLayer, resolveLayers } from '../../src/physics/stackFilms.ts';
import { layersText, parseLayers } from '../../src/physics/stackText.ts';
import { type Medium, mediumText } from '../../src/physics/medium.ts';
import { STACK_PRESETS } from '../../src/physics/stackPresets.ts';

/**
 * The page's centre pixel is the film seen head-on (θ_i ≈ 0: the centre ray is half a pixel off
 * the axis) with nothing behind it (env=none, sides=front, exposure 1), so its 8-bit colour must
 * be the reference's: XYZ → linear RGB → clip → sRGB-encode → round (what the CLI's srgb8 is).
 */

const BASE = '/?field=uniform&env=none&sides=front&exposure=1&animate=0';

/** Shows the view the URL `base&query` gives in the shared demo page and reads its centre (drawn in the same task), with whether the canvas is Display P3. */
async function centre(page: Page, query: string, timeout?: number, base = BASE): Promise<{ rgb: number[]; displayIsP3: boolean }> {
  const { settings, refusals } = parseSettings(`${base}&${query}`.slice(1));
  expect(refusals).toEqual([]);
  await showSettings(page, settings, timeout);
  const rgb = await centrePixel(page);
  const displayIsP3 = await page.evaluate(() => (window as unknown as { bubbleView: { displayIsP3: boolean } }).bubbleView.displayIsP3);
  return { rgb, displayIsP3 };
}

function expectClose(actual: number[], expected: number[], what: string, most = MAX_CODE_DIFFERENCE): void {
  expect(worstCodeDifference(actual, expected), `${what}: page ${actual} vs reference ${expected}`).toBeLessThanOrEqual(most);
}

const THICKNESSES_NM = [150, 300, 450, 700, 1000] as const;

for (const illuminant of ['D55', 'D65', 'D93'] as const) {
  test(`table mode: the centre pixel is the reference sRGB colour under ${illuminant}`, async ({ demoPage: page }) => {
    await centre(page, `thickness=${THICKNESSES_NM[0]}&illuminant=${illuminant}`);
    // The other films in the same page, as the panel sets them (the table rebuilt for each).
    for (const thicknessNm of THICKNESSES_NM) {
      if (thicknessNm !== THICKNESSES_NM[0]) await showSettings(page, { thicknessNm });
      const rgb = await centrePixel(page);
      const expected = reference8({ thicknessNm }, illuminant);
      console.log(`centre table ${illuminant} ${thicknessNm} nm: page ${rgb} reference ${expected}`);
      expect.soft(() => expectClose(rgb, expected, `${thicknessNm} nm under ${illuminant}`)).not.toThrow();
    }
  });
}

test('exact mode: the centre pixel is the reference sRGB colour', async ({ demoPage: page }) => {
  // Exact mode integrates 90 bins per fragment (seconds per frame on a software GPU): a small view.
  await page.setViewportSize({ width: 160, height: 120 });
  const { rgb } = await centre(page, 'thickness=450&illuminant=D65&mode=exact');
  const expected = reference8({ thicknessNm: 450 }, 'D65');
  console.log(`centre exact D65 450 nm: page ${rgb} reference ${expected}`);
  expectClose(rgb, expected, '450 nm under D65, exact');
});

test('under lamps and lines the centre pixel is the reference: a fluorescent tube in the table, sodium by exact in place of the table, a laser line in fourier', async ({
  demoPage: page,
}) => {
  const cases = [
    ['FL11', 'table', 450],
    ['Na', 'table', 3000],
    ['line:632.8', 'fourier', 12000],
  ] as const;
  for (const [light, mode, thicknessNm] of cases) {
    const { rgb } = await centre(page, `thickness=${thicknessNm}&illuminant=${light}&mode=${mode}`);
    const expected = reference8({ thicknessNm }, parseSettings(`illuminant=${light}`).settings.illuminant);
    console.log(`centre ${mode} ${light} ${thicknessNm} nm: page ${rgb} reference ${expected}`);
    expect.soft(() => expectClose(rgb, expected, `${thicknessNm} nm under ${light}, ${mode}`)).not.toThrow();
    // A table under a line source is drawn by exact, and the page says so.
    if (light === 'Na') await expect(page.getByText('mode=table under a line source (Na)')).toBeVisible();
  }
});

test('under a tinted fluorescent light (FL2, lightTint 1,0.5,0.2) the centre pixel is the reference in table, fourier and exact', async ({
  demoPage: page,
}) => {
  // exact integrates its bins per fragment: a small view keeps the three frames short on a software GPU. At 600 nm no
  // channel of the reference is clipped (77, 22, 21).
  await page.setViewportSize({ width: 160, height: 120 });
  for (const mode of ['table', 'fourier', 'exact'] as const) {
    const query = `thickness=600&illuminant=FL2&lightTint=1,0.5,0.2&mode=${mode}`;
    const { rgb } = await centre(page, query);
    const light = parseSettings(query).settings;
    const expected = xyzTo8(filmXyz({ ...SOAP_FILM_IN_AIR, angleDeg: 0, thicknessNm: 600 }, light), XYZ_TO_LINEAR_SRGB);
    // A page that left the light untinted would be far off: the tint is seen.
    expect(worstCodeDifference(expected, reference8({ thicknessNm: 600 }, 'FL2'))).toBeGreaterThan(5 * MAX_CODE_DIFFERENCE_TINT);
    console.log(`centre ${mode} FL2 tinted 1,0.5,0.2 600 nm: page ${rgb} reference ${expected}`);
    expect.soft(() => expectClose(rgb, expected, `600 nm under FL2 tinted 1,0.5,0.2, ${mode}`, MAX_CODE_DIFFERENCE_TINT)).not.toThrow();
  }
});

test('in a uniform coloured room (env=color:0.9,0.3,0.1) a film on gold shows the reference under the light tinted by that colour, in table, fourier and exact', async ({
  demoPage: page,
}) => {
  // The room is the only light, reflected as M · colour; on an opaque inside nothing is seen through the film, so the centre is
  // the film under the light times the colour's spectrum: the reference's tinted integral, no matrix involved.
  await page.setViewportSize({ width: 160, height: 120 });
  const colour = [0.9, 0.3, 0.1] as const;
  const room = BASE.replace('env=none', `env=color:${colour.join(',')}`);
  for (const thicknessNm of [300, 450]) {
    const stack = { nOutside: 1, nFilm: 1.38, nInside: 'Au' as Medium, thicknessNm, angleDeg: 0 };
    const expected = xyzTo8(filmXyz(stack, { lightTint: colour }), XYZ_TO_LINEAR_SRGB);
    // The product of two RGB triples, the film's colour times the room's, is far off: the spectral product is seen.
    const product = applyMatrix3(XYZ_TO_LINEAR_SRGB, filmXyz(stack)).map((v, i) => encode8(Math.min(1, Math.max(0, v * colour[i]!))));
    expect(worstCodeDifference(expected, product)).toBeGreaterThan(2 * MAX_CODE_DIFFERENCE);
    for (const mode of ['table', 'fourier', 'exact'] as const) {
      const { rgb } = await centre(page, `thickness=${thicknessNm}&nFilm=1.38&nInside=Au&mode=${mode}`, undefined, room);
      console.log(`centre ${mode} ${thicknessNm} nm on Au in the room ${colour}: page ${rgb} reference ${expected}`);
      expect.soft(() => expectClose(rgb, expected, `${thicknessNm} nm on gold in a room of ${colour}, ${mode}`)).not.toThrow();
    }
  }
});

// The table mode only: `exact` with a dispersive film (150 bins, Fresnel per bin, per pixel of the whole view) takes minutes on
// a busy CPU rasteriser; the parity spec holds its numbers to the reference.
test('a dispersive film (nFilm=water, a Cauchy film) shows the dispersive reference colour', async ({ demoPage: page }) => {
  const films = [
    ['nFilm=water&thickness=1200', 'water', 1200],
    ['nFilm=cauchy:1.45,6000&thickness=700', { cauchy: [1.45, 6000, 0] }, 700],
  ] as const;
  test.setTimeout(films.length * DISPERSIVE_FIRST_FRAME_MS + 60_000);
  for (const [query, nFilm, thicknessNm] of films) {
    const { rgb } = await centre(page, query, DISPERSIVE_FIRST_FRAME_MS);
    const expected = reference8({ thicknessNm, nFilm }, 'D65');
    console.log(`centre ${query}: page ${rgb} reference ${expected}`);
    expect.soft(() => expectClose(rgb, expected, query)).not.toThrow();
  }
});

test('space=display-p3 shows the reference P3 colour, or falls back to sRGB where the browser cannot', async ({ demoPage: page }) => {
  const { rgb, displayIsP3 } = await centre(page, 'thickness=450&illuminant=D65&space=display-p3');
  const expected = reference8({ thicknessNm: 450 }, 'D65', displayIsP3 ? XYZ_TO_LINEAR_DISPLAY_P3 : XYZ_TO_LINEAR_SRGB);
  console.log(
    `centre display-p3 (drawing buffer ${displayIsP3 ? 'display-p3' : 'srgb fallback'}) D65 450 nm: page ${rgb} reference ${expected}`,
  );
  if (!displayIsP3) {
    const colorSpace = await page.evaluate(
      () => (document.querySelector('canvas')!.getContext('webgl2') as WebGL2RenderingContext).drawingBufferColorSpace,
    );
    expect(colorSpace).toBe('srgb');
  }
  expectClose(rgb, expected, `450 nm under D65 in ${displayIsP3 ? 'Display P3' : 'sRGB (fallback)'}`);
});

/**
 * Stacks of films, each at the thickness field's value for its `d` layers: the Bragg mirror and the
 * coated lens of stackPresets.ts on their insides, and a nacre-like stack that follows the field.
 */
const STACKS: readonly { name: string; layers: readonly FilmLayer[]; nInside: Medium; thicknessNm: number }[] = [
  { name: 'Bragg mirror', layers: STACK_PRESETS.braggMirror.films, nInside: STACK_PRESETS.braggMirror.nInside, thicknessNm: 450 },
  { name: 'AR coating', layers: STACK_PRESETS.arCoating.films, nInside: STACK_PRESETS.arCoating.nInside, thicknessNm: 450 },
  { name: 'nacre-like (1.68:d/1.43:30)*2', layers: parseLayers('layers', '(1.68:d/1.43:30)*2'), nInside: 1.53, thicknessNm: 400 },
];

// `fourier` has no closed form for a stack: it draws the table, and the page says so.
test("a stack of films: the centre pixel is the transfer matrix's sRGB colour in table, exact and fourier", async ({ demoPage: page }) => {
  // Exact mode runs the stack's recursion in each of 150 bins per fragment: a small view, as for the single film's.
  await page.setViewportSize({ width: 160, height: 120 });
  test.setTimeout(STACK_FIRST_FRAME_MS + 120_000);
  const notice = page.locator('#messages .frame-notice');
  for (const { name, layers, nInside, thicknessNm } of STACKS) {
    const expected = stackReference8({ nOutside: 1, films: resolveLayers(layers, thicknessNm), nInside, angleDeg: 0 });
    const query = `thickness=${thicknessNm}&nInside=${encodeURIComponent(mediumText(nInside))}&layers=${encodeURIComponent(layersText(layers))}`;
    for (const mode of ['table', 'exact', 'fourier'] as const) {
      const { rgb } = await centre(page, `${query}&illuminant=D65&mode=${mode}`, STACK_FIRST_FRAME_MS);
      console.log(`centre ${name} ${mode}: page ${rgb} reference ${expected}`);
      expect.soft(() => expectClose(rgb, expected, `${name}, ${mode}`, MAX_CODE_DIFFERENCE_STACK)).not.toThrow();
      // A method that reads neither the stack nor a table (fourier) gives way to the table.
      if (!methodReads(mode, 'stack') && !methodReads(mode, 'table'))
        await expect(notice).toHaveText(message(EN, 'app.stackAsTable', { method: 'fourier', count: String(layers.length) }));
      else await expect(notice).toHaveCount(0);
    }
  }
});
