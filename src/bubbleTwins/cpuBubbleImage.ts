import { XYZ_TO_LINEAR_SRGB, type Rgb, applyMatrix3, encode8 } from '../physics/colorConversions.ts';
import { FILM_STACK_DOMAIN } from '../physics/filmReflectance.ts';
import { stackBinnedXyz } from '../physics/binnedIntegration.ts';
import { lightBins } from '../physics/environmentMatrix.ts';
import { absorbsInBand } from '../physics/medium.ts';
import { planeLights } from '../physics/spectralWeights.ts';
import type { LightTint } from '../physics/lightTint.ts';
import { filmPlanes } from '../settings/filmLight.ts';
import { DEFAULT_FILM_QUALITY } from '../settings/filmQuality.ts';
import { type ShownEnvironment, environmentRadiance, reflectedRadiance } from './environment.ts';
import type { EnvironmentPixels } from '../bubbleMaterials/environmentMaps.ts';
import { type FilmSettings, toneMappingOf } from '../settings/filmSettings.ts';
import { environmentColor, environmentKind, environmentText } from '../environments/environments.ts';
import { maxFieldThicknessNm, thicknessAt } from '../fields/fields.ts';
import { toneMap } from './toneMapping.ts';
import type { Vec3 } from '../fields/thicknessField.ts';

/** The view of src/view/bubbleView.ts: a camera on +z at distance 4 with a 35° vertical field of view. */
export const CAMERA_DISTANCE = 4;
export const FOV_DEG = 35;
/**
 * Films are coloured by the shader's method (binnedXyz at the default `exact` bin count, whose
 * error against filmXyz the benchmark's `exact` rows measure, docs/benchmarks.md; its cost does not
 * grow with thickness) on a memoised lattice, interpolated bilinearly: thickness in steps around
 * the set thickness (so a uniform film is exact), at least MIN_THICKNESS_STEP_NM and at most
 * LATTICE_THICKNESSES steps over the field's range (thick films vary slowly once their fringes
 * average out); cos θ_i in steps of 1/COS_STEPS. Between lattice points the interpolation adds its
 * own error, largest at the limb, where colour changes fastest with angle. An image costs one
 * binned integral per lattice point it meets (however many pixels) and a lookup per pixel.
 */
export const MIN_THICKNESS_STEP_NM = 8;
export const LATTICE_THICKNESSES = 256;
export const COS_STEPS = 32;

const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const normalize = (a: Vec3): Vec3 => {
  const l = Math.hypot(a[0], a[1], a[2]);
  return [a[0] / l, a[1] / l, a[2] / l];
};
const clamp01 = (v: number) => Math.min(1, Math.max(0, v));

/** GLSL's reflect(): d mirrored in the plane of the unit normal n. */
const reflect = (d: Vec3, n: Vec3): Vec3 => {
  const k = 2 * dot(d, n);
  return [d[0] - k * n[0], d[1] - k * n[1], d[2] - k * n[2]];
};

/**
 * A film's colour in the working space (linear sRGB): R per channel (3 numbers) where the walls
 * reflect the untinted light's white, or its environment matrix M in the working space (9, row-major)
 * where they reflect a coloured environment or a tinted light (filmPlanes), M's column j the film
 * under the untinted light times basis spectrum j.
 */
type FilmColorValue = readonly number[];
type FilmColor = (thicknessNm: number, cosIncidence: number, fromInside: boolean) => FilmColorValue;

/** The film's colour (eq 19 after eqs 1–18) at a thickness and cos θ_i, from the memoised lattice. */
function filmColorLattice(s: FilmSettings): FilmColor {
  const step = Math.max(MIN_THICKNESS_STEP_NM, maxFieldThicknessNm(s) / LATTICE_THICKNESSES);
  const planes = planeLights(s, filmPlanes(s)).map((light) => lightBins(light, DEFAULT_FILM_QUALITY.exactSpectralBins));
  const cache = new Map<string, FilmColorValue>();
  const node = (k: number, j: number, fromInside: boolean): FilmColorValue => {
    const key = `${k}|${j}|${fromInside}`;
    const hit = cache.get(key);
    if (hit) return hit;
    const thicknessNm = Math.min(FILM_STACK_DOMAIN.thicknessNm.max, Math.max(0, s.thicknessNm + k * step));
    const angleDeg = j === COS_STEPS ? 0 : j === 0 ? 90 : (Math.acos(j / COS_STEPS) * 180) / Math.PI;
    const [nOutside, nInside] = fromInside ? [s.nInside, s.nOutside] : [s.nOutside, s.nInside];
    const columns = planes.map((bins) =>
      applyMatrix3(XYZ_TO_LINEAR_SRGB, stackBinnedXyz({ nOutside, nFilm: s.nFilm, nInside, thicknessNm, angleDeg }, s.polarization, bins)),
    );
    // One plane: R per channel; three: M row by row (row i holds channel i of each column).
    const value = columns.length === 1 ? columns[0]! : [0, 1, 2].flatMap((i) => columns.map((c) => c[i]!));
    cache.set(key, value);
    return value;
  };
  return (thicknessNm, cosIncidence, fromInside) => {
    const u = (thicknessNm - s.thicknessNm) / step;
    const v = clamp01(cosIncidence) * COS_STEPS;
    const k = Math.floor(u),
      j = Math.min(COS_STEPS - 1, Math.floor(v));
    const fu = u - k,
      fv = v - j;
    const corner = (dk: number, dj: number, w: number) => node(k + dk, j + dj, fromInside).map((c) => c * w);
    const parts = [corner(0, 0, (1 - fu) * (1 - fv)), corner(1, 0, fu * (1 - fv)), corner(0, 1, (1 - fu) * fv), corner(1, 1, fu * fv)];
    return parts[0]!.map((_, i) => parts.reduce((sum, p) => sum + p[i]!, 0));
  };
}

/**
 * A wall's light (tfcWallRadiance in bubble.frag.glsl): the film's reflection of `reflected` and its
 * transmission of `transmitted`: R r + clamp(1 − R) t per channel, or M (tint r) + t − M t (the
 * untinted light's white has one plane, so only a matrix meets a tint).
 */
function wallRadiance(film: FilmColorValue, reflected: Rgb, transmitted: Rgb, tint: LightTint): Rgb {
  if (film.length === 3) return [0, 1, 2].map((i) => film[i]! * reflected[i]! + clamp01(1 - film[i]!) * transmitted[i]!) as unknown as Rgb;
  const m = (i: number, c: readonly number[]) => film[3 * i]! * c[0]! + film[3 * i + 1]! * c[1]! + film[3 * i + 2]! * c[2]!;
  const lit = reflected.map((c, i) => c * tint[i]!);
  return [0, 1, 2].map((i) => m(i, lit) + transmitted[i]! - m(i, transmitted)) as unknown as Rgb;
}

/** The environment a still image shows: an HDR `env` needs its pixels (environmentMaps.ts), a uniform one its colour. */
function shownEnvironment(s: FilmSettings, map: EnvironmentPixels | null): ShownEnvironment {
  const kind = environmentKind(s.env);
  const color = environmentColor(s.env);
  if (color) return { kind: 'color', color };
  if (kind === 'none' || kind === 'sky') return { kind };
  if (!map) throw new Error(`the environment ${environmentText(s.env)} needs its pixels`);
  return { kind: 'map', pixels: map, rotationDeg: s.envRotationDeg };
}

/**
 * A still image of the bubble computed on the CPU by src/physics, for pages without WebGL2:
 * the geometry and light paths of shaders/bubbleMaterials/bubble.frag.glsl (near wall and far wall seen from
 * inside at the same θ_i, each reflecting the environment in its mirror direction, environment
 * behind; `map`: the pixels of an HDR `env`) at `settings.timeSeconds`, times the exposure, tone
 * mapped as the GPU does (toneMapping.ts), in sRGB (8-bit, clipped). Row 0 is the top.
 * Differences from the GPU: sRGB even where a wide gamut was asked for (no hatching), film colours
 * interpolated on a lattice (see COS_STEPS), one ray per pixel (no antialiasing), the map in
 * float32 (the GPU's is half float).
 */
export function cpuBubbleImage(
  settings: FilmSettings,
  width: number,
  height: number,
  map: EnvironmentPixels | null = null,
): Uint8ClampedArray<ArrayBuffer> {
  const pixels = new Uint8ClampedArray(4 * width * height);
  const env = shownEnvironment(settings, map);
  const mapping = toneMappingOf(settings);
  const film = filmColorLattice(settings);
  const tanHalf = Math.tan((FOV_DEG * Math.PI) / 360);
  const eye: Vec3 = [0, 0, CAMERA_DISTANCE];
  for (let row = 0; row < height; row++) {
    for (let col = 0; col < width; col++) {
      const ndcX = (2 * (col + 0.5)) / width - 1;
      const ndcY = 1 - (2 * (row + 0.5)) / height;
      const dir = normalize([ndcX * tanHalf * (width / height), ndcY * tanHalf, -1]);
      const b = dot(eye, dir);
      const disc = b * b - (CAMERA_DISTANCE * CAMERA_DISTANCE - 1);
      let radiance: Rgb;
      if (disc < 0) {
        radiance = environmentRadiance(dir, env); // at infinity, as the bubble sees it
      } else {
        radiance = bubbleRadiance(settings, env, film, eye, dir, -b - Math.sqrt(disc));
      }
      const color = toneMap(radiance.map((c) => settings.exposure * c) as unknown as Rgb, mapping);
      pixels.set([encode8(clamp01(color[0])), encode8(clamp01(color[1])), encode8(clamp01(color[2])), 255], 4 * (row * width + col));
    }
  }
  return pixels;
}

/** shaders/bubbleMaterials/bubble.frag.glsl (before the exposure) for the ray eye + t·dir that meets the bubble at t. */
function bubbleRadiance(s: FilmSettings, env: ShownEnvironment, film: FilmColor, eye: Vec3, dir: Vec3, t: number): Rgb {
  const p = normalize([eye[0] + t * dir[0], eye[1] + t * dir[1], eye[2] + t * dir[2]]);
  const cos = clamp01(Math.abs(dot(p, dir)));
  const near = film(thicknessAt(p, s), cos, false);
  const nearLight = reflectedRadiance(reflect(dir, p), env);
  // An opaque inside (a metal) transmits nothing: no far wall, nothing behind.
  const opaque = absorbsInBand(s.nInside);
  let behind: Rgb = opaque ? [0, 0, 0] : environmentRadiance(dir, env);
  if (s.sides === 'both' && !opaque) {
    // The chord through a unit sphere at incidence θ has length 2 cos θ (toEye = −dir).
    const far = normalize([p[0] + 2 * cos * dir[0], p[1] + 2 * cos * dir[1], p[2] + 2 * cos * dir[2]]);
    behind = wallRadiance(film(thicknessAt(far, s), cos, true), reflectedRadiance(reflect(dir, far), env), behind, s.lightTint);
  }
  return wallRadiance(near, nearLight, behind, s.lightTint);
}
