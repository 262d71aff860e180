import { describe, expect, it } from 'vitest';
import { XYZ_TO_LINEAR_SRGB, applyMatrix3, encode8, mapToGamut } from '../../../src/physics/colorConversions.ts';
import { SOAP_FILM_IN_AIR } from '../../../src/physics/filmReflectance.ts';
import { filmXyz } from '../../../src/physics/spectralIntegration.ts';
import { DEFAULT_SETTINGS } from '../../../src/settings/filmParameters.ts';
import type { EnvironmentPixels } from '../../../src/bubbleMaterials/environmentMaps.ts';
import type { FilmSettings } from '../../../src/settings/filmSettings.ts';
import { toneMap } from '../../../src/bubbleTwins/toneMapping.ts';
import { cpuBubbleImage } from '../../../src/bubbleTwins/cpuBubbleImage.ts';

/** The image uses the shader's binned integral (ΔE00 ≤ 0.11 from the reference): one 8-bit code. */
const MAX_CODE_DIFFERENCE = 1;
const SIZE = 240;
const film = (over: Partial<FilmSettings>): FilmSettings => ({
  ...DEFAULT_SETTINGS,
  field: 'uniform',
  env: 'none',
  sides: 'front',
  ...over,
});
const pixel = (image: Uint8ClampedArray, col: number, row: number) => [...image.slice(4 * (row * SIZE + col), 4 * (row * SIZE + col) + 4)];

describe('the CPU still image of the bubble', () => {
  it('shows at its centre the reference colour of the film seen head-on', () => {
    for (const thicknessNm of [150, 450, 1000]) {
      const image = cpuBubbleImage(film({ thicknessNm }), SIZE, SIZE);
      const xyz = filmXyz({ ...SOAP_FILM_IN_AIR, thicknessNm, angleDeg: 0 }, { illuminant: 'D65' });
      const expected = mapToGamut(applyMatrix3(XYZ_TO_LINEAR_SRGB, xyz), xyz[1]).map(encode8);
      const centre = pixel(image, SIZE / 2, SIZE / 2);
      expect(centre[3]).toBe(255);
      for (let i = 0; i < 3; i++)
        expect(Math.abs(centre[i]! - expected[i]!), `${thicknessNm} nm: ${centre} vs ${expected}`).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
    }
  });

  it("has the bubble's silhouette where the 35° camera at distance 4 sees it, and the background outside", () => {
    // The unit sphere subtends asin(1/4) from the camera: tan(asin(1/4)) / tan(17.5°) of the half-height.
    const radiusPx = (Math.tan(Math.asin(1 / 4)) / Math.tan((17.5 * Math.PI) / 180)) * (SIZE / 2);
    const image = cpuBubbleImage(film({ thicknessNm: 450, exposure: 100 }), SIZE, SIZE);
    const c = SIZE / 2;
    const inside = Math.floor(radiusPx - 2),
      outside = Math.ceil(radiusPx + 2);
    for (const [col, row] of [
      [c + inside, c],
      [c - inside, c],
      [c, c + inside],
      [c, c - inside],
    ] as const) {
      expect(
        pixel(image, col, row)
          .slice(0, 3)
          .some((v) => v > 0),
        `inside at ${col},${row}`,
      ).toBe(true);
    }
    for (const [col, row] of [
      [c + outside, c],
      [c - outside, c],
      [c, c + outside],
      [c, c - outside],
      [0, 0],
      [SIZE - 1, SIZE - 1],
    ] as const) {
      expect(pixel(image, col, row), `outside at ${col},${row}`).toEqual([0, 0, 0, 255]);
    }
  });

  it('in a uniform environment the bubble vanishes: each wall passes on what it does not reflect (T = 1 − R)', () => {
    const L = [0.9, 0.5, 0.3];
    const uniform: EnvironmentPixels = { width: 4, height: 2, rgba: Float32Array.from({ length: 32 }, (_, k) => [...L, 1][k & 3]!) };
    for (const over of [
      { thicknessNm: 3000, sides: 'both', tonemap: 'none' },
      { thicknessNm: 1200, field: 'drainage', thicknessRangeNm: 1500, sides: 'both', tonemap: 'agx', exposure: 2 },
    ] as const) {
      const s = film({ ...over, env: 'park', envRotationDeg: 40 });
      const expected = [
        ...toneMap(L.map((v) => s.exposure * v) as unknown as readonly [number, number, number], s.tonemap as 'none' | 'agx').map((v) =>
          encode8(Math.min(1, v)),
        ),
        255,
      ];
      const image = cpuBubbleImage(s, SIZE, SIZE, uniform);
      for (const [col, row] of [
        [SIZE / 2, SIZE / 2],
        [SIZE / 2 + 40, SIZE / 2 - 60],
        [SIZE / 2 - 85, SIZE / 2],
        [5, 5],
      ] as const) {
        const got = pixel(image, col, row);
        for (let i = 0; i < 3; i++)
          expect(Math.abs(got[i]! - expected[i]!), `${JSON.stringify(over)} at ${col},${row}: ${got} vs ${expected}`).toBeLessThanOrEqual(
            MAX_CODE_DIFFERENCE,
          );
      }
    }
  });

  it('a uniform colour (env=color:R,G,B) draws what a map of that one colour draws, pixel for pixel, with no map', () => {
    // Exact in float32, as the map's texels are.
    const L = [0.75, 0.5, 0.25] as const;
    const uniform: EnvironmentPixels = { width: 4, height: 2, rgba: Float32Array.from({ length: 32 }, (_, k) => [...L, 1][k & 3]!) };
    for (const over of [
      { thicknessNm: 700, sides: 'both' },
      { thicknessNm: 100, nFilm: 1.38, nInside: 'Au', sides: 'both' },
    ] as const) {
      const asMap = cpuBubbleImage(film({ ...over, env: 'park', tonemap: 'none' }), SIZE / 4, SIZE / 4, uniform);
      const asColor = cpuBubbleImage(film({ ...over, env: { color: L }, tonemap: 'auto' }), SIZE / 4, SIZE / 4);
      expect(asColor, JSON.stringify(over)).toEqual(asMap);
    }
  });

  it("over a metal in a grey room of g, the centre is g times the metal's colour (linear in the light it reflects), the background g", () => {
    const g = 0.5;
    const s = film({ thicknessNm: 0, nInside: 'Au', sides: 'both', env: { color: [g, g, g] } });
    const image = cpuBubbleImage(s, SIZE, SIZE);
    const r = applyMatrix3(XYZ_TO_LINEAR_SRGB, filmXyz({ nOutside: 1, nFilm: 1.33, nInside: 'Au', thicknessNm: 0, angleDeg: 0 }));
    const expected = r.map((v) => encode8(Math.min(1, Math.max(0, g * v))));
    const centre = pixel(image, SIZE / 2, SIZE / 2);
    for (let i = 0; i < 3; i++)
      expect(Math.abs(centre[i]! - expected[i]!), `${centre} vs ${expected}`).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
    expect(pixel(image, 5, 5)).toEqual([encode8(g), encode8(g), encode8(g), 255]);
  });

  it('over a metal the sphere is opaque: in a uniform environment it shows M L (the film under L as a spectrum), no far wall, nothing behind; the background stays L', () => {
    const L = [0.9, 0.5, 0.3] as const;
    const uniform: EnvironmentPixels = { width: 4, height: 2, rgba: Float32Array.from({ length: 32 }, (_, k) => [...L, 1][k & 3]!) };
    const s = film({ thicknessNm: 100, nFilm: 1.38, nInside: 'Au', sides: 'both', env: 'park', tonemap: 'none' });
    const image = cpuBubbleImage(s, SIZE, SIZE, uniform);
    // The float64 film under the light tinted L: L's spectrum by the basis, no matrix involved.
    const r = applyMatrix3(
      XYZ_TO_LINEAR_SRGB,
      filmXyz({ nOutside: 1, nFilm: 1.38, nInside: 'Au', thicknessNm: 100, angleDeg: 0 }, { lightTint: L }),
    );
    const expected = r.map((v) => encode8(Math.min(1, Math.max(0, v))));
    const centre = pixel(image, SIZE / 2, SIZE / 2);
    for (let i = 0; i < 3; i++)
      expect(Math.abs(centre[i]! - expected[i]!), `${centre} vs ${expected}`).toBeLessThanOrEqual(MAX_CODE_DIFFERENCE);
    expect(pixel(image, 5, 5).slice(0, 3)).toEqual(L.map((v) => encode8(v)));
  });
  it('a tinted light t is a colour the film reflects through its matrix: with no environment the centre is the float64 film under the tinted light; in a room of c, under the light tinted t·c', () => {
    const t = [1, 0.5, 0.2] as const;
    const c = [0.4, 0.9, 0.8] as const;
    const cases = [
      [film({ thicknessNm: 600, lightTint: t }), { ...SOAP_FILM_IN_AIR, thicknessNm: 600 }, t],
      [
        film({ thicknessNm: 300, nFilm: 1.38, nInside: 'Au', sides: 'both', lightTint: t }),
        { nOutside: 1, nFilm: 1.38, nInside: 'Au', thicknessNm: 300 },
        t,
      ],
      [
        film({ thicknessNm: 300, nFilm: 1.38, nInside: 'Au', sides: 'both', lightTint: t, env: { color: c }, tonemap: 'none' }),
        { nOutside: 1, nFilm: 1.38, nInside: 'Au', thicknessNm: 300 },
        t.map((v, i) => v * c[i]!),
      ],
    ] as const;
    for (const [s, stack, tint] of cases) {
      const xyz = filmXyz({ ...stack, angleDeg: 0 }, { lightTint: tint as unknown as readonly [number, number, number] });
      const expected = applyMatrix3(XYZ_TO_LINEAR_SRGB, xyz).map((v) => encode8(Math.min(1, Math.max(0, v))));
      const untinted = applyMatrix3(XYZ_TO_LINEAR_SRGB, filmXyz({ ...stack, angleDeg: 0 })).map((v) =>
        encode8(Math.min(1, Math.max(0, v))),
      );
      // The tint is seen: the untinted film is far from the expected colour.
      expect(Math.max(...expected.map((v, i) => Math.abs(v - untinted[i]!)))).toBeGreaterThan(10 * MAX_CODE_DIFFERENCE);
      const centre = pixel(cpuBubbleImage(s, SIZE, SIZE), SIZE / 2, SIZE / 2);
      for (let i = 0; i < 3; i++)
        expect(Math.abs(centre[i]! - expected[i]!), `${JSON.stringify(stack)} tint ${tint}: ${centre} vs ${expected}`).toBeLessThanOrEqual(
          MAX_CODE_DIFFERENCE,
        );
    }
  });
});
