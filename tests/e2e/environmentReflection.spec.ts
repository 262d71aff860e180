import { expect, test } from '@playwright/test';
import { XYZ_TO_LINEAR_SRGB, type Rgb, applyMatrix3, encode8 } from '../../src/physics/colorConversions.ts';
import { SOAP_FILM_IN_AIR } from '../../src/physics/filmReflectance.ts';
import { type Medium, mediumText } from '../../src/physics/medium.ts';
import { filmEnvironmentMatrix, reflectedXyz } from '../../src/physics/environmentMatrix.ts';
import { type ShownEnvironment, environmentRadiance } from '../../src/bubbleTwins/environment.ts';
import { loadEnvironmentPixels } from '../../src/bubbleMaterials/environmentMaps.ts';
import { type HdrEnvironment, environmentKind, isHdrEnvironment } from '../../src/environments/environments.ts';
import type { ToneMapping } from '../../src/settings/filmSettings.ts';
import { toneMap } from '../../src/bubbleTwins/toneMapping.ts';
import { CAMERA_DISTANCE, FOV_DEG } from '../../src/bubbleTwins/cpuBubbleImage.ts';
import { MAX_CODE_DIFFERENCE, worstCodeDifference } from './referenceColor.ts';

/**
 * Pixels of a uniform film (near wall only) in front of an environment, against values computed
 * here from src/physics (the reference film's environment matrix M at each pixel's θ_i: each
 * colour's reflection an integral of two spectra, eqs 1–19 with the light times the colour's
 * spectrum) and the environment's own TypeScript function (the procedural sky, or the HDR map
 * decoded in Node): on the bubble exposure · (M L(mirror direction) + L(straight through) −
 * M L(straight through)), in linear sRGB, off it exposure · L(straight through), each through the
 * tone mapping's TypeScript twin. The bubble
 * pixel sits above the centre, where the mirror direction climbs and the straight ray sees the
 * horizon, so the two terms differ; the background pixels sit on a grid across the view. Over an
 * opaque inside (a metal, here a constant gold-like ñ) the bubble pixel is exposure · R · L(mirror)
 * alone: nothing is seen through it.
 */
const CASES: { env: 'sky' | HdrEnvironment; rotationDeg: number; tonemap: ToneMapping; exposure: number; nInside: Medium }[] = [
  { env: 'sky', rotationDeg: 0, tonemap: 'none', exposure: 1, nInside: SOAP_FILM_IN_AIR.nInside },
  { env: 'city', rotationDeg: 137, tonemap: 'agx', exposure: 1.5, nInside: SOAP_FILM_IN_AIR.nInside },
  { env: 'park', rotationDeg: 300, tonemap: 'neutral', exposure: 0.7, nInside: SOAP_FILM_IN_AIR.nInside },
  { env: 'sky', rotationDeg: 0, tonemap: 'none', exposure: 1, nInside: { complex: [0.43, 2.455] } },
];
const THICKNESS_NM = 450;
/** Points read, as fractions of the view: the bubble pixel first, then background pixels outside the bubble. */
const POINTS: [number, number][] = [
  [0.5, 0.32],
  ...[0.03, 0.12, 0.88, 0.97].flatMap((fx) => [0.05, 0.3, 0.5, 0.7, 0.95].map((fy): [number, number] => [fx, fy])),
];

for (const c of CASES) {
  const opaque = c.nInside !== SOAP_FILM_IN_AIR.nInside;
  const over = opaque ? ` over nInside=${mediumText(c.nInside)}, opaque,` : '';
  test(`a uniform film${over} in ${c.env} (turned ${c.rotationDeg}°, tone mapping ${c.tonemap}, exposure ${c.exposure}) reflects it in the mirror direction${opaque ? '' : ' and shows it behind'}`, async ({
    page,
  }) => {
    const env: ShownEnvironment = isHdrEnvironment(c.env)
      ? { kind: 'map', pixels: await loadEnvironmentPixels(c.env), rotationDeg: c.rotationDeg }
      : { kind: environmentKind(c.env) };
    await page.goto(
      `/?field=uniform&thickness=${THICKNESS_NM}&env=${c.env}&envRotation=${c.rotationDeg}&tonemap=${c.tonemap}` +
        `&exposure=${c.exposure}&sides=front&animate=0&nInside=${encodeURIComponent(mediumText(c.nInside))}`,
    );
    await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
    const read = await page.evaluate((points) => {
      const view = (window as unknown as { bubbleView: import('../../src/view/bubbleView.ts').BubbleView }).bubbleView;
      view.render();
      const gl = view.renderer.getContext();
      const w = gl.drawingBufferWidth,
        h = gl.drawingBufferHeight;
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      return points.map(([fx, fy]) => {
        // GL rows count from the bottom.
        const x = Math.floor(fx * w),
          y = Math.floor((1 - fy) * h);
        const pixel = new Uint8Array(4);
        gl.readPixels(x, y, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
        return { rgb: [pixel[0]!, pixel[1]!, pixel[2]!], x, y, w, h };
      });
    }, POINTS);
    const tanHalf = Math.tan((FOV_DEG * Math.PI) / 360);
    const shown = (radiance: Rgb) =>
      toneMap(radiance.map((v) => c.exposure * v) as unknown as Rgb, c.tonemap).map((v) => encode8(Math.min(1, Math.max(0, v))));
    const differences = read.map(({ rgb, x, y, w, h }, i) => {
      // The camera ray through that pixel's centre.
      const ndcX = (2 * (x + 0.5)) / w - 1,
        ndcY = (2 * (y + 0.5)) / h - 1;
      const raw = [ndcX * tanHalf * (w / h), ndcY * tanHalf, -1];
      const len = Math.hypot(...raw);
      const d = raw.map((v) => v / len) as [number, number, number];
      const b = CAMERA_DISTANCE * d[2];
      const disc = b * b - (CAMERA_DISTANCE * CAMERA_DISTANCE - 1);
      expect(disc >= 0, `point ${i} on the bubble`).toBe(i === 0);
      let expected: number[];
      if (i === 0) {
        const t = -b - Math.sqrt(disc);
        const p = [t * d[0], t * d[1], CAMERA_DISTANCE + t * d[2]] as [number, number, number];
        const cos = -(p[0] * d[0] + p[1] * d[1] + p[2] * d[2]);
        const mirror = p.map((n, k) => d[k]! + 2 * cos * n) as [number, number, number];
        const m = filmEnvironmentMatrix(
          { ...SOAP_FILM_IN_AIR, nInside: c.nInside, thicknessNm: THICKNESS_NM, angleDeg: (Math.acos(cos) * 180) / Math.PI },
          { illuminant: 'D65' },
        );
        const film = (light: Rgb) => applyMatrix3(XYZ_TO_LINEAR_SRGB, reflectedXyz(m, light));
        const reflected = film(environmentRadiance(mirror, env));
        const behind: Rgb = opaque ? [0, 0, 0] : environmentRadiance(d, env);
        const kept = film(behind);
        expected = shown([0, 1, 2].map((k) => reflected[k]! + behind[k]! - kept[k]!) as unknown as Rgb);
      } else {
        expected = shown(environmentRadiance(d, env));
      }
      console.log(`${c.env} (${x}, ${y}): page ${rgb} expected ${expected}`);
      return worstCodeDifference(rgb, expected);
    });
    expect(Math.max(...differences)).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
  });
}
