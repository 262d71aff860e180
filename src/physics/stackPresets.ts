import type { FilmLayer } from './stackFilms.ts';
import { type Medium, transparentIndexAt } from './medium.ts';

/**
 * Named stacks of films (docs/physics.md#named-stacks): a coated lens, a dielectric mirror and two
 * of nature's reflectors, each with the numbers its source gives. Films run from the outside in,
 * every thickness in nm (none follows the thickness field), every film within LAYERS_DOMAIN.
 */
export const STACK_PRESET_NAMES = ['arCoating', 'braggMirror', 'nacre', 'chirpedBeetle'] as const;
export type StackPresetName = (typeof STACK_PRESET_NAMES)[number];

/** A stack as a source describes it. */
export interface StackPreset {
  readonly films: readonly FilmLayer[];
  /** n_a, where the light comes from: a real constant */
  readonly nOutside: number;
  /** the medium under the last film */
  readonly nInside: Medium;
  /** The wavelength the films are quarter waves at (for the chirped stack: its middle), nm; null when none. */
  readonly designNm: number | null;
  /** One line on what it is. */
  readonly description: string;
  /** Where the numbers come from: author(s), year, title, and which numbers were taken. */
  readonly source: string;
}

/** A quarter wave of `n` at `designNm`: d = λ₀ / (4 n(λ₀)), so 2 n d = λ₀/2 (Macleod 2010). */
export const quarterWaveLayer = (n: Medium, designNm: number): FilmLayer => ({
  n,
  thicknessNm: designNm / (4 * transparentIndexAt(n, designNm)),
});

/** `group` repeated `count` times, outside in: the text's `(…)*N`. */
export const repeatLayers = (group: readonly FilmLayer[], count: number): FilmLayer[] => Array.from({ length: count }, () => group).flat();

/** Magnesium fluoride, n = 1.38 in the visible (Macleod 2010, antireflection coatings). */
export const MGF2_INDEX = 1.38;
/** Crown glass, n = 1.52 (Macleod 2010, the substrate of its examples). */
export const CROWN_GLASS_INDEX = 1.52;
/** The AR coating's and the mirror's design wavelength: the middle of the visible, near the eye's peak. */
export const DESIGN_NM = 550;

/** The quarter-wave mirror (HL)^periods of TiO₂ (H) and SiO₂ (L) at `designNm`, the outside in: H first. */
export const braggMirrorLayers = (periods: number, designNm = DESIGN_NM): FilmLayer[] =>
  repeatLayers([quarterWaveLayer('TiO2', designNm), quarterWaveLayer('SiO2', designNm)], periods);

/** The mirror's periods: (2.164/1.460)^16 × 1.52 ≈ 830, R(λ₀) = ((1 − Y)/(1 + Y))² ≈ 0.995. */
export const BRAGG_PERIODS = 8;

/** Nacre's lamellae: aragonite tablets and organic (protein and chitin) sheets. */
export const ARAGONITE_INDEX = 1.68;
export const NACRE_ORGANIC_INDEX = 1.43;
export const NACRE_TABLET_NM = 500;
export const NACRE_ORGANIC_NM = 25;
export const NACRE_PERIODS = 10;

/** The beetle's films: the real parts of Noyes, Vukusic & Hooper's fit (2007). */
export const BEETLE_HIGH_INDEX = 1.68;
export const BEETLE_LOW_INDEX = 1.55;
/** Quarter-wave pairs, and the wavelength they are tuned to at the surface and at the deepest pair. */
export const BEETLE_PAIRS = 16;
export const BEETLE_SURFACE_NM = 480;
export const BEETLE_DEPTH_NM = 660;

/**
 * `pairs` quarter-wave pairs of `high`|`low` whose design wavelength runs linearly from `surfaceNm`
 * (the first pair) to `depthNm` (the last): a chirped stack. `surfaceNm = depthNm` is a regular one.
 */
export function chirpedLayers(high: number, low: number, pairs: number, surfaceNm: number, depthNm: number): FilmLayer[] {
  return Array.from({ length: pairs }, (_, j) => {
    const designNm = pairs === 1 ? surfaceNm : surfaceNm + ((depthNm - surfaceNm) * j) / (pairs - 1);
    return [quarterWaveLayer(high, designNm), quarterWaveLayer(low, designNm)];
  }).flat();
}

const MACLEOD = 'H. A. Macleod, Thin-Film Optical Filters, 4th ed. (CRC Press, 2010)';

/** Every named stack. */
export const STACK_PRESETS: Readonly<Record<StackPresetName, StackPreset>> = {
  arCoating: {
    films: [quarterWaveLayer(MGF2_INDEX, DESIGN_NM)],
    nOutside: 1,
    nInside: CROWN_GLASS_INDEX,
    designNm: DESIGN_NM,
    description: 'a coated lens: one quarter wave of MgF₂ on crown glass, R ≈ 1.3 % at 550 nm instead of 4.3 %',
    source:
      `${MACLEOD}, the chapter on antireflection coatings: a single quarter-wave layer of MgF₂, n = 1.38, on crown glass, ` +
      'n = 1.52, in air: R = ((n₀n_s − n₁²)/(n₀n_s + n₁²))² = 1.26 % at the design wavelength (here 550 nm: d = 99.6 nm)',
  },
  braggMirror: {
    films: braggMirrorLayers(BRAGG_PERIODS),
    nOutside: 1,
    nInside: CROWN_GLASS_INDEX,
    designNm: DESIGN_NM,
    description: 'a dielectric mirror: 8 quarter-wave pairs of TiO₂ and SiO₂ on glass, a green reflection band',
    source:
      `${MACLEOD}, the chapter on multilayer high-reflectance coatings (the quarter-wave stack): R(λ₀) = ((1 − Y)/(1 + Y))², Y = (n_H/n_L)^(2p) n_s, and the ` +
      "band's half-width Δg = (2/π) arcsin((n_H − n_L)/(n_H + n_L)) in g = λ₀/λ; the media are TiO₂ (Sarkar et al. 2019, " +
      'n = 2.164 at 550 nm: 63.5 nm) and SiO₂ (Malitson 1965, n = 1.460: 94.2 nm) on crown glass, n = 1.52',
  },
  nacre: {
    films: repeatLayers(
      [
        { n: ARAGONITE_INDEX, thicknessNm: NACRE_TABLET_NM },
        { n: NACRE_ORGANIC_INDEX, thicknessNm: NACRE_ORGANIC_NM },
      ],
      NACRE_PERIODS,
    ),
    nOutside: 1,
    nInside: ARAGONITE_INDEX,
    designNm: null,
    description: 'nacre (mother-of-pearl): 10 aragonite tablets, 500 nm thick, between 25 nm organic sheets',
    source:
      'J. Salman et al., "Hyperspectral interference tomography of nacre", PNAS 118, e2023623118 (2021): alternating ' +
      'aragonite tablets (≈ 0.5 µm) and much thinner organic sheets; aragonite n = 1.68 (its in-plane indices n_β = 1.680, ' +
      'n_γ = 1.685: the c axis is normal to the lamellae); the organic sheets, 25 nm and n = 1.43, are an assumption of ' +
      'this preset, not a measured value',
  },
  chirpedBeetle: {
    films: chirpedLayers(BEETLE_HIGH_INDEX, BEETLE_LOW_INDEX, BEETLE_PAIRS, BEETLE_SURFACE_NM, BEETLE_DEPTH_NM),
    nOutside: 1,
    nInside: BEETLE_LOW_INDEX,
    designNm: (BEETLE_SURFACE_NM + BEETLE_DEPTH_NM) / 2,
    description: 'a jewel-beetle-like chirped stack: 16 pairs of cuticle films, quarter waves at 480 nm near the surface to 660 nm deep',
    source:
      'J. A. Noyes, P. Vukusic & I. R. Hooper, "Experimental method for reliably establishing the refractive index of ' +
      'buprestid beetle exocuticle", Opt. Express 15, 4351 (2007): the alternating films of Chrysochroa raja, n = 1.68 (k = 0.03) and ' +
      'n = 1.55 (k = 0.14), taken here without k; the chirp, optical thickness changing steadily with depth, after A. R. ' +
      'Parker, D. R. McKenzie & M. C. J. Large, "Multilayer reflectors in animals using green and gold beetles as ' +
      'contrasting examples", J. Exp. Biol. 201, 1307 (1998); its pairs and span are this preset\'s choice',
  },
};
