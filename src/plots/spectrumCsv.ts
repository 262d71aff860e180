import type { FilmSpectrum } from './filmSpectrum.ts';

/** The spectra behind a film's colour as CSV: one row per wavelength, every value at full float64 precision. */
export function spectrumCsv(s: FilmSpectrum): string {
  const rows = Array.from(s.lambdasNm, (l, i) => [l, s.reflectance[i], s.incident[i], s.reflected[i]].join(','));
  return `wavelength_nm,R,I_in_relative,I_out_relative\n${rows.join('\n')}\n`;
}
