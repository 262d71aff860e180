import { writeFileSync } from 'node:fs';
import type { Page } from '@playwright/test';
import { expect, test } from './fixtures.ts';
import { deltaE00 } from '../../src/physics/colorDifference.ts';
import { POLARIZATIONS } from '../../src/physics/filmReflectance.ts';
import { spectralBins, stackBinnedXyz } from '../../src/physics/binnedIntegration.ts';
import { filmXyz, whiteXyz } from '../../src/physics/spectralIntegration.ts';
import { type Xyz, spectralWeights } from '../../src/physics/spectralWeights.ts';
import { DEFAULT_FILM_QUALITY } from '../../src/settings/filmQuality.ts';
import { MODES } from '../../src/settings/filmSettings.ts';
import { methodReads } from '../../src/methods/methods.ts';
import type { ParityGroup, ParityMode } from '../../scripts/harness/parityCase.ts';
import { MAX_DELTA_E00_FIXED, MAX_DELTA_E00_STRESS, WHITE_BOUND_SLACK } from '../tolerances.ts';

/**
 * The shader under numerical stress (docs/gpu.md#float32-limits), through the float-target harness
 * (tests/e2e/harness/parity.ts, the real shaders/film/filmColor.glsl): a dense grid over the whole
 * domain never gives NaN, ±Infinity, a negative or an impossibly bright XYZ, in either mode;
 * then where float32 stops being good enough in `exact` mode, against the float64 reference.
 */

/** Indices 1–4 in every order: film above, below, equal to its media; TIR at either face; frustrated TIR. */
const STACKS = [
  [1, 1.33, 1],
  [1, 4, 1],
  [1, 1, 1],
  [4, 4, 4],
  [1, 1.33, 4],
  [4, 2.5, 1],
  [4, 1, 1],
  [1.5, 1.33, 1],
  [1.33, 1.5, 1],
  [2, 1.2, 3],
] as const;
const THICKNESSES_NM = [0, 0.5, 10, 100, 550, 2000, 7000, 12000, 17000, 20000];
/** cos θ_i from grazing (90°) to normal incidence, both ends included. */
const COSINES = [0, 1e-6, 1e-3, 0.02, 0.1, 0.3, 0.6, 0.9, 0.999, 1];

/**
 * Every stack × polarisation per fragment (`exact`, `fourier`); in `table` mode, where each group
 * builds its own table, each stack with one polarisation, in turn.
 */
function domainGroups(mode: ParityMode): ParityGroup[] {
  const inputs = THICKNESSES_NM.flatMap((t) => COSINES.map((c) => [t, c] as const));
  return STACKS.flatMap(([nOutside, nFilm, nInside], i) =>
    (!methodReads(mode, 'table') ? POLARIZATIONS : [POLARIZATIONS[i % POLARIZATIONS.length]!]).map((polarization) => ({
      nOutside,
      nFilm,
      nInside,
      polarization,
      inputs,
      illuminant: i % 2 ? 'D65' : { daylightCct: 25000 }, // the bluest light has the largest X, Z
      normalization: 'white',
    })),
  );
}

async function render(page: Page, groups: readonly ParityGroup[], mode: ParityMode): Promise<number[][][]> {
  return page.evaluate(([g, m]) => window.renderFilmXyz!(g, m), [groups, mode] as const);
}

for (const mode of MODES) {
  test(`${mode} mode: no NaN, Infinity, negative or over-white XYZ anywhere in the domain`, async ({ parityPage: page }) => {
    const groups = domainGroups(mode);
    const rendered = await render(page, groups, mode);
    const bad: string[] = [];
    groups.forEach((g, gi) => {
      const white = whiteXyz(g.illuminant, g.normalization);
      g.inputs.forEach(([t, c], ci) => {
        const xyz = rendered[gi]![ci]!;
        const ok = xyz.every((v, k) => Number.isFinite(v) && v >= 0 && v <= white[k]! * (1 + WHITE_BOUND_SLACK));
        if (!ok) bad.push(`${JSON.stringify({ ...g, inputs: undefined, t, c })}: ${xyz}`);
      });
    });
    expect(groups.length * THICKNESSES_NM.length * COSINES.length).toBe(methodReads(mode, 'table') ? 1000 : 4000);
    expect(bad.slice(0, 10), `${bad.length} bad pixels`).toEqual([]);
  });
}

/** The float64 twin of the shader's method: the same 90 bins and closed-form means. */
function binned64(g: ParityGroup, thicknessNm: number, angleDeg: number): Xyz {
  const bins = spectralBins(spectralWeights(g.illuminant, g.normalization), DEFAULT_FILM_QUALITY.exactSpectralBins);
  return stackBinnedXyz({ ...g, thicknessNm, angleDeg }, g.polarization, bins);
}

/** ΔE00 steps where float32 is called no longer good enough: the parity bound, and a just-noticeable difference. */
const LIMITS = [MAX_DELTA_E00_FIXED, MAX_DELTA_E00_STRESS] as const;

test('exact mode: where float32 stops being good enough, along thickness and along angle', async ({ parityPage: page }) => {
  const soap = { nOutside: 1, nFilm: 1.33, nInside: 1, illuminant: 'D65', polarization: 'unpolarized', normalization: 'white' } as const;
  const sweeps: { label: string; cases: [number, number][] }[] = [
    ...[0, 45, 80, 89].map((a) => ({
      label: `thickness 0–20 µm at ${a}°`,
      cases: Array.from({ length: 401 }, (_, i): [number, number] => [50 * i, a]),
    })),
    ...[300, 2000, 10000, 20000].map((t) => ({
      label: `angle 0–89.99° at ${t} nm`,
      cases: [...Array.from({ length: 179 }, (_, i) => i / 2), 89.5, 89.7, 89.9, 89.95, 89.99].map((a): [number, number] => [t, a]),
    })),
  ];
  const groups = sweeps.map((s) => ({ ...soap, inputs: s.cases.map(([t, a]) => [t, Math.sin(((90 - a) * Math.PI) / 180)] as const) }));
  const rendered = await render(page, groups, 'exact');
  const white = whiteXyz('D65');
  const figures = sweeps.map((s, si) => {
    const vs64 = s.cases.map(([t, a], ci) => deltaE00(rendered[si]![ci]! as unknown as Xyz, binned64(groups[si]!, t, a), white));
    const vsRef = s.cases.map(([t, a], ci) =>
      deltaE00(rendered[si]![ci]! as unknown as Xyz, filmXyz({ ...soap, thicknessNm: t, angleDeg: a }, soap), white),
    );
    const first = (d: number[], limit: number) => s.cases[d.findIndex((v) => v > limit)] ?? null;
    return {
      sweep: s.label,
      maxFloat32Only: Math.max(...vs64),
      maxVsReference: Math.max(...vsRef),
      ...Object.fromEntries(
        LIMITS.flatMap((l) => [
          [`float32 > ${l}`, first(vs64, l)],
          [`vs reference > ${l}`, first(vsRef, l)],
        ]),
      ),
    };
  });
  for (const f of figures) console.log(`float32 ${JSON.stringify(f)}`);
  writeFileSync(new URL('./float32-figures.json', import.meta.url), `${JSON.stringify(figures, null, 2)}\n`);
  // Measured: float32 alone stays under the parity bound along every sweep (max 0.36, 300 nm near grazing).
  for (const f of figures) expect(f.maxFloat32Only, f.sweep).toBeLessThanOrEqual(LIMITS[0]);
  // Against the reference the 90 bins' own sampling error adds (beyond 18.25 µm); measured max 0.71.
  for (const f of figures) expect(f.maxVsReference, f.sweep).toBeLessThanOrEqual(LIMITS[1]);
});

/** Inside this fraction of the bubble's radius a pixel sees film over sky or ground, never pure black. */
const DISC_FRACTION = 0.97;

test('the whole bubble pipeline at extreme settings draws no black (NaN) pixel inside the bubble', async ({ page }) => {
  const extremes = [
    'thickness=0&nFilm=4&nOutside=4&nInside=1',
    'thickness=20000&thicknessRange=20000&nFilm=4&exposure=100&space=wide-gamut',
    'thickness=20000&nOutside=4&nInside=1&nFilm=1&polarization=paper&exposure=100',
  ];
  await page.setViewportSize({ width: 240, height: 180 }); // exact mode at 20 µm is slow on SwiftShader
  for (const mode of ['exact', 'table']) {
    for (const query of extremes) {
      await page.goto(`/?${query}&mode=${mode}&field=swirl&animate=0&time=5&env=sky&sides=both`);
      await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready', { timeout: 60_000 });
      const black = await page.evaluate((fraction) => {
        // The frame the page drew (its drawing buffer is preserved): exact mode takes seconds per frame here.
        const view = (window as unknown as { bubbleView: import('../../src/view/bubbleView.ts').BubbleView }).bubbleView;
        const gl = view.renderer.getContext();
        const [w, h] = [gl.drawingBufferWidth, gl.drawingBufferHeight];
        const pixels = new Uint8Array(4 * w * h);
        gl.bindFramebuffer(gl.FRAMEBUFFER, null);
        gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
        // The unit bubble seen from distance 4 under a 35° vertical field: radius tan(asin ¼)/tan 17.5° of the half-height.
        const radius = (Math.tan(Math.asin(0.25)) / Math.tan((17.5 * Math.PI) / 180)) * (h / 2) * fraction;
        let count = 0;
        for (let y = 0; y < h; y++)
          for (let x = 0; x < w; x++) {
            if (Math.hypot(x + 0.5 - w / 2, y + 0.5 - h / 2) > radius) continue;
            const i = 4 * (y * w + x);
            if (pixels[i] === 0 && pixels[i + 1] === 0 && pixels[i + 2] === 0) count++;
          }
        return count;
      }, DISC_FRACTION);
      expect(black, `${mode}: ${query}`).toBe(0);
    }
  }
});
