import { expect, test, type Page } from '@playwright/test';
import {
  type Matrix3,
  XYZ_TO_LINEAR_DISPLAY_P3,
  XYZ_TO_LINEAR_SRGB,
  applyMatrix3,
  encode8,
  mapToGamut,
} from '../../src/physics/colorConversions.ts';
import { SOAP_FILM_IN_AIR } from '../../src/physics/filmReflectance.ts';
import type { NamedIlluminant } from '../../src/physics/illuminants.ts';
import { filmXyz } from '../../src/physics/spectralIntegration.ts';

/**
 * The page's centre pixel is the film seen head-on (θ_i ≈ 0: the centre ray is half a pixel off
 * the axis) with nothing behind it (env=none, sides=front, exposure 1), so its 8-bit colour must
 * be the reference's: XYZ → linear RGB → clip → sRGB-encode → round (what the CLI's srgb8 is).
 */

/** 8-bit rounding on each side, plus the table's interpolation and float32: 2 codes. */
const MAX_CODE_DIFFERENCE = 2;

const BASE = '/?field=uniform&env=none&sides=front&exposure=1&animate=0';

function reference8(thicknessNm: number, illuminant: NamedIlluminant, toLinear: Matrix3): number[] {
  const xyz = filmXyz({ ...SOAP_FILM_IN_AIR, thicknessNm, angleDeg: 0 }, { illuminant });
  return mapToGamut(applyMatrix3(toLinear, xyz), xyz[1]).map(encode8);
}

/**
 * Draws a frame and reads the drawing buffer's centre in the same task (so the read does not
 * depend on the context preserving its buffer), with whether the canvas is Display P3.
 */
async function centre(page: Page, query: string): Promise<{ rgb: number[]; displayIsP3: boolean }> {
  await page.goto(`${BASE}&${query}`);
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
  return page.evaluate(() => {
    const view = (window as unknown as { bubbleView: import('../../src/scene/bubbleView.ts').BubbleView }).bubbleView;
    view.render();
    const gl = view.renderer.getContext();
    const pixel = new Uint8Array(4);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.readPixels(gl.drawingBufferWidth >> 1, gl.drawingBufferHeight >> 1, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    return { rgb: [pixel[0]!, pixel[1]!, pixel[2]!], displayIsP3: view.displayIsP3 };
  });
}

function expectClose(actual: number[], expected: number[], what: string): void {
  const worst = Math.max(...actual.map((v, i) => Math.abs(v - expected[i]!)));
  expect(worst, `${what}: page ${actual} vs reference ${expected}`).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
}

for (const illuminant of ['D55', 'D65', 'D93'] as const) {
  test(`table mode: the centre pixel is the reference sRGB colour under ${illuminant}`, async ({ page }) => {
    for (const thicknessNm of [150, 300, 450, 700, 1000]) {
      const { rgb } = await centre(page, `thickness=${thicknessNm}&illuminant=${illuminant}`);
      const expected = reference8(thicknessNm, illuminant, XYZ_TO_LINEAR_SRGB);
      console.log(`centre table ${illuminant} ${thicknessNm} nm: page ${rgb} reference ${expected}`);
      expect.soft(() => expectClose(rgb, expected, `${thicknessNm} nm under ${illuminant}`)).not.toThrow();
    }
  });
}

test('exact mode: the centre pixel is the reference sRGB colour', async ({ page }) => {
  const { rgb } = await centre(page, 'thickness=450&illuminant=D65&mode=exact');
  const expected = reference8(450, 'D65', XYZ_TO_LINEAR_SRGB);
  console.log(`centre exact D65 450 nm: page ${rgb} reference ${expected}`);
  expectClose(rgb, expected, '450 nm under D65, exact');
});

test('space=display-p3 shows the reference P3 colour, or falls back to sRGB where the browser cannot', async ({ page }) => {
  const { rgb, displayIsP3 } = await centre(page, 'thickness=450&illuminant=D65&space=display-p3');
  const expected = reference8(450, 'D65', displayIsP3 ? XYZ_TO_LINEAR_DISPLAY_P3 : XYZ_TO_LINEAR_SRGB);
  console.log(`centre display-p3 (drawing buffer ${displayIsP3 ? 'display-p3' : 'srgb fallback'}) D65 450 nm: page ${rgb} reference ${expected}`);
  if (!displayIsP3) {
    const colorSpace = await page.evaluate(() => (document.querySelector('canvas')!.getContext('webgl2') as WebGL2RenderingContext).drawingBufferColorSpace);
    expect(colorSpace).toBe('srgb');
  }
  expectClose(rgb, expected, `450 nm under D65 in ${displayIsP3 ? 'Display P3' : 'sRGB (fallback)'}`);
});
