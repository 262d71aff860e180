/**
 * The English catalogue: every text the project's elements show, one key each. Keys are
 * namespaced by who shows them (`common.` for the film's own terms, shared by the diagram, the
 * bubble and the panel; `diagram.` for <thin-film-diagram>). `{name}` marks a value filled in when
 * shown (messages.ts). Its keys are the catalogue's type: every other language has exactly these.
 */
export const EN = {
  'common.thinFilmInterference': 'thin-film interference',
  'common.thickness': 'film thickness d (nm)',
  'common.angle': 'angle of incidence θi (°)',
  'common.wavelength': 'wavelength λ (nm)',
  'common.nOutside': 'refractive index outside n_a',
  'common.nFilm': 'refractive index of the film n_b',
  'common.nInside': 'refractive index inside n_c',
  'common.reflectance': 'reflectance R',
  'common.polarization': 'polarisation',
  'common.polarization.unpolarized': 'unpolarised: R = (R_s + R_p)/2',
  'common.polarization.paper': "the paper's amplitude average (eqs 4, 8)",
  'common.polarization.s': 's polarisation',
  'common.polarization.p': 'p polarisation',
  'common.illuminant': 'light source',
  'common.colorMatchingFunctions': 'colour-matching functions',
  'common.colorSpace': 'colour space',
  'common.unit.nm': 'nm',
  'common.unit.degrees': '°',
  'diagram.label': 'Thin-film interference diagram',
  'diagram.controls': 'Settings',
  'diagram.figureTitle': 'The principle of thin-film interference: the reflected beams',
  'diagram.figureDescription':
    'Medium a (n_a = {na}) above, the film b ({thickness} nm thick, n_b = {nb}), medium c (n_c = {nc}) below. ' +
    'The incident ray meets the film at θi = {angle}° and is refracted to θri = {refracted} in it. ' +
    '{count} reflected beams E0 to E{last} are drawn, each as wide as its amplitude |E_n|: {amplitudes}.',
  'diagram.mediumA': 'medium a: n_a = {n}',
  'diagram.mediumB': 'medium b (film, d = {thickness} nm): n_b = {n}',
  'diagram.mediumC': 'medium c: n_c = {n}',
  'diagram.drawnAngle': 'the angles are drawn at {angle}° so the beams stay apart',
  'diagram.incident': 'incident light',
  'diagram.evanescent': 'complex (evanescent in the film)',
  'diagram.backTotalReflection': 'total internal reflection at the back surface',
  'diagram.opticalPath': 'Δ = 2 n_b d cos θri = {delta} nm (eq 12)',
  'diagram.opticalPathEvanescent': 'Δ = 2 n_b d cos θri = {delta} nm: imaginary',
  'diagram.beamsCaption': 'The reflected beams (relative to the incident field)',
  'diagram.beam': 'beam',
  'diagram.amplitude': 'amplitude',
  'diagram.magnitude': '|E_n| ({channel})',
  'diagram.tail': 'tail',
  'diagram.total': 'E, the sum (eq 13)',
  'diagram.phasorTitle': 'Phasor diagram, {channel}',
  'diagram.phasorDescription':
    'In the complex plane E0, E1, … are added head to tail; they converge to E = {total}, and |E|² = R = {reflectance}.',
  'diagram.spectrumTitle': 'Reflectance R(λ) from 380 to 830 nm',
  'diagram.spectrumDescription':
    'The curve of R over the visible band, marked at λ = {wavelength} nm where R = {reflectance}. ' +
    'The film’s colour is this curve times the light source, weighed by the colour-matching functions and shown in a colour space.',
  'diagram.flipTop': 'no phase flip at the top surface',
  'diagram.flipTopHint':
    'Reverses the sign of r_ab in E0 only. Light reflected by a denser medium changes sign; without that, a very thin film would reflect about (2 r_ab)² and look bright instead of black.',
  'diagram.flipTopNote': 'hypothetical: no phase flip at the top surface',
  'diagram.summary': 'R = {reflectance} at λ = {wavelength} nm ({polarization}).',
  'diagram.summaryBeams': '{count} beams drawn; the rest of the series adds at most {bound} of the incident amplitude.',
  'diagram.summaryTail': '{count} beams drawn; the rest, at most {bound} of the incident amplitude, is added in closed form (eq 13).',
  'diagram.summaryDiverges':
    '{count} beams drawn; here the series does not converge (|r_ba r_bc e^{iφ}| = 1), so E is the closed form of eq 13.',
  'diagram.summaryNoEntry': 'No light enters the film (grazing incidence): only E0 is reflected.',
  'diagram.error.number': '{attribute}={value} is not allowed: expected a number from {min} to {max}{unit}.',
  'diagram.error.choice': '{attribute}={value} is not allowed: expected one of {choices}.',
  'diagram.error.filmIndex':
    '{attribute}={value} is not allowed: expected a number from {min} to {max}, {materials}, or {cauchy} staying within that range.',
  'diagram.error.for': '{attribute}={value}: no {tag} with that id on this page.',
} as const satisfies Record<string, string>;

/** A text's key. */
export type MessageKey = keyof typeof EN;

/** A language's catalogue: a text for every key, no more, no less. */
export type Catalogue = Readonly<Record<MessageKey, string>>;
