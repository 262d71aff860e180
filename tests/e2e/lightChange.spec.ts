import { expect } from '@playwright/test';
import { test } from './fixtures.ts';
import { openPanel } from './panel.ts';
import { MAX_CODE_DIFFERENCE, reference8, worstCodeDifference, xyzTo8 } from './referenceColor.ts';
import { expectChangeShownCleanly, recordCentreFrames } from './centreFrames.ts';
import { showSettings } from './appSettings.ts';
import { COARSE_FRAME_CODES } from '../tolerances.ts';
import { TABLE_PASS_NAME } from '../../src/film/keptPasses.ts';
import { XYZ_TO_LINEAR_SRGB } from '../../src/physics/colorConversions.ts';
import type { LightTint } from '../../src/physics/lightTint.ts';
import { filmXyz } from '../../src/physics/spectralIntegration.ts';
import { parseSettings } from '../../src/settings/settingsQuery.ts';

/**
 * A new light through the panel: its spectral transform is computed in a Web Worker while the
 * view goes on drawing, and every frame drawn on the way shows the previous light or the new one
 * (in `table` mode from the coarse table, then in full; in `fourier` mode, which reads the
 * transform per fragment, the previous light until the new one's transform is there), never a
 * blank or mixed one. The centre pixel is the film
 * head-on with nothing behind it, so each light's colour there is the reference's.
 */

const THICKNESS_NM = 450;
const LIGHTS = ['D55', 'D93'] as const;

for (const mode of ['table', 'fourier'] as const)
  test(`${mode} mode: a light change shows the previous light until the new one is drawn, never a frame of another`, async ({ page }) => {
    await page.goto(
      `/?field=uniform&thickness=${THICKNESS_NM}&env=none&sides=front&exposure=1&animate=0&mode=${mode}&illuminant=${LIGHTS[0]}`,
    );
    await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
    const expected = LIGHTS.map((light) => reference8({ thicknessNm: THICKNESS_NM }, light));
    // The two lights' colours are told apart even from a coarse table.
    expect(worstCodeDifference(expected[0]!, expected[1]!)).toBeGreaterThan(2 * COARSE_FRAME_CODES);
    // From here, the centre pixel of every frame the view draws, and whether it was drawn in full.
    const drawn = await recordCentreFrames(page);

    await openPanel(page);
    const illuminant = page.locator('.lil-controller', { hasText: /^illuminant/ }).locator('select');
    for (const [from, to] of [
      [0, 1],
      [1, 0],
    ] as const) {
      await expectChangeShownCleanly(
        drawn,
        () => illuminant.selectOption(LIGHTS[to]),
        [LIGHTS[from], LIGHTS[to]],
        [expected[from]!, expected[to]!],
      );
    }
  });

test('table mode: a change of tint in a coloured room is a colour the film matrix maps: the next frame shows it in full, no table drawn, no program linked', async ({
  demoPage: page,
}) => {
  // A film on gold in a grey room: the centre is M (t · room), the float64 film under the light tinted by t · room (opaque
  // inside: nothing behind).
  const room = [0.8, 0.8, 0.8] as const;
  const query = `field=uniform&env=color:${room.join(',')}&sides=front&exposure=1&animate=0&mode=table&nFilm=1.38&nInside=Au&thickness=300`;
  const { settings, refusals } = parseSettings(query);
  expect(refusals).toEqual([]);
  await page.setViewportSize({ width: 160, height: 120 });
  await showSettings(page, settings);
  const tints: LightTint[] = [
    [1, 0.5, 0.2],
    [0.3, 0.9, 1],
  ];
  const expected = tints.map((t) =>
    xyzTo8(
      filmXyz(
        { nOutside: 1, nFilm: 1.38, nInside: 'Au', thicknessNm: 300, angleDeg: 0 },
        { lightTint: t.map((v, i) => v * room[i]!) as unknown as LightTint },
      ),
      XYZ_TO_LINEAR_SRGB,
    ),
  );
  expect(worstCodeDifference(expected[0]!, expected[1]!)).toBeGreaterThan(10 * MAX_CODE_DIFFERENCE);
  await showSettings(page, { lightTint: tints[0] });
  const drawn = await recordCentreFrames(page);
  // From here, the table passes drawn at the view's renderer (the table pass's material is named TABLE_PASS_NAME).
  await page.evaluate((tablePassName) => {
    type Drawn = { material?: { name?: string } };
    const w = window as unknown as { bubbleView: { renderer: { render(d: Drawn, c: unknown): void } }; tablePasses: number };
    const renderer = w.bubbleView.renderer;
    const render = renderer.render.bind(renderer);
    w.tablePasses = 0;
    renderer.render = (d, c) => {
      if (d.material?.name === tablePassName) w.tablePasses++;
      render(d, c);
    };
  }, TABLE_PASS_NAME);
  const programs = () =>
    page.evaluate(
      () =>
        (window as unknown as { bubbleView: { renderer: { info: { programs?: unknown[] } } } }).bubbleView.renderer.info.programs?.length ??
        0,
    );
  const before = await programs();
  for (const i of [1, 0]) {
    const from = (await drawn()).length;
    await showSettings(page, { lightTint: tints[i] });
    const frames = (await drawn()).slice(from);
    console.log(
      `tint ${tints[i]} in a room of ${room}: ${frames.map(([rgb, full]) => `${rgb}${full ? '' : ' (coarse)'}`).join('; ')}; reference ${expected[i]}`,
    );
    expect(frames.length).toBeGreaterThan(0);
    for (const [rgb, full] of frames) {
      expect(full, 'drawn in full, from the table already built').toBe(true);
      expect(worstCodeDifference(rgb, expected[i]!), `${rgb} against the reference ${expected[i]}`).toBeLessThanOrEqual(
        MAX_CODE_DIFFERENCE,
      );
    }
  }
  expect(await page.evaluate(() => (window as unknown as { tablePasses: number }).tablePasses), 'table passes drawn').toBe(0);
  expect(await programs(), 'programs linked').toBe(before);
});
