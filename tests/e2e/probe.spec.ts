import { expect, test } from '@playwright/test';
import { deltaE00 } from '../../src/physics/colorDifference.ts';
import { SOAP_FILM_IN_AIR } from '../../src/physics/filmReflectance.ts';
import { filmXyz, whiteXyz } from '../../src/physics/spectralIntegration.ts';
import { reference8 } from './referenceColor.ts';
import { ANGLE_TOL_DEG, printedValueTol } from '../tolerances.ts';

/**
 * Clicking the bubble probes that pixel; the readout's numbers are checked against geometry
 * done here (a ray from the camera meeting the unit sphere) and against src/physics.
 */

/** The scene's camera: on +z at distance 4, 35° vertical field of view, looking at the origin. */
const CAMERA_DISTANCE = 4;
const FOV_DEG = 35;

/** θ_i where the ray through a pixel (fractions of the view) meets the unit sphere, by the quadratic. */
function incidenceDeg(fx: number, fy: number, aspect: number): number {
  const t = Math.tan((FOV_DEG * Math.PI) / 360);
  const d = [(2 * fx - 1) * t * aspect, (1 - 2 * fy) * t, -1];
  const len = Math.hypot(...d);
  const dir = d.map((v) => v / len);
  const o = [0, 0, CAMERA_DISTANCE];
  const b = o[2]! * dir[2]!;
  const s = -b - Math.sqrt(b * b - (CAMERA_DISTANCE ** 2 - 1));
  const hit = o.map((v, i) => v + s * dir[i]!);
  const cos = -hit.reduce((sum, v, i) => sum + v * dir[i]!, 0);
  return (Math.acos(cos) * 180) / Math.PI;
}

/** The readout shows XYZ to 4 decimals and θ_i to 0.01°: for a dim film that rounding alone is a few hundredths. */
const READOUT_ROUNDING_DELTA_E00 = 0.05;
/** The shader's film colour against the reference at the same film: parity.spec.ts's bound. */
const MAX_RENDERED_DELTA_E00 = 0.5;

const readout = (page: import('@playwright/test').Page, field: string) =>
  page.locator(`.tfb-readout [data-field="${field}"]`).textContent();

test('a click probes the film there: thickness, angle, colour and ΔE00 agree with src/physics; the URL keeps the probe', async ({
  page,
}) => {
  await page.goto('/?field=uniform&thickness=450&env=none&sides=front&animate=0');
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
  // Without a click the probe sits at the centre: normal incidence.
  await expect(page.locator('.tfb-plots')).toHaveAttribute('data-probe', '0.5,0.5 bubble');
  expect(parseFloat((await readout(page, 'angle'))!)).toBeLessThan(ANGLE_TOL_DEG);

  const box = (await page.locator('#bubble').boundingBox())!;
  const [fx, fy] = [0.525, 0.75]; // between the plots box and the panel at 640×480
  await page.mouse.click(box.x + fx * box.width, box.y + fy * box.height);
  await expect(page.locator('.tfb-plots')).toHaveAttribute('data-probe', `${fx},${fy} bubble`);
  await expect(page).toHaveURL(new RegExp(`probe=${fx}%2C${fy}`));

  const thicknessNm = parseFloat((await readout(page, 'thickness'))!);
  const angleDeg = parseFloat((await readout(page, 'angle'))!);
  // The readout shows the thickness to 0.1 nm.
  expect(Math.abs(thicknessNm - 450)).toBeLessThan(printedValueTol(1));
  const expectedAngle = incidenceDeg(fx, fy, box.width / box.height);
  expect(Math.abs(angleDeg - expectedAngle)).toBeLessThan(ANGLE_TOL_DEG);

  const hex = (await readout(page, 'hex'))!.trim();
  const expected = reference8({ thicknessNm, angleDeg });
  expect(hex).toBe(`#${expected.map((v) => v.toString(16).padStart(2, '0')).join('')}`);
  const xyz = (await readout(page, 'xyz'))!.split(' ').map(Number);
  const reference = filmXyz({ ...SOAP_FILM_IN_AIR, thicknessNm, angleDeg });
  expect(deltaE00(xyz as unknown as [number, number, number], reference, whiteXyz('D65'))).toBeLessThan(READOUT_ROUNDING_DELTA_E00);
  const shownDeltaE = parseFloat((await readout(page, 'deltaE00'))!);
  console.log(`probe at ${fx},${fy}: ${thicknessNm} nm, ${angleDeg}° (geometry ${expectedAngle.toFixed(2)}°), ${hex}, ΔE00 ${shownDeltaE}`);
  expect(shownDeltaE).toBeGreaterThanOrEqual(0);
  expect(shownDeltaE).toBeLessThan(MAX_RENDERED_DELTA_E00);

  // Off the bubble, the probe says so.
  await page.mouse.click(box.x + 5, box.y + 5);
  await expect(page.locator('.tfb-plots')).toHaveAttribute('data-probe', /miss$/);
  await expect(page.locator('.tfb-readout [data-field="thickness"]')).toHaveText('off the bubble');
});

test('a shared URL with a probe restores it', async ({ page }) => {
  await page.goto('/?field=drainage&animate=0&env=none&probe=0.5,0.25');
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
  await expect(page.locator('.tfb-plots')).toHaveAttribute('data-probe', '0.5,0.25 bubble');
  // The drained film is thinner above the middle (mean 550 nm, range 800 nm: 150–950 nm top to bottom).
  const thicknessNm = parseFloat((await readout(page, 'thickness'))!);
  expect(thicknessNm).toBeGreaterThan(150);
  expect(thicknessNm).toBeLessThan(550);
});
