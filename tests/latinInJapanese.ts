/**
 * Latin words a Japanese text may hold: units, symbols and names that are written the same in
 * both languages (colour spaces, file formats, the key a user presses). Runs of one or two letters
 * are symbols (n_b, θi, R, E0, K) and always allowed.
 */
export const LATIN_IN_JAPANESE: ReadonlySet<string> = new Set([
  'nm', // nanometres
  'mol', // moles, in the surfactant's mol/m²
  'cos', // the optical path's cosine
  'out', // I_out, the reflected light's symbol
  'sRGB',
  'RGB',
  'XYZ',
  'CIE',
  'LED', // a light-emitting diode, and the CIE's LED lights by name
  'AgX', // three.js's tone mapping, by its name
  'HDR',
  'CPU',
  'WebGL',
  'PNG',
  'CSV',
  'Shift', // the key's label
  'cauchy', // the URL's and attribute's keyword for a Cauchy film
  'complex', // the URL's and attribute's keyword for a complex index n,k
  'line', // the URL's and attribute's keyword for a single spectral line, line:NM
  'TiO', // TiO₂, titanium dioxide's formula
  'SiO', // SiO₂, silica's formula
]);

/** The Latin words of `text` that are neither symbols (one or two letters) nor in LATIN_IN_JAPANESE. */
export const englishLeftIn = (text: string): string[] =>
  (text.match(/[A-Za-z]+/g) ?? []).filter((w) => w.length > 2 && !LATIN_IN_JAPANESE.has(w));
