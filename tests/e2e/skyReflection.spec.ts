import { expect, test } from '@playwright/test';
import { XYZ_TO_LINEAR_SRGB, applyMatrix3, encode8 } from '../../src/physics/colorConversions.ts';
import { SOAP_FILM_IN_AIR } from '../../src/physics/filmReflectance.ts';
import { filmXyz } from '../../src/physics/spectralIntegration.ts';
import { environmentRadiance } from '../../src/render/environment.ts';
import { CAMERA_DISTANCE, FOV_DEG } from '../../src/scene/cpuBubbleImage.ts';
import { MAX_CODE_DIFFERENCE, worstCodeDifference } from './referenceColor.ts';

/**
 * One pixel of a uniform film in front of the procedural sky, near wall only: the page must show
 * R · L(mirror direction) + (1 − R) · L(straight through), with R the reference film colour
 * (src/physics, eqs 1–19) at that pixel's θ_i and L the sky's own TypeScript function. The pixel
 * sits above the centre, where the mirror direction climbs into the blue and the straight ray
 * sees the pale horizon, so the two terms differ.
 */
test('a uniform film against the sky reflects the sky in the mirror direction and transmits it behind', async ({ page }) => {
  const thicknessNm = 450;
  await page.goto(`/?field=uniform&thickness=${thicknessNm}&env=sky&sides=front&exposure=1&animate=0`);
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
  const read = await page.evaluate(() => {
    const view = (window as unknown as { bubbleView: import('../../src/scene/bubbleView.ts').BubbleView }).bubbleView;
    view.render();
    const gl = view.renderer.getContext();
    const w = gl.drawingBufferWidth,
      h = gl.drawingBufferHeight;
    const x = w >> 1,
      y = Math.round(h * 0.68);
    const pixel = new Uint8Array(4);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.readPixels(x, y, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    return { rgb: [pixel[0]!, pixel[1]!, pixel[2]!], x, y, w, h };
  });
  // The camera ray through that pixel's centre (GL rows count from the bottom).
  const tanHalf = Math.tan((FOV_DEG * Math.PI) / 360);
  const ndcX = (2 * (read.x + 0.5)) / read.w - 1,
    ndcY = (2 * (read.y + 0.5)) / read.h - 1;
  const raw = [ndcX * tanHalf * (read.w / read.h), ndcY * tanHalf, -1];
  const len = Math.hypot(...raw);
  const d = raw.map((c) => c / len) as [number, number, number];
  const b = CAMERA_DISTANCE * d[2];
  const t = -b - Math.sqrt(b * b - (CAMERA_DISTANCE * CAMERA_DISTANCE - 1));
  const p = [t * d[0], t * d[1], CAMERA_DISTANCE + t * d[2]] as [number, number, number];
  const cos = -(p[0] * d[0] + p[1] * d[1] + p[2] * d[2]);
  const mirror = p.map((n, i) => d[i]! + 2 * cos * n) as [number, number, number];
  const R = applyMatrix3(
    XYZ_TO_LINEAR_SRGB,
    filmXyz({ ...SOAP_FILM_IN_AIR, thicknessNm, angleDeg: (Math.acos(cos) * 180) / Math.PI }, { illuminant: 'D65' }),
  );
  const reflected = environmentRadiance(mirror, 'sky');
  const behind = environmentRadiance(d, 'sky');
  const expected = [0, 1, 2].map((i) =>
    encode8(Math.min(1, Math.max(0, R[i]! * reflected[i]! + Math.min(1, Math.max(0, 1 - R[i]!)) * behind[i]!))),
  );
  console.log(
    `sky pixel (${read.x}, ${read.y}) θ_i ${((Math.acos(cos) * 180) / Math.PI).toFixed(1)}°: page ${read.rgb} expected ${expected}`,
  );
  expect(worstCodeDifference(read.rgb, expected)).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
});
