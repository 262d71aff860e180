import { DataTexture, FloatType, NearestFilter, RGBAFormat } from 'three';
import { SharedTextures } from '../gpu/sharedTextures.ts';
import { packTexelRecord, texelRecord, texelRecordDefines } from '../gpu/texelRecord.ts';
import { binCenterNm } from '../physics/binnedIntegration.ts';
import { asComplex } from '../physics/complex.ts';
import { type FilmLayer, FIELD_THICKNESS, LAYERS_DOMAIN, followsField } from '../physics/stackFilms.ts';
import { type Medium, mediumIndexAt } from '../physics/medium.ts';
import type { FilmMethodSettings } from '../methods/filmMethod.ts';
import { optionFilmsOf } from '../methods/filmStacks.ts';

/**
 * A stack of films on the GPU (docs/gpu.md#stacks-of-films): shaders/physics/transferMatrix.glsl
 * reads each film's ñ at every spectral bin's centre, its thickness and whether it takes the
 * thickness field's value from one data texture, `uFilmLayers`, a row per film from the outside
 * in and a last row for the inside, a column per bin (ñ in float64 from src/physics/medium.ts).
 */

/** What carries a stack: the films its option stacks (none: the single film of nFilm), with the media its fill depends on (filmFills.ts). */
export type StackedSettings = FilmMethodSettings;

/** The texel of a film (or the inside) at a bin, read by these names in transferMatrix.glsl. */
export const FILM_LAYER = texelRecord('TFC_FILM_LAYER', { N: 2, THICKNESS_NM: 1, FOLLOWS_FIELD: 1 });

/** The defines of transferMatrix.glsl for a stack. */
export const FILM_STACK_DEFINES: Readonly<Record<string, number>> = {
  TFC_FILM_LAYERS: 1,
  TFC_FILM_LAYERS_MAX: LAYERS_DOMAIN.count.max,
  ...texelRecordDefines(FILM_LAYER),
};

/** The uniforms transferMatrix.glsl declares: the stack's texture and its film count. */
export const filmStackUniforms = () => ({
  uFilmLayers: { value: null as DataTexture | null },
  uFilmLayerCount: { value: 0 },
});

interface StackKey {
  readonly films: readonly FilmLayer[];
  readonly nInside: Medium;
  readonly bins: number;
}

const nk = (m: Medium, lambdaNm: number): [number, number] => {
  const z = asComplex(mediumIndexAt(m, lambdaNm));
  return [z.re, z.im];
};

/** The texels of a stack: row l < films the film l (outside in), the last row the inside; column b the bin b's centre. */
export function filmStackTexels({ films, nInside, bins }: StackKey): Float32Array {
  const data = new Float32Array(FILM_LAYER.floats * bins * (films.length + 1));
  const rows: readonly FilmLayer[] = [...films, { n: nInside, thicknessNm: 0 }];
  rows.forEach((entry, row) => {
    const field = entry.thicknessNm === FIELD_THICKNESS;
    for (let b = 0; b < bins; b++)
      packTexelRecord(FILM_LAYER, data, row * bins + b, {
        N: nk(entry.n, binCenterNm(b, bins)),
        THICKNESS_NM: field ? 0 : entry.thicknessNm,
        FOLLOWS_FIELD: field ? 1 : 0,
      });
  });
  return data;
}

const shared = new SharedTextures((key) => {
  const stack = JSON.parse(key) as StackKey;
  const texture = new DataTexture(filmStackTexels(stack), FILM_LAYER.texels * stack.bins, stack.films.length + 1, RGBAFormat, FloatType);
  texture.minFilter = texture.magFilter = NearestFilter;
  texture.needsUpdate = true;
  return texture;
});

/** Points transferMatrix.glsl's uniforms at the stack of `s` over `bins` bins, held for `holder` (shared by the holders of one stack). */
export function holdFilmStackTexture(u: Record<string, { value: unknown }>, s: StackedSettings, bins: number, holder: object): void {
  const films = optionFilmsOf(s);
  u.uFilmLayers!.value = shared.hold(JSON.stringify({ films, nInside: s.nInside, bins } satisfies StackKey), holder);
  u.uFilmLayerCount!.value = films.length;
}

/** Points transferMatrix.glsl's uniforms at no stack, and lets go of any `holder` held. */
export function clearFilmStackUniforms(u: Record<string, { value: unknown }>, holder: object): void {
  releaseFilmStackTexture(holder);
  u.uFilmLayers!.value = null;
  u.uFilmLayerCount!.value = 0;
}

/** `holder` needs no stack texture any more. */
export const releaseFilmStackTexture = (holder: object): void => shared.release(holder);

/**
 * The real index whose fringes in the field's thickness a stack's table resolves: the sum over its
 * FIELD_THICKNESS films of each one's largest real index at the bins (the phase turns by all of
 * them as the field's thickness grows); null for a stack that does not follow the field.
 */
export function stackFieldIndex(films: readonly FilmLayer[], bins: number): number | null {
  if (!followsField(films)) return null;
  let sum = 0;
  for (const film of films) {
    if (film.thicknessNm !== FIELD_THICKNESS) continue;
    let max = 0;
    for (let b = 0; b < bins; b++) max = Math.max(max, nk(film.n, binCenterNm(b, bins))[0]);
    sum += max;
  }
  return sum;
}
