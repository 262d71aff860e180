/**
 * What the node film reads from the CPU: the bin weights or a line source's lines, the media's knots, the stack, the media
 * at the D line, as TSL textures and uniforms of one material, brought up to its film's uniforms
 * (src/film/filmColor.ts's, the WebGL material's: one source for both) before each draw.
 */
import { DataTexture, FloatType, NearestFilter, RGBAFormat, Vector2, Vector4 } from 'three';
import { uniform, uniformArray, uniformTexture } from 'three/tsl';
import { type TextureNode, type UniformNode } from 'three/webgpu';
import { MEDIA_KNOT, MEDIA_KNOT_DEFINES } from '../film/filmMedia.ts';
import { MAX_LIGHT_LINES } from '../physics/lightLines.ts';
import { type LightLineNodes } from './binnedIntegration.ts';

/** A float RGBA texture of `width` × 1 texels (a placeholder until the film's own is bound). */
export function floatRow(width: number, data = new Float32Array(4 * width)): DataTexture {
  const t = new DataTexture(data, width, 1, RGBAFormat, FloatType);
  t.minFilter = t.magFilter = NearestFilter;
  t.needsUpdate = true;
  return t;
}

export interface FilmInputs {
  readonly weights: TextureNode;
  readonly lines: LightLineNodes;
  readonly knots: TextureNode;
  readonly layers: TextureNode;
  readonly layerCount: UniformNode<'int', number>;
  readonly nFilm: UniformNode<'vec2', Vector2>;
  readonly nInside: UniformNode<'vec2', Vector2>;
}

export const filmInputs = (): FilmInputs => ({
  weights: uniformTexture(floatRow(1)),
  lines: {
    // A set of lines per colour plane (binSumPlanes).
    values: uniformArray(
      Array.from({ length: 3 * MAX_LIGHT_LINES }, () => new Vector4()),
      'vec4',
    ),
    count: uniform(0, 'int'),
  },
  knots: uniformTexture(floatRow(MEDIA_KNOT.texels * MEDIA_KNOT_DEFINES.TFC_MEDIA_KNOTS!)),
  layers: uniformTexture(floatRow(1)),
  layerCount: uniform(0, 'int'),
  nFilm: uniform(new Vector2(1.33, 0)),
  nInside: uniform(new Vector2(1, 0)),
});

type Uniforms = Record<string, { value: unknown }>;

/** Brings the inputs up to a film's uniforms (filmColorUniforms and filmStackUniforms, as updateFilmColorUniforms left them). */
export function setFilmInputs(i: FilmInputs, u: Uniforms): void {
  const bins = u.uSpectralBins!.value as DataTexture | null;
  if (bins) i.weights.value = bins;
  (i.lines.values.array as Vector4[]).forEach((line, k) => line.copy((u.uLightLines!.value as Vector4[])[k]!));
  i.lines.count.value = u.uLightLineCount!.value as number;
  const layers = u.uFilmLayers!.value as DataTexture | null;
  if (layers) i.layers.value = layers;
  i.layerCount.value = u.uFilmLayerCount!.value as number;
  i.nFilm.value.fromArray(u.uNFilm!.value as number[]);
  i.nInside.value.fromArray(u.uNInside!.value as number[]);
  const knots = u.uMediaKnots!.value as Float32Array;
  const texture = i.knots.value as DataTexture;
  const data = texture.image.data as Float32Array;
  if (knots.length === data.length && knots.some((v, k) => v !== data[k])) {
    data.set(knots);
    texture.needsUpdate = true;
  }
}
