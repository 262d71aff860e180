/**
 * A metal's complex index from its colour (Gulbrandsen 2014): the remapping's round trip against
 * the normal-incidence Fresnel reflectance written here, its limits, the paper's inverse on a
 * measured metal, the channels' wavelengths against the spectrum locus, and the bare metal's colour.
 */
import { describe, expect, it } from 'vitest';
import {
  ARTIST_METAL_MAX_REFLECTIVITY,
  CHANNEL_WAVELENGTHS_NM,
  artistMetalIndex,
  artistMetalMedium,
} from '../../../src/physics/artistMetal.ts';
import { XYZ_TO_LINEAR_SRGB, applyMatrix3, invert3 } from '../../../src/physics/colorConversions.ts';
import { deltaE00 } from '../../../src/physics/colorDifference.ts';
import { CIE1931_CMF_START_NM, CIE1931_XBAR, CIE1931_YBAR, CIE1931_ZBAR } from '../../../src/physics/data/cie1931Cmf2deg.ts';
import { mediumIndexAt } from '../../../src/physics/medium.ts';
import { filmXyz } from '../../../src/physics/spectralIntegration.ts';
import { ALGEBRAIC_TOL, ARTIST_METAL_BARE_DE00, ROUNDING_TOL } from '../../tolerances.ts';

/** |(ñ − 1)/(ñ + 1)|² by complex division: air onto ñ at normal incidence (Born & Wolf's r = (1 − ñ)/(1 + ñ)). */
function normalReflectance(n: number, k: number): number {
  const [ar, ai, br, bi] = [n - 1, k, n + 1, k];
  const d = br * br + bi * bi;
  const [qr, qi] = [(ar * br + ai * bi) / d, (ai * br - ar * bi) / d];
  return qr * qr + qi * qi;
}

describe('the remapping r, g → n, k', () => {
  it('gives back r as the normal-incidence reflectance for every edge tint', () => {
    let worst = 0;
    for (let r = 0.01; r <= ARTIST_METAL_MAX_REFLECTIVITY; r += 0.0485)
      for (let g = 0; g <= 1; g += 0.125) {
        const z = artistMetalIndex(r, g);
        worst = Math.max(worst, Math.abs(normalReflectance(z.re, z.im) - r));
      }
    expect(worst).toBeLessThan(ALGEBRAIC_TOL);
  });

  it("is a dielectric at g = 0 (k = 0) and takes the paper's least n at g = 1", () => {
    for (const r of [0.04, 0.5, 0.9]) {
      const s = Math.sqrt(r);
      const dielectric = artistMetalIndex(r, 0);
      expect(dielectric.im).toBeLessThan(1e-6);
      expect(Math.abs(dielectric.re - (1 + s) / (1 - s))).toBeLessThan(ALGEBRAIC_TOL);
      expect(Math.abs(artistMetalIndex(r, 1).re - (1 - r) / (1 + r))).toBeLessThan(ROUNDING_TOL);
    }
  });

  it("recovers gold's measured ñ from its r and the paper's inverse g = (n_max − n)/(n_max − n_min)", () => {
    const [n, k] = [0.43, 2.455]; // Johnson & Christy 1972, 548.6 nm
    const r = normalReflectance(n, k);
    const s = Math.sqrt(r);
    const [nMin, nMax] = [(1 - r) / (1 + r), (1 + s) / (1 - s)];
    const z = artistMetalIndex(r, (nMax - n) / (nMax - nMin));
    expect(Math.abs(z.re - n)).toBeLessThan(ALGEBRAIC_TOL);
    expect(Math.abs(z.im - k)).toBeLessThan(ALGEBRAIC_TOL);
  });

  it('stays finite at r = 1 and beyond, and at the ends of g', () => {
    for (const [r, g] of [
      [1, 1],
      [1, 0],
      [1.5, 0.5],
      [0, 1],
      [0, 0],
    ] as const) {
      const z = artistMetalIndex(r, g);
      expect(Number.isFinite(z.re) && Number.isFinite(z.im) && z.re >= 0.01 && z.im >= 0, `${r}, ${g}`).toBe(true);
    }
  });
});

describe('the metal as a medium', () => {
  it("places the channels at the sRGB primaries' dominant wavelengths on the CIE 1931 locus", () => {
    const white = [0.3127, 0.329]; // D65
    const primaries = { r: [0.64, 0.33], g: [0.3, 0.6], b: [0.15, 0.06] }; // IEC 61966-2-1
    for (const [name, [x, y]] of Object.entries(primaries)) {
      const hue = Math.atan2(y! - white[1]!, x! - white[0]!);
      let best = { nm: 0, off: Infinity };
      for (let i = 20; i < 400; i++) {
        const [X, Y, Z] = [CIE1931_XBAR[i]!, CIE1931_YBAR[i]!, CIE1931_ZBAR[i]!];
        const s = X + Y + Z;
        const off = Math.abs(Math.atan2(Y / s - white[1]!, X / s - white[0]!) - hue);
        if (off < best.off) best = { nm: CIE1931_CMF_START_NM + i, off };
      }
      expect(Math.abs(best.nm - CHANNEL_WAVELENGTHS_NM[name as 'r' | 'g' | 'b']), name).toBeLessThanOrEqual(0.5);
    }
  });

  it('shows its base colour when bare, under D65, for gold, copper, silver and iron', () => {
    const toXyz = invert3(XYZ_TO_LINEAR_SRGB);
    const white = applyMatrix3(toXyz, [1, 1, 1]);
    for (const color of [
      [1, 0.766, 0.336],
      [0.955, 0.638, 0.538],
      [0.972, 0.96, 0.915],
      [0.56, 0.57, 0.58],
    ] as const) {
      for (const tint of [color, [1, 1, 1] as const]) {
        const bare = filmXyz({ nOutside: 1, nFilm: 1.5, nInside: artistMetalMedium(color, tint), thicknessNm: 0, angleDeg: 0 });
        expect(deltaE00(bare, applyMatrix3(toXyz, color), white), `${color} ${tint}`).toBeLessThan(ARTIST_METAL_BARE_DE00);
      }
    }
  });

  it('absorbs and keeps k ≥ 0, n in its domain, at every λ of the band', () => {
    const metal = artistMetalMedium([1, 0.766, 0.336], [1, 1, 1]);
    for (let l = 380; l <= 830; l += 7) {
      const z = mediumIndexAt(metal, l) as { re: number; im: number };
      expect(z.re >= 0.01 && z.re <= 10 && z.im > 0, `${l} nm`).toBe(true);
    }
  });
});
