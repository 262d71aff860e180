/**
 * Where each HDR environment of the registry (environments.ts) comes from: CC0 equirectangular
 * EXRs from @pmndrs/assets, each its own dynamic import, so that a page fetches only the one it
 * shows. A module of its own: a build that reaches it emits every map as a chunk, so only what
 * draws an environment imports it, never a material's film.
 */
import { type HdrEnvironment } from './environments.ts';

/** A module holding an HDR map as a base64 data URL of an EXR (512 × 256, linear Rec. 709). */
export type MapSource = () => Promise<{ readonly default: string }>;

const HDR_MAP_SOURCES: Readonly<Record<HdrEnvironment, MapSource>> = {
  park: () => import('@pmndrs/assets/hdri/park.exr.js'),
  sunset: () => import('@pmndrs/assets/hdri/sunset.exr.js'),
  studio: () => import('@pmndrs/assets/hdri/studio.exr.js'),
  city: () => import('@pmndrs/assets/hdri/city.exr.js'),
};

/** Where an HDR environment's map comes from. */
export const mapSource = (env: HdrEnvironment): MapSource => HDR_MAP_SOURCES[env];
