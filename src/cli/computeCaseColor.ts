import {
  type GamutMapping,
  type Rgb,
  XYZ_TO_LINEAR_DISPLAY_P3,
  XYZ_TO_LINEAR_SRGB,
  XYZ_TO_LINEAR_WIDE_GAMUT,
  applyMatrix3,
  encode8,
  mapToGamut,
} from '../physics/colorConversions.ts';
import type { IlluminantSpec } from '../physics/illuminants.ts';
import type { LightTint } from '../physics/lightTint.ts';
import { type IndexJson, type Medium, indexJson, mediumIndexAt } from '../physics/medium.ts';
import { type Normalization, type Xyz } from '../physics/spectralWeights.ts';
import { FILM_FILLS, filmFill } from '../methods/filmFills.ts';
import { filmStackOf, stackReflectance, stackXyz, withOptionFilms } from '../methods/filmStacks.ts';
import type { ColorCase } from './colorCase.ts';

/** What the CLI reports for one case. */
export interface CaseColor {
  readonly id: string | number;
  readonly illuminant: IlluminantSpec;
  /** The light's tint, linear sRGB relative to its white. */
  readonly lightTint: LightTint;
  /** Which k of eqs (16)–(18) scales `xyz`: `white` (Y = 1 for a perfect reflector) or `paper`. */
  readonly normalization: Normalization;
  readonly xyz: Xyz;
  /** Eq (19), not clipped: out-of-gamut colours show as channels < 0 or > 1. */
  readonly linearSrgb: Rgb;
  /** round(255 · sRGB-encode(gamut-mapped linear sRGB)). */
  readonly srgb8: Rgb;
  /** Eq (20), the paper's Wide Gamut RGB, not clipped. */
  readonly linearWideGamut: Rgb;
  /** Like `srgb8` with the Display P3 matrix (P3 uses the sRGB transfer function). */
  readonly displayP3_8: Rgb;
  /** R(λ) at each of the case's `wavelengthsNm`, eqs (1)–(14). */
  readonly reflectance: readonly number[];
  /** ñ_b(λ), the film's index, at each of the case's `wavelengthsNm`: a number when real, { n, k } when it absorbs (a single film). */
  readonly nFilm?: readonly IndexJson[];
  /** For a stack of films: at each of `wavelengthsNm`, every film's index from the outside in, as `nFilm` writes one. */
  readonly nLayers?: readonly (readonly IndexJson[])[];
  /** ñ_c(λ), the inside's index, the same way. */
  readonly nInside: readonly IndexJson[];
}

/** 8-bit codes of a linear colour after mapping it into [0, 1] (Y is the luminance it keeps). */
const to8Bit = (linear: Rgb, luminance: number, gamut: GamutMapping): Rgb => {
  const [r, g, b] = mapToGamut(linear, luminance, gamut);
  return [encode8(r), encode8(g), encode8(b)];
};

/**
 * The colour of one case: eqs (15)–(18) for XYZ, then the paper's matrices and display encodings;
 * R(λ) of the single film (eqs 1–14), or of a stack of films by the transfer matrix (transferMatrix.ts).
 */
export function computeCaseColor(c: ColorCase, gamut: GamutMapping): CaseColor {
  const options = { illuminant: c.illuminant, lightTint: c.lightTint, polarization: c.polarization, normalization: c.normalization };
  const film = withOptionFilms(c.stack, c.films);
  const stack = filmStackOf(film);
  const xyz = stackXyz(stack, options);
  const indicesAt = (m: Medium) => c.wavelengthsNm.map((lambdaNm) => indexJson(mediumIndexAt(m, lambdaNm)));
  const linearSrgb = applyMatrix3(XYZ_TO_LINEAR_SRGB, xyz);
  return {
    id: c.id,
    illuminant: c.illuminant,
    lightTint: c.lightTint,
    normalization: c.normalization,
    xyz,
    linearSrgb,
    srgb8: to8Bit(linearSrgb, xyz[1], gamut),
    linearWideGamut: applyMatrix3(XYZ_TO_LINEAR_WIDE_GAMUT, xyz),
    displayP3_8: to8Bit(applyMatrix3(XYZ_TO_LINEAR_DISPLAY_P3, xyz), xyz[1], gamut),
    reflectance: c.wavelengthsNm.map((lambdaNm) => stackReflectance(lambdaNm, stack, c.polarization)),
    // The report names the media as the case gives them: each film's where its option stacks films.
    ...FILM_FILLS[filmFill(film)].caseIndices(film, c.wavelengthsNm),
    nInside: indicesAt(c.stack.nInside),
  };
}
