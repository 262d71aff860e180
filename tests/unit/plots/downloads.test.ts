import { describe, expect, it } from 'vitest';
import { SOAP_FILM_IN_AIR } from '../../../src/physics/filmReflectance.ts';
import { downloadName } from '../../../src/plots/downloadName.ts';
import { filmSpectrum } from '../../../src/plots/filmSpectrum.ts';
import { spectrumCsv } from '../../../src/plots/spectrumCsv.ts';

describe('plot downloads', () => {
  it('are named after the view: thickness, light and angle, rounded', () => {
    expect(downloadName({ thicknessNm: 550, angleDeg: 30, illuminant: 'D65' }, 'spectrum', 'png')).toBe(
      'film-550nm-D65-30deg-spectrum.png',
    );
    expect(downloadName({ thicknessNm: 539.6, angleDeg: 0.4, illuminant: 'D65-table' }, 'xy', 'png')).toBe(
      'film-540nm-D65-table-0deg-xy.png',
    );
    expect(downloadName({ thicknessNm: 0, angleDeg: 89.5, illuminant: { daylightCct: 7500 } }, 'spectrum', 'csv')).toBe(
      'film-0nm-7500K-90deg-spectrum.csv',
    );
    expect(downloadName({ thicknessNm: 600, angleDeg: 0, illuminant: 'FL2', lightTint: [1, 0.5, 0.2] }, 'spectrum', 'png')).toBe(
      'film-600nm-FL2-tint-1-0.5-0.2-0deg-spectrum.png',
    );
    expect(downloadName({ thicknessNm: 600, angleDeg: 0, illuminant: 'FL2', lightTint: [1, 1, 1] }, 'spectrum', 'png')).toBe(
      'film-600nm-FL2-0deg-spectrum.png',
    );
    expect(downloadName({ thicknessNm: 600, angleDeg: 0, illuminant: { lineNm: 632.8 } }, 'spectrum', 'png')).toBe(
      'film-600nm-line-632.8nm-0deg-spectrum.png',
    );
    expect(downloadName({ thicknessNm: 600, angleDeg: 0, illuminant: 'LED-B1' }, 'xy', 'png')).toBe('film-600nm-LED-B1-0deg-xy.png');
  });

  it("draws a tinted light's spectrum: equal energy tinted blue is the basis's blue (its rows at 450 and 700 nm)", () => {
    const s = filmSpectrum({ ...SOAP_FILM_IN_AIR, thicknessNm: 450, angleDeg: 0 }, 'E', 'unpolarized', 1, [0, 0, 1]);
    const at = (nm: number) => s.incident[nm - 380]!;
    expect(Math.abs(at(700) / at(450) - 0.276826038721536 / 0.957025264931328)).toBeLessThan(1e-12);
  });

  it("draws a line source's lines in the spectrum: each line's power shared by the 1 nm samples beside it", () => {
    const s = filmSpectrum({ ...SOAP_FILM_IN_AIR, thicknessNm: 450, angleDeg: 0 }, 'Na', 'unpolarized');
    const at = (nm: number) => s.incident[nm - 380]!;
    // D2 (power 2) at 588.995 nm, D1 (power 1) at 589.592 nm, scaled so the largest sample is 1.
    const raw = { 588: 2 * 0.005, 589: 2 * 0.995 + 0.408, 590: 0.592 };
    expect(at(589)).toBe(1);
    expect(Math.abs(at(588) - raw[588] / raw[589])).toBeLessThan(1e-12);
    expect(Math.abs(at(590) - raw[590] / raw[589])).toBeLessThan(1e-12);
    expect(s.incident.filter((v) => v > 0)).toHaveLength(3);
  });

  it('the spectrum CSV holds every sample at full precision', () => {
    const s = filmSpectrum({ ...SOAP_FILM_IN_AIR, thicknessNm: 450, angleDeg: 30 }, 'D93', 's', 5);
    const [header, ...rows] = spectrumCsv(s).trimEnd().split('\n');
    expect(header).toBe('wavelength_nm,R,I_in_relative,I_out_relative');
    expect(rows.map((row) => row.split(',').map(Number))).toEqual(
      Array.from(s.lambdasNm, (l, i) => [l, s.reflectance[i], s.incident[i], s.reflected[i]]),
    );
  });
});
