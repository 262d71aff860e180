import { DataTexture, FloatType, NearestFilter, RGBAFormat } from 'three';
import { type IlluminantSpec } from '../physics/illuminants.ts';
import { type Normalization, significantBins, spectralBins, spectralWeights } from '../physics/spectralIntegration.ts';

interface Entry {
  readonly texture: DataTexture;
  /** Who uses the texture now (a material, a table pass); it is freed when nobody does. */
  readonly holders: Set<object>;
}

const entries = new Map<string, Entry>();
/** The key each holder uses, so switching to other weights lets go of the old texture. */
const heldKey = new WeakMap<object, string>();

/**
 * The bin weights ∫_bin I_in x̄, ȳ, z̄ dλ / k as a `count` × 1 float texture, from the reference
 * (one source of truth), for `holder`. Holders of the same weights share one texture (several
 * bubbles on a page upload it once); a texture no holder uses any more is disposed, so a long
 * session of illuminant changes keeps only the textures in use.
 */
export function spectralBinsTexture(illuminant: IlluminantSpec, normalization: Normalization, count: number, holder: object): DataTexture {
  const key = `${JSON.stringify(illuminant)}|${normalization}|${count}`;
  const previous = heldKey.get(holder);
  if (previous !== key) {
    if (previous !== undefined) letGo(holder, previous);
    heldKey.set(holder, key);
  }
  let entry = entries.get(key);
  if (!entry) {
    const { weights } = spectralBins(spectralWeights(illuminant, normalization), count);
    const data = new Float32Array(4 * count);
    for (let b = 0; b < count; b++) data.set([weights[3 * b]!, weights[3 * b + 1]!, weights[3 * b + 2]!, 1], 4 * b);
    const texture = new DataTexture(data, count, 1, RGBAFormat, FloatType);
    texture.minFilter = texture.magFilter = NearestFilter;
    texture.needsUpdate = true;
    entry = { texture, holders: new Set() };
    entries.set(key, entry);
  }
  entry.holders.add(holder);
  return entry.texture;
}

/** `holder` needs no spectral texture any more (it is disposed, or its method needs none). */
export function releaseSpectralBinsTexture(holder: object): void {
  const key = heldKey.get(holder);
  if (key === undefined) return;
  heldKey.delete(holder);
  letGo(holder, key);
}

function letGo(holder: object, key: string): void {
  const entry = entries.get(key);
  if (!entry) return;
  entry.holders.delete(holder);
  if (entry.holders.size > 0) return;
  entry.texture.dispose();
  entries.delete(key);
}

/** Illuminants spanning the ones offered: flat, and daylight at both ends of its CCT range. */
const SPAN: readonly IlluminantSpec[] = ['E', { daylightCct: 4000 }, { daylightCct: 25000 }, 'D65-table'];
const definesCache = new Map<string, Record<string, number>>();

/**
 * The defines of shaders/spectralIntegration.glsl: `count` bins, of which the loop visits only
 * those where the colour-matching functions matter (`significantBins` with `tailTolerance`) under
 * any offered illuminant — so the defines, and the compiled program, do not depend on the light,
 * and bubbles under D55 and D93 share one program.
 */
export function spectralBinDefines(count: number, tailTolerance: number): Record<string, number> {
  const key = `${count}|${tailTolerance}`;
  const hit = definesCache.get(key);
  if (hit) return hit;
  const ranges = SPAN.map((i) => significantBins(spectralBins(spectralWeights(i, 'white'), count), tailTolerance));
  const defines = {
    SPECTRAL_BINS: count,
    SPECTRAL_BIN_FIRST: Math.min(...ranges.map((r) => r.first)),
    SPECTRAL_BIN_END: Math.max(...ranges.map((r) => r.end)),
  };
  definesCache.set(key, defines);
  return defines;
}
