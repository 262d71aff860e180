/**
 * The table's per-row series terms, read by their names as the table pass reads them: at normal
 * incidence on a lossless film they are the Airy function's own (its mean over the phase, the ratio
 * of its geometric series, its value at phase 0 and π), for light from outside and from inside.
 */
import { describe, expect, it } from 'vitest';
import { AIRY_ROW, airySeriesRows, airySeriesRowsTexture } from '../../../src/film/airySeriesRows.ts';
import { TEXEL_FLOATS } from '../../../src/gpu/texelRecord.ts';
import { DEFAULT_FILM_QUALITY } from '../../../src/settings/filmQuality.ts';

/** The rows are float32: a few roundings of a value of order 1 (2⁻²⁴ relative each). */
const FLOAT32_TOL = 1e-6;

const LAYOUT = { ...DEFAULT_FILM_QUALITY.table, rows: 4 };
const FILM = { nOutside: 1, nFilm: 1.33, nInside: 1.5, polarization: 'unpolarized' } as const;

/** Field `name` of record `index`, as shaders/gpu/texelRecord.glsl reads it (texel offset / 4, channel offset % 4). */
function field(data: Float32Array, index: number, name: keyof typeof AIRY_ROW.fields): number[] {
  const at = index * AIRY_ROW.floats + AIRY_ROW.offsets[name];
  return [...data.subarray(at, at + AIRY_ROW.fields[name])];
}

/** The Airy reflectance of a film between media a and c at normal incidence, at phase φ: |r₁ + r₂e^{iφ}|² / |1 + r₁r₂e^{iφ}|². */
const airyReflectance = (r1: number, r2: number, cosPhi: number): number =>
  (r1 * r1 + r2 * r2 + 2 * r1 * r2 * cosPhi) / (1 + r1 * r1 * r2 * r2 + 2 * r1 * r2 * cosPhi);

describe('airySeriesRows', () => {
  it('a row per texel record: the texture holds AIRY_ROW.texels texels per row, both halves', () => {
    const texture = airySeriesRowsTexture(LAYOUT);
    expect([texture.image.width, texture.image.height]).toEqual([AIRY_ROW.texels, 2 * LAYOUT.rows]);
    expect(texture.image.data).toHaveLength(AIRY_ROW.texels * TEXEL_FLOATS * 2 * LAYOUT.rows);
  });

  it('at normal incidence, each field by name holds its quantity of the Airy function, from outside and from inside', () => {
    const data = airySeriesRowsTexture(LAYOUT).image.data as Float32Array;
    airySeriesRows(FILM, LAYOUT, data);
    const normal = LAYOUT.rows - 1; // cos θ_i = 1
    const halves = [
      { index: normal, na: FILM.nOutside, nc: FILM.nInside },
      { index: LAYOUT.rows + normal, na: FILM.nInside, nc: FILM.nOutside },
    ];
    for (const { index, na, nc } of halves) {
      const nb = FILM.nFilm;
      const r1 = (na - nb) / (na + nb);
      const r2 = (nb - nc) / (nb + nc);
      const [R1, R2] = [r1 * r1, r2 * r2];
      // The phase average of the Airy reflectance (the incoherent sum), and the ratio of its series, r_ba r_bc.
      const c0 = (R1 + R2 - 2 * R1 * R2) / (1 - R1 * R2);
      const q = -r1 * r2;
      expect(Math.abs(field(data, index, 'PATH_PER_NM')[0]! - 2 * nb)).toBeLessThan(FLOAT32_TOL * 2 * nb);
      expect(field(data, index, 'REAL_PATH')).toEqual([1]);
      for (const [C0, B, Q] of [
        ['C0_0', 'B_0', 'Q_0'],
        ['C0_1', 'B_1', 'Q_1'],
      ] as const) {
        expect(Math.abs(field(data, index, C0)[0]! - c0)).toBeLessThan(FLOAT32_TOL);
        const [qRe, qIm] = field(data, index, Q);
        expect(Math.abs(qRe! - q) + Math.abs(qIm!)).toBeLessThan(FLOAT32_TOL);
        // R(φ) = C₀ + 2 Re(B Σ_{m≥1} q^{m−1} e^{imφ}): at φ = 0 the sum is 1/(1 − q), at φ = π it is −1/(1 + q).
        const [bRe, bIm] = field(data, index, B);
        expect(Math.abs(bIm!)).toBeLessThan(FLOAT32_TOL);
        expect(Math.abs(c0 + (2 * bRe!) / (1 - q) - airyReflectance(r1, r2, 1))).toBeLessThan(FLOAT32_TOL);
        expect(Math.abs(c0 - (2 * bRe!) / (1 + q) - airyReflectance(r1, r2, -1))).toBeLessThan(FLOAT32_TOL);
      }
    }
  });
});
