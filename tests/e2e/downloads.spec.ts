import { readFileSync } from 'node:fs';
import { expect, test, type Page } from '@playwright/test';
import { PNG } from 'pngjs';
import { SOAP_FILM_IN_AIR, filmReflectance } from '../../src/physics/filmReflectance.ts';
import { illuminantSpd } from '../../src/physics/illuminants.ts';
import { FLOAT_TOLERANCE, SAVED_PLOT_CODES } from '../tolerances.ts';

/**
 * The plots' downloads hold what the plots show: each PNG is its canvas's pixels (over the
 * opaque background the panel is saved on), and the spectrum's CSV is the float64 reference's
 * R(λ) and the light's spectrum at the probed film. Files are named after the view.
 */

/** A window large enough for the plots to start open beside the bubble (index.html). */
test.use({ viewport: { width: 1000, height: 700 } });

const PROBE = [0.6, 0.45] as const;
const VIEW = `/?field=uniform&thickness=450&illuminant=D65&animate=0&probe=${PROBE.join(',')}`;
/** The background the plots are saved on, as RGB: `#141418` (the plots box's colour). */
const BACKGROUND = [0x14, 0x14, 0x18];

/** Clicks a save button and returns the download's name and bytes. */
async function save(page: Page, file: string): Promise<{ name: string; bytes: Buffer }> {
  const [download] = await Promise.all([page.waitForEvent('download'), page.click(`button[data-download="${file}"]`)]);
  return { name: download.suggestedFilename(), bytes: readFileSync(await download.path()) };
}

test('each plot saves as a PNG of its pixels, the spectrum as the reference CSV, named after the view', async ({ page }) => {
  await page.goto(VIEW);
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
  // The film the plots show: the probe's reading (thickness from the shader, θ_i from the camera ray), once back from the GPU.
  const reading = await page.evaluate(
    ([fx, fy]) => (window as unknown as { bubbleView: import('../../src/view/bubbleView.ts').BubbleView }).bubbleView.probe(fx, fy),
    PROBE,
  );
  expect(reading, 'the probe is on the bubble').not.toBeNull();
  const { thicknessNm, angleDeg } = reading!;
  console.log(`downloads: probed ${thicknessNm} nm at ${angleDeg}°`);
  expect(angleDeg).toBeGreaterThan(5);
  const base = `film-450nm-D65-${Math.round(angleDeg)}deg`;
  // The colour scale (the xy path and the strip) comes from its worker after the rest of the plots.
  await expect(page.locator('.tfb-plots')).toHaveAttribute('data-scale', 'ready');

  for (const [file, canvas] of [
    ['spectrum.png', '.tfb-spectrum'],
    ['xy.png', '.tfb-chromaticity'],
    ['scale.png', '.tfb-strip'],
  ] as const) {
    const { name, bytes } = await save(page, file);
    expect(name).toBe(`${base}-${file}`);
    const png = PNG.sync.read(bytes);
    const shown = await page.evaluate((selector) => {
      const c = document.querySelector<HTMLCanvasElement>(selector)!;
      return { width: c.width, height: c.height, rgba: Array.from(c.getContext('2d')!.getImageData(0, 0, c.width, c.height).data) };
    }, canvas);
    expect([png.width, png.height]).toEqual([shown.width, shown.height]);
    // Counted in plain loops: an expect per pixel would take minutes.
    let worst = 0;
    let drawn = 0;
    let transparent = 0;
    for (let i = 0; i < shown.rgba.length; i += 4) {
      const alpha = shown.rgba[i + 3]! / 255;
      if (alpha > 0) drawn++;
      if (png.data[i + 3] !== 255) transparent++;
      for (let c = 0; c < 3; c++) {
        const expected = Math.round(shown.rgba[i + c]! * alpha + BACKGROUND[c]! * (1 - alpha));
        worst = Math.max(worst, Math.abs(png.data[i + c]! - expected));
      }
    }
    expect(transparent).toBe(0);
    console.log(`downloads: ${name} ${png.width}×${png.height}, ${drawn} pixels drawn, worst difference ${worst} codes`);
    expect(drawn).toBeGreaterThan(shown.rgba.length / 4 / 50);
    expect(worst).toBeLessThanOrEqual(SAVED_PLOT_CODES);
  }

  const { name, bytes } = await save(page, 'spectrum.csv');
  expect(name).toBe(`${base}-spectrum.csv`);
  const [header, ...rows] = bytes.toString('utf8').trimEnd().split('\n');
  expect(header).toBe('wavelength_nm,R,I_in_relative,I_out_relative');
  const lambdas = Array.from({ length: 451 }, (_, i) => 380 + i);
  const spd = illuminantSpd('D65');
  const peak = Math.max(...lambdas.map(spd));
  expect(rows).toHaveLength(lambdas.length);
  rows.forEach((row, i) => {
    const [lambda, r, incident, reflected] = row.split(',').map(Number) as [number, number, number, number];
    const expectedR = filmReflectance(lambdas[i]!, { ...SOAP_FILM_IN_AIR, thicknessNm, angleDeg });
    expect(lambda).toBe(lambdas[i]);
    expect(Math.abs(r - expectedR)).toBeLessThanOrEqual(FLOAT_TOLERANCE);
    expect(Math.abs(incident - spd(lambda) / peak)).toBeLessThanOrEqual(FLOAT_TOLERANCE);
    expect(Math.abs(reflected - expectedR * (spd(lambda) / peak))).toBeLessThanOrEqual(FLOAT_TOLERANCE);
  });
});
