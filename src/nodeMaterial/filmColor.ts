/**
 * The film's colour in TSL, as shaders/film/filmColor.glsl computes it for `exact`: the film's XYZ
 * by the binned integral (eqs 15–18 over eqs 1–14), for a film of constant media, of media that
 * depend on λ (their knots), or a stack of films, taken to three's working space (linear sRGB,
 * eq 19).
 */
import { float, vec3 } from 'three/tsl';
import { type Node, type TextureNode } from 'three/webgpu';
import { type FilmFill } from '../methods/filmFills.ts';
import { XYZ_TO_LINEAR_SRGB } from '../physics/colorConversions.ts';
import { type LightLineNodes, type SpectralBinNodes, binReflectance, binSumPlanes, binnedXyz } from './binnedIntegration.ts';
import { type PlaneCount } from '../physics/spectralWeights.ts';
import { type ComplexNode, type FloatNode } from './complex.ts';
import { type Channels, filmOptics, filmPathPerNm } from './filmReflectance.ts';
import { mediaAt } from './medium.ts';
import { type StackNodes, layersReflectance } from './transferMatrix.ts';

/** What the film's nodes read: its channels, its bins or a line source's lines, its media (at the D line, their knots, or the stack). */
export interface FilmNodes {
  readonly fill: FilmFill;
  /** n_a, real: the light comes from a transparent medium */
  readonly nOutside: FloatNode;
  readonly channels: Channels;
  readonly bins: SpectralBinNodes;
  readonly lines: LightLineNodes;
  readonly nFilm: ComplexNode;
  readonly nInside: ComplexNode;
  readonly knots: TextureNode;
  readonly stack: StackNodes;
}

/** Each bin's Fresnel terms at ñ of its centre, its phase window from the optical path at its two ends (dispersiveBinnedXyz). */
function dispersiveXyz(f: FilmNodes, thicknessNm: FloatNode, cosIncidence: FloatNode, planes: PlaneCount): Node<'vec3'>[] {
  const pathPerNm = (lambdaNm: FloatNode) => filmPathPerNm(mediaAt(f.knots, lambdaNm).film, f.nOutside, cosIncidence);
  return binSumPlanes(
    f.bins,
    f.lines,
    ({ low, high, center }) => {
      const media = mediaAt(f.knots, center);
      const optics = filmOptics(f.channels, f.nOutside, media.film, media.inside, thicknessNm, cosIncidence);
      const lowPhase = pathPerNm(low).mul(thicknessNm).div(low).toVar();
      const highPhase = pathPerNm(high).mul(thicknessNm).div(high).toVar();
      return binReflectance(optics, center, lowPhase.add(highPhase).mul(Math.PI), lowPhase.sub(highPhase).mul(Math.PI));
    },
    planes,
  );
}

/**
 * The film's XYZ at a thickness and cos θ_i, light from outside, in `planes` colour planes: its XYZ
 * under the light (1), or the columns of its environment matrix (3, the bins' weights of the light
 * times each basis spectrum: src/physics/environmentMatrix.ts).
 */
export function filmPlanesXyz(f: FilmNodes, thicknessNm: FloatNode, cosIncidence: FloatNode, planes: PlaneCount): Node<'vec3'>[] {
  if (f.fill === 'stack')
    return binSumPlanes(
      f.bins,
      f.lines,
      ({ index, center }) => layersReflectance(f.stack, f.channels, index, center, f.nOutside, thicknessNm, cosIncidence),
      planes,
    );
  if (f.fill === 'dispersive') return dispersiveXyz(f, thicknessNm, cosIncidence, planes);
  return binnedXyz(f.bins, f.lines, filmOptics(f.channels, f.nOutside, f.nFilm, f.nInside, thicknessNm, cosIncidence), float(0), planes);
}

/** The film's XYZ under the light (filmPlanesXyz in one plane). */
export const filmXyz = (f: FilmNodes, thicknessNm: FloatNode, cosIncidence: FloatNode): Node<'vec3'> =>
  filmPlanesXyz(f, thicknessNm, cosIncidence, 1)[0]!;

/** XYZ → linear sRGB, three's working space (eq 19), row by row. */
export function xyzToLinearWorking(xyz: Node<'vec3'>): Node<'vec3'> {
  const m = XYZ_TO_LINEAR_SRGB;
  const row = (r: number) => xyz.dot(vec3(m[3 * r], m[3 * r + 1], m[3 * r + 2]));
  return vec3(row(0), row(1), row(2));
}
