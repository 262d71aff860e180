/**
 * How an environment is drawn (TFC_ENVIRONMENT in shaders/bubbleMaterials/environment.glsl, and the CPU
 * twin src/bubbleTwins/environment.ts): black, the procedural sky, or an equirectangular HDR map.
 */
export const ENVIRONMENT_KINDS = ['none', 'sky', 'map'] as const;
export type EnvironmentKind = (typeof ENVIRONMENT_KINDS)[number];

/** A module holding an HDR map as a base64 data URL of an EXR (512 × 256, linear Rec. 709). */
export type MapSource = () => Promise<{ readonly default: string }>;

/** An environment: its kind, and for a map where it comes from. */
export type EnvironmentEntry = { readonly kind: 'none' | 'sky' } | { readonly kind: 'map'; readonly source: MapSource };

const map = (source: MapSource) => ({ kind: 'map', source }) as const;

/**
 * Every environment, by its name in the URL (`env=`): the one place an environment is registered.
 * `none` is black (the film lit by the light's white: the reference views), `sky` procedural; the
 * maps are CC0 equirectangular EXRs from @pmndrs/assets, each its own dynamic import, so a page
 * fetches only the one it shows. Its label is the message `choice.env.<name>` in each catalogue.
 */
export const ENVIRONMENT_REGISTRY = {
  sky: { kind: 'sky' },
  none: { kind: 'none' },
  park: map(() => import('@pmndrs/assets/hdri/park.exr.js')),
  sunset: map(() => import('@pmndrs/assets/hdri/sunset.exr.js')),
  studio: map(() => import('@pmndrs/assets/hdri/studio.exr.js')),
  city: map(() => import('@pmndrs/assets/hdri/city.exr.js')),
} as const satisfies Record<string, EnvironmentEntry>;

export type Environment = keyof typeof ENVIRONMENT_REGISTRY;
export const ENVIRONMENTS = Object.keys(ENVIRONMENT_REGISTRY) as Environment[];
/** The environments shown from an HDR map. */
export type HdrEnvironment = {
  [K in Environment]: (typeof ENVIRONMENT_REGISTRY)[K] extends { readonly kind: 'map' } ? K : never;
}[Environment];

/** How `env` is drawn (its type follows the name: the kind of a given environment is known where its name is). */
export const environmentKind = <E extends Environment>(env: E): (typeof ENVIRONMENT_REGISTRY)[E]['kind'] => ENVIRONMENT_REGISTRY[env].kind;
export const isHdrEnvironment = (env: Environment): env is HdrEnvironment => environmentKind(env) === 'map';
export const HDR_ENVIRONMENTS = ENVIRONMENTS.filter(isHdrEnvironment);

/** Where an HDR environment's map comes from. */
export const mapSource = (env: HdrEnvironment): MapSource => ENVIRONMENT_REGISTRY[env].source;

/** The environment shown in place of an HDR one until its map arrives, or when it fails to load. */
export const STAND_IN_ENVIRONMENT = 'sky' satisfies Environment;
