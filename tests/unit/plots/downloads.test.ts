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
