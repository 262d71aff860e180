/**
 * The one place where what is asked becomes what is drawn (src/view/drawnFrame.ts): each offer of
 * the machine and the page, alone, and the frame and notices it must give. The expected values are
 * the rules' own (docs/architecture.md#what-is-asked-and-what-is-drawn), written out here.
 */
import { describe, expect, it } from 'vitest';
import { FIELDS, maxFieldThicknessNm } from '../../../src/fields/fields.ts';
import { flowParametersOf } from '../../../src/fields/flowField.ts';
import { type FrameOffers, resolveFrame, retimed, sameFrame } from '../../../src/view/drawnFrame.ts';
import { parseLayers } from '../../../src/physics/stackText.ts';
import { DEFAULT_VIEW_SETTINGS, type ViewSettings, filmSettingsOf } from '../../../src/settings/viewParameters.ts';

/** A frozen view on a machine that offers everything at once: no governor, nothing loading, every light ready. */
const OFFERS: FrameOffers = {
  choice: null,
  environmentLoaded: () => true,
  environmentFailure: () => null,
  compilesInParallel: true,
  lightReady: () => true,
  lightShown: null,
  devicePixelRatio: 1,
  baseStepsPerFrame: 8,
  drawsDisplayP3: () => true,
};
/** A frozen swirl in the sky, in the table, at grid and speed left to the governor: what the default view asks. */
const ASKED: ViewSettings = { ...DEFAULT_VIEW_SETTINGS, field: 'swirl', env: 'sky', mode: 'table', animate: false };
const FLOW: ViewSettings = { ...ASKED, field: 'flow', animate: true, seed: 7, thicknessNm: 600 };
const D65_WHITE = { illuminant: 'D65', lightTint: [1, 1, 1], normalization: 'white' } as const;

describe('what is drawn for what is asked', () => {
  it('shows a wide space in Display P3 where the canvas can, else sRGB with a notice; sRGB asked never asks the canvas', () => {
    for (const space of ['display-p3', 'wide-gamut'] as const) {
      expect(resolveFrame({ ...ASKED, space }, OFFERS)).toMatchObject({ displayP3: true, notices: [] });
      const srgb = resolveFrame({ ...ASKED, space }, { ...OFFERS, drawsDisplayP3: () => false });
      expect(srgb.displayP3).toBe(false);
      expect(srgb.notices).toEqual([{ setting: 'space', asked: space, drawn: 'srgb', message: { key: 'app.noDisplayP3', values: {} } }]);
    }
    const asking = () => {
      throw new Error('the canvas was asked for Display P3 where sRGB was asked');
    };
    expect(resolveFrame({ ...ASKED, space: 'srgb' }, { ...OFFERS, drawsDisplayP3: asking })).toMatchObject({
      displayP3: false,
      notices: [],
    });
  });

  it('draws what is asked, without a notice, where the machine offers everything; the frame is frozen', () => {
    const frame = resolveFrame(ASKED, OFFERS);
    expect(frame.film.mode).toBe('table');
    expect(frame.film.env).toBe('sky');
    expect([frame.film.illuminant, frame.film.normalization]).toEqual([ASKED.illuminant, ASKED.normalization]);
    expect(frame.notices).toEqual([]);
    expect(frame.environment).toEqual({ state: 'shown' });
    expect([frame.fetch, frame.lightPending]).toEqual([null, null]);
    expect(Object.isFrozen(frame)).toBe(true);
  });

  it('a stack of films asked in `fourier` is drawn by the table, the notice naming the method and the layers', () => {
    const frame = resolveFrame({ ...ASKED, mode: 'fourier', layers: parseLayers('layers', '1.38:99.6/1.6:50') }, OFFERS);
    expect(frame.film.mode).toBe('table');
    expect(frame.asked.mode).toBe('fourier');
    expect(frame.notices).toEqual([
      {
        setting: 'mode',
        asked: 'fourier',
        drawn: 'table',
        message: { key: 'app.stackAsTable', values: { method: 'fourier', count: '2' } },
      },
    ]);
  });

  it('`fourier` with a dispersive film is drawn by the table, the notice naming the film; a plain film keeps `fourier`', () => {
    const frame = resolveFrame({ ...ASKED, mode: 'fourier', nFilm: 'water' }, OFFERS);
    expect(frame.film.mode).toBe('table');
    expect(frame.notices[0]!.message).toEqual({ key: 'app.fourierAsTable', values: { name: 'nFilm', medium: 'water' } });
    expect(resolveFrame({ ...ASKED, mode: 'fourier', nFilm: 1.33 }, OFFERS).film.mode).toBe('fourier');
  });

  it('an HDR environment not loaded yet: the sky meanwhile, its map fetched, said loading; a failed one: the sky, said why, not fetched again', () => {
    const loading = resolveFrame({ ...ASKED, env: 'park' }, { ...OFFERS, environmentLoaded: () => false });
    expect(loading.film.env).toBe('sky');
    expect(loading.environment).toEqual({ state: 'loading', env: 'park' });
    expect(loading.fetch).toBe('park');
    expect(loading.notices).toEqual([{ setting: 'env', asked: 'park', drawn: 'sky', message: null }]);
    const failed = resolveFrame({ ...ASKED, env: 'park' }, { ...OFFERS, environmentLoaded: () => false, environmentFailure: () => '404' });
    expect(failed.film.env).toBe('sky');
    expect(failed.environment).toEqual({ state: 'failed', env: 'park', reason: '404' });
    expect(failed.fetch).toBe(null);
    const loaded = resolveFrame({ ...ASKED, env: 'park' }, OFFERS);
    expect([loaded.film.env, loaded.fetch, loaded.notices]).toEqual(['park', null, []]);
  });

  it('keeps the frame shown while the next programs compile only where the GPU compiles in parallel', () => {
    expect(resolveFrame(ASKED, OFFERS).keepsFrameWhileCompiling).toBe(true);
    expect(resolveFrame(ASKED, { ...OFFERS, compilesInParallel: false }).keepsFrameWhileCompiling).toBe(false);
  });

  it('a new light whose transform is not ready keeps the light shown for a method that reads it, and says which is pending', () => {
    const asked = { ...ASKED, mode: 'fourier' as const, illuminant: 'D93' as const };
    const waiting = { ...OFFERS, lightShown: D65_WHITE, lightReady: () => false };
    const frame = resolveFrame(asked, waiting);
    expect([frame.film.illuminant, frame.film.normalization]).toEqual(['D65', 'white']);
    expect(frame.lightPending).toEqual({ illuminant: 'D93', lightTint: asked.lightTint, normalization: asked.normalization });
    expect(frame.notices.map((n) => n.setting)).toEqual(['illuminant']);
    // Ready, or a method that reads no transform (the table's own pass fills it), or no light shown yet: the light asked for.
    for (const [mode, offers] of [
      ['fourier', { ...waiting, lightReady: () => true }],
      ['exact', waiting],
      ['fourier', { ...waiting, lightShown: null }],
    ] as const) {
      const drawn = resolveFrame({ ...asked, mode }, offers);
      expect([drawn.film.illuminant, drawn.lightPending]).toEqual(['D93', null]);
    }
  });
});

describe('the governor, the device and the flowing film', () => {
  const CHOICE = { gridN: 48, pixelRatio: 0.75, stepsPerFrame: 5 };

  it("the governor's grid, pixel ratio and steps where the user left them, each grid and ratio with a notice", () => {
    const frame = resolveFrame(FLOW, { ...OFFERS, choice: CHOICE, devicePixelRatio: 2 });
    expect([frame.film.gridN, frame.pixelRatio, frame.stepsPerFrame]).toEqual([48, 0.75, 5]);
    expect(frame.notices).toEqual([
      { setting: 'gridN', asked: 'auto', drawn: 48, message: null },
      { setting: 'pixelRatio', asked: 'auto', drawn: 0.75, message: null },
    ]);
  });

  it("what the user gave is drawn exactly; a given speed takes every step the time asks; a frozen view takes its quality's steps", () => {
    const given = resolveFrame({ ...FLOW, gridN: 24, pixelRatio: 1.5, simSpeed: 2 }, { ...OFFERS, choice: CHOICE });
    expect([given.film.gridN, given.pixelRatio, given.stepsPerFrame, given.film.simSpeed]).toEqual([24, 1.5, Infinity, 2]);
    expect(given.notices).toEqual([]);
    // A frozen view: the flow's default grid, 128 (docs/flow.md's table of parameters), at the quality's steps.
    const frozen = resolveFrame({ ...FLOW, animate: false }, OFFERS);
    expect([frozen.film.gridN, frozen.stepsPerFrame]).toEqual([128, 8]);
  });

  it('the device pixel ratio is drawn up to 2, a larger one capped with a notice; a ratio given is drawn as given', () => {
    expect(resolveFrame(ASKED, { ...OFFERS, devicePixelRatio: 1.5 }).pixelRatio).toBe(1.5);
    const dense = resolveFrame(ASKED, { ...OFFERS, devicePixelRatio: 3 });
    expect(dense.pixelRatio).toBe(2);
    expect(dense.notices).toEqual([{ setting: 'pixelRatio', asked: 'auto', drawn: 2, message: null }]);
    expect(resolveFrame({ ...ASKED, pixelRatio: 3 }, { ...OFFERS, devicePixelRatio: 3 }).pixelRatio).toBe(3);
  });
});

describe("the field as drawn: what it derives, once, and the table's range", () => {
  it("a flowing film's parameters are derived of the film drawn: the governor's grid in them, a frozen view's default grid", () => {
    const governed = resolveFrame(FLOW, { ...OFFERS, choice: { gridN: 48, pixelRatio: 1, stepsPerFrame: 5 } });
    expect(governed.field.derived).toEqual(flowParametersOf({ ...filmSettingsOf(FLOW), gridN: 48 }));
    expect(governed.field.derived).toMatchObject({ gridN: 48, seed: 7, thicknessNm: 600 });
    // A frozen view: the flow's default grid, 128 (docs/flow.md's table of parameters).
    expect(resolveFrame({ ...FLOW, animate: false }, OFFERS).field.derived).toMatchObject({ gridN: 128, seed: 7 });
    // The film table covers the field drawn: its range is the field's largest thickness, above the mean.
    expect(governed.field.maxThicknessNm).toBe(maxFieldThicknessNm(governed.film));
    expect(governed.field.maxThicknessNm).toBeGreaterThan(600);
    expect(Object.isFrozen(governed.field)).toBe(true);
  });

  it("a field whose film does not evolve derives nothing; a uniform film's table reaches its thickness, a swirl's its field's largest", () => {
    const uniform = resolveFrame({ ...ASKED, field: 'uniform', thicknessNm: 420 }, OFFERS);
    expect(uniform.field).toEqual({ derived: null, maxThicknessNm: 420 });
    const swirl = resolveFrame(ASKED, { ...OFFERS, choice: { gridN: 48, pixelRatio: 1, stepsPerFrame: 5 } });
    expect(swirl.field.derived).toBeNull();
    expect(swirl.field.maxThicknessNm).toBe(maxFieldThicknessNm(swirl.film));
  });

  it('a frame retimed is the frame resolved at that time, for every field, governed or not (nothing else it resolves moves with the clock)', () => {
    const choice = { gridN: 48, pixelRatio: 1, stepsPerFrame: 5 };
    for (const field of FIELDS)
      for (const offers of [OFFERS, { ...OFFERS, choice }]) {
        const asked = { ...FLOW, field, timeSeconds: 1.5 };
        const later = retimed(resolveFrame(asked, offers), 42.25);
        expect(later).toEqual(resolveFrame({ ...asked, timeSeconds: 42.25 }, offers));
        expect(Object.isFrozen(later)).toBe(true);
      }
  });

  it('a frame resolved again from equal settings and offers is the same frame; any setting or offer that changes it makes another', () => {
    const frame = resolveFrame(ASKED, OFFERS);
    expect(sameFrame(frame, resolveFrame({ ...ASKED }, { ...OFFERS }))).toBe(true);
    expect(sameFrame(frame, resolveFrame({ ...ASKED, nInside: 'Au' }, OFFERS))).toBe(false);
    expect(sameFrame(frame, resolveFrame(ASKED, { ...OFFERS, devicePixelRatio: 1.5 }))).toBe(false);
    expect(sameFrame(frame, retimed(frame, 3))).toBe(false);
  });
});
