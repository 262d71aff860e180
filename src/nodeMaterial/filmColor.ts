/**
 * The film's colour in TSL, as shaders/film/filmColor.glsl computes it for `exact`: the film's XYZ
 * by the binned integral (eqs 15–18 over eqs 1–14), for a film of constant media, of media that
 * depend on λ (their knots), or a stack of films, taken to three's working space (linear sRGB,
 * eq 19).
 */
import { float, select, vec3 } from 'three/tsl';
import { type Node, type TextureNode } from 'three/webgpu';
import { type FilmFill } from '../methods/filmFills.ts';
import { XYZ_TO_LINEAR_SRGB } from '../physics/colorConversions.ts';
import { type SpectralBinNodes, binReflectance, binSum, binnedXyz } from './binnedIntegration.ts';
import { type ComplexNode, type FloatNode } from './complex.ts';
import { type ChannelKind, filmOptics, filmPathPerNm } from './filmReflectance.ts';
import { mediaAt } from './medium.ts';
import { type StackNodes, layersReflectance } from './transferMatrix.ts';

/** What the film's nodes read: its channels, its bins, its media (at the D line, their knots, or the stack). */
export interface FilmNodes {
  readonly fill: FilmFill;
  readonly kinds: readonly ChannelKind[];
  readonly bins: SpectralBinNodes;
  readonly nFilm: ComplexNode;
  readonly nInside: ComplexNode;
  readonly knots: TextureNode;
  readonly stack: StackNodes;
}

/** The material's film lies in air (three's film has air outside). */
const N_OUTSIDE = float(1);

/** Each bin's Fresnel terms at ñ of its centre, its phase window from the optical path at its two ends (dispersiveBinnedXyz). */
function dispersiveXyz(f: FilmNodes, thicknessNm: FloatNode, cosIncidence: FloatNode): Node<'vec3'> {
  const pathPerNm = (lambdaNm: FloatNode) => filmPathPerNm(mediaAt(f.knots, lambdaNm).film, N_OUTSIDE, cosIncidence);
  return binSum(f.bins, ({ low, high, center }) => {
    const media = mediaAt(f.knots, center);
    const optics = filmOptics(f.kinds, N_OUTSIDE, media.film, media.inside, thicknessNm, cosIncidence);
    const lowPhase = pathPerNm(low).mul(thicknessNm).div(low).toVar();
    const highPhase = pathPerNm(high).mul(thicknessNm).div(high).toVar();
    return binReflectance(optics, center, lowPhase.add(highPhase).mul(Math.PI), lowPhase.sub(highPhase).mul(Math.PI));
  });
}

/** The film's XYZ at a thickness and cos θ_i, light from outside. */
export function filmXyz(f: FilmNodes, thicknessNm: FloatNode, cosIncidence: FloatNode): Node<'vec3'> {
  if (f.fill === 'stack')
    return binSum(f.bins, ({ index, center }) => layersReflectance(f.stack, f.kinds, index, center, N_OUTSIDE, thicknessNm, cosIncidence));
  if (f.fill === 'dispersive') return dispersiveXyz(f, thicknessNm, cosIncidence);
  return binnedXyz(f.bins, filmOptics(f.kinds, N_OUTSIDE, f.nFilm, f.nInside, thicknessNm, cosIncidence));
}

/**
 * The film's XYZ as the table pass fills a texel (shaders/film/filmTable.glsl's binned fill): a
 * film of constant media averaged over the texel's thickness cell (`cellNm`) so fringes finer
 * than a cell do not alias, its phase half-width at λ 2π · Re(Δ per nm) · cell / (2λ); a dispersive
 * film or a stack at the texel's film.
 */
export function tableTexelXyz(f: FilmNodes, thicknessNm: FloatNode, cosIncidence: FloatNode, cellNm: FloatNode): Node<'vec3'> {
  if (f.fill !== 'constant') return filmXyz(f, thicknessNm, cosIncidence);
  const o = filmOptics(f.kinds, N_OUTSIDE, f.nFilm, f.nInside, thicknessNm, cosIncidence);
  const perNmPath = select(thicknessNm.greaterThan(0), o.opticalPathNm.x.div(thicknessNm), filmPathPerNm(f.nFilm, N_OUTSIDE, cosIncidence));
  return binnedXyz(f.bins, o, perNmPath.mul(cellNm).mul(Math.PI));
}

/** XYZ → linear sRGB, three's working space (eq 19), row by row. */
export function xyzToLinearWorking(xyz: Node<'vec3'>): Node<'vec3'> {
  const m = XYZ_TO_LINEAR_SRGB;
  const row = (r: number) => xyz.dot(vec3(m[3 * r], m[3 * r + 1], m[3 * r + 2]));
  return vec3(row(0), row(1), row(2));
}
