import { describe, expect, it } from 'vitest';
import { FIELD_THICKNESS, LAYERS_DOMAIN, resolveLayers } from '../../../src/physics/stackFilms.ts';
import { mediumProblem, transparentIndexAt } from '../../../src/physics/medium.ts';
import {
  BEETLE_DEPTH_NM,
  BEETLE_HIGH_INDEX,
  BEETLE_LOW_INDEX,
  BEETLE_PAIRS,
  BEETLE_SURFACE_NM,
  BRAGG_PERIODS,
  CROWN_GLASS_INDEX,
  DESIGN_NM,
  MGF2_INDEX,
  STACK_PRESETS,
  STACK_PRESET_NAMES,
  type StackPreset,
  chirpedLayers,
} from '../../../src/physics/stackPresets.ts';
import { type LayerStack, layersReflectance } from '../../../src/physics/transferMatrix.ts';
import { ALGEBRAIC_TOL, BRAGG_BAND_CENTRE_G_TOL, BRAGG_PEAK_NM_TOL, TMM_GOLDEN_TOL } from '../../tolerances.ts';

const stackOf = (p: StackPreset, angleDeg = 0): LayerStack => ({
  nOutside: p.nOutside,
  films: resolveLayers(p.films, 0),
  nInside: p.nInside,
  angleDeg,
});

/** R(λ) every nm over 380–830 nm. */
function spectrum(stack: LayerStack): { lambdasNm: number[]; r: number[] } {
  const lambdasNm = Array.from({ length: 451 }, (_, i) => 380 + i);
  return { lambdasNm, r: lambdasNm.map((l) => layersReflectance(l, stack)) };
}

/** The first and last wavelength where R exceeds `level`, and where R peaks. */
function band(stack: LayerStack, level: (max: number) => number): { fromNm: number; toNm: number; peakNm: number } {
  const { lambdasNm, r } = spectrum(stack);
  const max = Math.max(...r);
  const above = lambdasNm.filter((_, i) => r[i]! > level(max));
  return { fromNm: above[0]!, toNm: above[above.length - 1]!, peakNm: lambdasNm[r.indexOf(max)]! };
}

describe('named stacks', () => {
  it('every preset lies within LAYERS_DOMAIN and the media domains, none following the field', () => {
    for (const name of STACK_PRESET_NAMES) {
      const p = STACK_PRESETS[name];
      const { count, thicknessNm } = LAYERS_DOMAIN;
      expect(p.films.length, name).toBeGreaterThanOrEqual(count.min);
      expect(p.films.length, name).toBeLessThanOrEqual(count.max);
      for (const layer of p.films) {
        expect(layer.thicknessNm, name).not.toBe(FIELD_THICKNESS);
        expect(layer.thicknessNm as number, name).toBeGreaterThanOrEqual(thicknessNm.min);
        expect(layer.thicknessNm as number, name).toBeLessThanOrEqual(thicknessNm.max);
        expect(mediumProblem(layer.n, 'film'), name).toBeNull();
      }
      expect(mediumProblem(p.nOutside, 'outside'), name).toBeNull();
      expect(mediumProblem(p.nInside, 'inside'), name).toBeNull();
      expect(p.source.length, name).toBeGreaterThan(0);
      expect(p.source, name).toMatch(/(19|20)\d\d/);
    }
  });

  it('the AR coating reflects, at its design wavelength and normal incidence, the quarter-wave closed form (Macleod): 1.26 %', () => {
    const p = STACK_PRESETS.arCoating;
    const [n0, n1, ns] = [1, MGF2_INDEX, CROWN_GLASS_INDEX];
    const closedForm = ((n0 * ns - n1 ** 2) / (n0 * ns + n1 ** 2)) ** 2;
    expect(Math.abs(layersReflectance(DESIGN_NM, stackOf(p)) - closedForm)).toBeLessThan(ALGEBRAIC_TOL);
    expect(closedForm).toBeCloseTo(0.0126, 4);
    // Less than the bare glass's 4.26 % across the visible.
    const bare = ((ns - n0) / (ns + n0)) ** 2;
    for (const l of [400, 500, 600, 700]) expect(layersReflectance(l, stackOf(p))).toBeLessThan(bare);
  });

  it('the Bragg mirror reflects the quarter-wave stack closed form, above 0.99, at its design wavelength', () => {
    const p = STACK_PRESETS.braggMirror;
    const [nH, nL] = [transparentIndexAt('TiO2', DESIGN_NM), transparentIndexAt('SiO2', DESIGN_NM)];
    // Macleod: each quarter wave maps the admittance Y → n²/Y, so (HL)^p on n_s gives Y = (n_H/n_L)^(2p) n_s.
    const y = (nH / nL) ** (2 * BRAGG_PERIODS) * CROWN_GLASS_INDEX;
    const r = layersReflectance(DESIGN_NM, stackOf(p));
    expect(Math.abs(r - ((1 - y) / (1 + y)) ** 2)).toBeLessThan(ALGEBRAIC_TOL);
    expect(r).toBeGreaterThan(0.99);
  });

  it("the Bragg mirror's band is centred on its design wavelength, its edges about Macleod's Δg", () => {
    const stack = stackOf(STACK_PRESETS.braggMirror);
    const half = band(stack, (max) => max / 2);
    expect(Math.abs(half.peakNm - DESIGN_NM)).toBeLessThanOrEqual(BRAGG_PEAK_NM_TOL);
    const g = (l: number) => DESIGN_NM / l;
    expect(Math.abs((g(half.fromNm) + g(half.toNm)) / 2 - 1)).toBeLessThan(BRAGG_BAND_CENTRE_G_TOL);
    // Δg is the edge of an infinite stack; a finite one's edges slope across it: above R = 0.9 the
    // band is narrower, above half its peak wider.
    const [nH, nL] = [transparentIndexAt('TiO2', DESIGN_NM), transparentIndexAt('SiO2', DESIGN_NM)];
    const dg = (2 / Math.PI) * Math.asin((nH - nL) / (nH + nL));
    const steep = band(stack, () => 0.9);
    expect((g(steep.fromNm) - g(steep.toNm)) / 2).toBeLessThan(dg);
    expect((g(half.fromNm) - g(half.toNm)) / 2).toBeGreaterThan(dg);
  });

  it('the Bragg mirror shifts towards blue at a slant', () => {
    const p = STACK_PRESETS.braggMirror;
    const peaks = [0, 30, 45, 60].map((a) => band(stackOf(p, a), (max) => max / 2).peakNm);
    for (let i = 1; i < peaks.length; i++) expect(peaks[i]!).toBeLessThan(peaks[i - 1]!);
  });

  it('the chirped stack reflects a wider band than a regular one of the same mean period', () => {
    const p = STACK_PRESETS.chirpedBeetle;
    const meanNm = (BEETLE_SURFACE_NM + BEETLE_DEPTH_NM) / 2;
    const regular = { ...p, films: chirpedLayers(BEETLE_HIGH_INDEX, BEETLE_LOW_INDEX, BEETLE_PAIRS, meanNm, meanNm) };
    const total = (q: StackPreset) => resolveLayers(q.films, 0).reduce((sum, l) => sum + l.thicknessNm, 0);
    // The same mean period: the quarter-wave thicknesses are linear in the design wavelength.
    expect(total(p)).toBeCloseTo(total(regular), 9);
    const width = (q: StackPreset) => {
      const b = band(stackOf(q), (max) => max / 2);
      return b.toNm - b.fromNm;
    };
    expect(width(p)).toBeGreaterThan(2 * width(regular));
  });

  it('nacre and the chirped stack reflect what tmm (Byrnes 2016, v0.2.0) computes for the same films', () => {
    // coh_tmm('s'/'p', [1, …films, inside], [inf, …d, inf], θ, λ), unpolarised = the mean.
    const golden: [keyof typeof STACK_PRESETS, number, number, number][] = [
      ['nacre', 440, 0, 0.5769420740337887],
      ['nacre', 587, 0, 0.44499395389698654],
      ['nacre', 500, 30, 0.038754762155286795],
      ['chirpedBeetle', 440, 0, 0.0901400223053497],
      ['chirpedBeetle', 587, 0, 0.3513989809254733],
      ['chirpedBeetle', 500, 30, 0.46264426707422057],
    ];
    for (const [name, l, angle, r] of golden)
      expect(Math.abs(layersReflectance(l, stackOf(STACK_PRESETS[name], angle)) - r), `${name} ${l} nm ${angle}°`).toBeLessThan(
        TMM_GOLDEN_TOL,
      );
  });
});
