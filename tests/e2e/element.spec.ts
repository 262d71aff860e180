import { expect, test, type Page } from '@playwright/test';
import {
  XYZ_TO_LINEAR_DISPLAY_P3,
  XYZ_TO_LINEAR_SRGB,
  applyMatrix3,
  encode8,
  invert3,
  srgbDecode,
} from '../../src/physics/colorConversions.ts';
import { MAX_CODE_DIFFERENCE, reference8, worstCodeDifference } from './referenceColor.ts';
import { watchProblems, withoutWebGL } from './pageWatch.ts';
import { BUILT_URL } from './servers.ts';

/**
 * The built element (dist/thin-film-bubble.js, from `npm run build`) on plain HTML pages served
 * statically with the build output: one <script type="module"> line, then the elements.
 */

const FILM = 'field="uniform" thickness="450" env="none" sides="front" animate="0"';

/** A plain page at the built site's origin holding `body`, loading the element with one line. */
async function plainPage(page: Page, body: string): Promise<void> {
  await page.route(`${BUILT_URL}/plain.html`, (route) =>
    route.fulfill({
      contentType: 'text/html',
      body: `<!doctype html><meta charset="utf-8"><script type="module" src="/thin-film-bubble.js"></script>
<style>thin-film-bubble { width: 200px; height: 200px; display: inline-block; }</style>${body}`,
    }),
  );
  await page.goto(`${BUILT_URL}/plain.html`);
}

/** Counts WebGL2 contexts and shader compilations on the page, from before any script runs (on every load after this call). */
async function countGl(page: Page): Promise<void> {
  await page.addInitScript(() => {
    const w = window as unknown as { glCanvases: Set<HTMLCanvasElement>; compiles: number };
    w.glCanvases = new Set();
    w.compiles = 0;
    // eslint-disable-next-line @typescript-eslint/unbound-method -- wrapped below and called with .call(this)
    const getContext = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function (this: HTMLCanvasElement, kind: string, ...rest: unknown[]) {
      if (kind === 'webgl2') w.glCanvases.add(this);
      return (getContext as (...a: unknown[]) => unknown).call(this, kind, ...rest);
    } as typeof getContext;
    // eslint-disable-next-line @typescript-eslint/unbound-method -- wrapped below and called with .call(this)
    const compile = WebGL2RenderingContext.prototype.compileShader;
    WebGL2RenderingContext.prototype.compileShader = function (this: WebGL2RenderingContext, s: WebGLShader) {
      w.compiles++;
      return compile.call(this, s);
    };
  });
}

const glCounts = (page: Page) =>
  page.evaluate(() => {
    const w = window as unknown as { glCanvases: Set<HTMLCanvasElement>; compiles: number };
    const lost = [...w.glCanvases].map((c) => (c.getContext('webgl2') as WebGL2RenderingContext).isContextLost());
    // The page's one-off WebGL2 probe (cpuFallback.ts hasWebGL2) is released at once: count live ones.
    return { liveContexts: lost.filter((l) => !l).length, compiles: w.compiles };
  });

/** The centre pixel of the i-th element's canvas, once it has drawn. */
async function centre(page: Page, i: number): Promise<number[]> {
  const el = page.locator('thin-film-bubble').nth(i);
  await expect(el).toHaveAttribute('data-frames', /\d+/);
  return el.evaluate((e) => {
    const c = e.querySelector('canvas')!;
    return [
      ...c
        .getContext('2d')!
        .getImageData(c.width >> 1, c.height >> 1, 1, 1)
        .data.slice(0, 3),
    ];
  });
}

test('the built element renders the reference centre colour; two elements share one context and its programs', async ({ page }) => {
  const problems = watchProblems(page);
  await countGl(page);
  await plainPage(page, `<thin-film-bubble ${FILM} illuminant="D55"></thin-film-bubble>`);
  const one = await centre(page, 0);
  const single = await glCounts(page);

  await plainPage(
    page,
    `<thin-film-bubble ${FILM} illuminant="D55"></thin-film-bubble><thin-film-bubble ${FILM} illuminant="D93"></thin-film-bubble>`,
  );
  const [d55, d93] = [await centre(page, 0), await centre(page, 1)];
  const pair = await glCounts(page);
  console.log(
    `element centre: D55 ${d55} (alone ${one}), D93 ${d93}; shader compiles: one element ${single.compiles}, two ${pair.compiles}`,
  );

  for (const [rgb, illuminant] of [
    [one, 'D55'],
    [d55, 'D55'],
    [d93, 'D93'],
  ] as const) {
    expect(worstCodeDifference(rgb, reference8({ thicknessNm: 450 }, illuminant)), `${illuminant}: ${rgb}`).toBeLessThanOrEqual(
      MAX_CODE_DIFFERENCE,
    );
  }
  expect(pair.liveContexts).toBe(1);
  expect(pair.compiles).toBe(single.compiles);
  expect(problems).toEqual([]);
});

test('attributes: a bad one is named with its range and its default kept; a change redraws; removal frees the context', async ({
  page,
}) => {
  const problems = watchProblems(page);
  await countGl(page);
  await plainPage(page, `<thin-film-bubble ${FILM} nFilm="<b>9</b>" illuminant="D99" lighttint="1,2,0"></thin-film-bubble>`);
  const el = page.locator('thin-film-bubble');
  await expect(el.locator('.tfb-messages')).toContainText('lightTint');
  await expect(el.locator('.tfb-messages')).toContainText('each in [0, 1]');
  await expect(el.locator('.tfb-messages')).toContainText('nFilm');
  await expect(el.locator('.tfb-messages')).toContainText('[1, 4]');
  await expect(el.locator('.tfb-messages')).toContainText('illuminant');
  expect(await el.locator('.tfb-messages b').count()).toBe(0);
  expect(worstCodeDifference(await centre(page, 0), reference8({ thicknessNm: 450 }, 'D65'))).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);

  const frames = Number(await el.getAttribute('data-frames'));
  await el.evaluate((e) => e.setAttribute('thickness', '300'));
  await expect(el).not.toHaveAttribute('data-frames', String(frames));
  expect(worstCodeDifference(await centre(page, 0), reference8({ thicknessNm: 300 }, 'D65'))).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);

  await el.evaluate((e) => e.remove());
  expect((await glCounts(page)).liveContexts).toBe(0);
  expect(problems).toEqual([]);
});

/** The first element's canvases, bottom first: each one's 2-D colour space and its centre pixel (RGBA) read back in `readAs`. */
const canvases = (page: Page, readAs: PredefinedColorSpace) =>
  page
    .locator('thin-film-bubble')
    .first()
    .evaluate(
      (e, colorSpace) =>
        [...e.querySelectorAll<HTMLCanvasElement>('.tfb-stage > canvas')].map((c) => {
          const context = c.getContext('2d')!;
          const rgba = [...context.getImageData(c.width >> 1, c.height >> 1, 1, 1, { colorSpace }).data];
          return { colorSpace: context.getContextAttributes().colorSpace, rgba };
        }),
      readAs,
    );

/** An 8-bit sRGB colour as 8-bit Display P3 (the same transfer curve): what an sRGB canvas read as Display P3 gives. */
const srgb8InDisplayP3 = (rgb: readonly number[]) =>
  applyMatrix3(
    XYZ_TO_LINEAR_DISPLAY_P3,
    applyMatrix3(invert3(XYZ_TO_LINEAR_SRGB), [srgbDecode(rgb[0]! / 255), srgbDecode(rgb[1]! / 255), srgbDecode(rgb[2]! / 255)]),
  ).map(encode8);

test('space=display-p3 shows the Display P3 colour in a Display P3 canvas, and a change of space takes the canvas along', async ({
  page,
}) => {
  const offersDisplayP3 = await page.evaluate(() => {
    const twoD = document.createElement('canvas').getContext('2d', { colorSpace: 'display-p3' });
    const gl = document.createElement('canvas').getContext('webgl2');
    if (gl) gl.drawingBufferColorSpace = 'display-p3';
    return twoD?.getContextAttributes().colorSpace === 'display-p3' && gl?.drawingBufferColorSpace === 'display-p3';
  });
  test.skip(!offersDisplayP3, 'this browser offers no Display P3 2-D canvas or WebGL drawing buffer: the element stays sRGB there');
  const problems = watchProblems(page);
  // 450 nm under D65 lies outside sRGB (its linear red is negative): its Display P3 colour is
  // farther than the tolerance from its clipped sRGB colour read as Display P3, so a frame clipped
  // to sRGB on its way to the page fails.
  const p3 = reference8({ thicknessNm: 450 }, 'D65', XYZ_TO_LINEAR_DISPLAY_P3);
  const srgb = reference8({ thicknessNm: 450 }, 'D65');
  expect(worstCodeDifference(srgb8InDisplayP3(srgb), p3)).toBeGreaterThan(MAX_CODE_DIFFERENCE);

  await plainPage(page, `<thin-film-bubble ${FILM} space="display-p3"></thin-film-bubble>`);
  const el = page.locator('thin-film-bubble');
  await expect(el).toHaveAttribute('data-frames', /\d+/);
  /** Sets the attribute `space` and waits for a frame drawn in full in it. */
  const setSpace = async (space: string) => {
    const frames = await el.getAttribute('data-frames');
    await el.evaluate((e, value) => e.setAttribute('space', value), space);
    await expect(el).not.toHaveAttribute('data-frames', frames!);
  };
  // The frame is in a Display P3 canvas (read back as Display P3) beneath the element's own
  // canvas, which is clear (it takes focus and keys).
  const expectDisplayP3 = async () => {
    const shown = await canvases(page, 'display-p3');
    console.log(`element display-p3 450 nm D65: canvases ${JSON.stringify(shown)}; reference P3 ${p3}, sRGB ${srgb}`);
    expect(shown.map((c) => c.colorSpace)).toEqual(['display-p3', 'srgb']);
    expect(worstCodeDifference(shown[0]!.rgba.slice(0, 3), p3), `P3 canvas ${shown[0]!.rgba}`).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
    expect(shown[1]!.rgba[3]).toBe(0);
  };
  await expectDisplayP3();

  // Back to sRGB: one canvas, the clipped sRGB colour read back as before; then Display P3 again.
  await setSpace('srgb');
  const shownSrgb = await canvases(page, 'srgb');
  expect(shownSrgb.map((c) => c.colorSpace)).toEqual(['srgb']);
  expect(worstCodeDifference(shownSrgb[0]!.rgba.slice(0, 3), srgb), `sRGB canvas ${shownSrgb[0]!.rgba}`).toBeLessThanOrEqual(
    MAX_CODE_DIFFERENCE,
  );
  await setSpace('display-p3');
  await expectDisplayP3();
  expect(problems).toEqual([]);
});

test('the built teaching page shows all its bubbles without an error', async ({ page }) => {
  const problems = watchProblems(page);
  await page.goto(`${BUILT_URL}/teaching.html`);
  const bubbles = page.locator('thin-film-bubble');
  expect(await bubbles.count()).toBeGreaterThanOrEqual(3);
  for (let i = 0; i < (await bubbles.count()); i++) {
    await bubbles.nth(i).scrollIntoViewIfNeeded();
    await expect(bubbles.nth(i)).toHaveAttribute('data-frames', /\d+/);
  }
  const plots = page.locator('.tfb-plots');
  expect(await plots.count()).toBeGreaterThanOrEqual(1);
  for (let i = 0; i < (await plots.count()); i++) await expect(plots.nth(i)).toHaveAttribute('data-probe', /bubble$/);
  await expect(page.locator('thin-film-diagram')).toHaveAttribute('data-reflectance', /^0\.\d+/);
  expect(problems).toEqual([]);
});

test('without WebGL2 the element shows a message and a CPU image of the bubble with the reference colour', async ({ page }) => {
  const problems = watchProblems(page);
  await withoutWebGL(page);
  await plainPage(page, `<thin-film-bubble ${FILM}></thin-film-bubble>`);
  const el = page.locator('thin-film-bubble');
  await expect(el).toHaveAttribute('data-frames', 'fallback', { timeout: 30_000 });
  await expect(el.locator('figcaption')).toContainText('no WebGL2');
  const rgb = await el.evaluate((e) => {
    const c = e.querySelector('canvas')!;
    return [
      ...c
        .getContext('2d')!
        .getImageData(c.width >> 1, c.height >> 1, 1, 1)
        .data.slice(0, 3),
    ];
  });
  expect(worstCodeDifference(rgb, reference8({ thicknessNm: 450 }))).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
  expect(problems).toEqual([]);
});
