import {
  ENVIRONMENT_COLOR_DOMAIN,
  ENVIRONMENT_COLOR_EXPECTED,
  ENVIRONMENT_COLOR_FORM,
  type EnvironmentColor,
  environmentColorText,
  readEnvironmentColor,
} from './environmentColor.ts';

/**
 * How an environment is drawn (TFC_ENVIRONMENT in shaders/bubbleMaterials/environment.glsl, and the CPU
 * twin src/bubbleTwins/environment.ts): black, the procedural sky, an equirectangular HDR map, or
 * one colour from every direction (environmentColor.ts).
 */
export const ENVIRONMENT_KINDS = ['none', 'sky', 'map', 'color'] as const;
export type EnvironmentKind = (typeof ENVIRONMENT_KINDS)[number];

/** An environment: its kind. */
export interface EnvironmentEntry {
  readonly kind: Exclude<EnvironmentKind, 'color'>;
}

/**
 * Every environment, by its name in the URL (`env=`): the one place an environment is registered.
 * `none` is black (the film lit by the light's white: the reference views), `sky` procedural; a
 * `map` is an HDR map, whose source hdrMaps.ts gives (apart, so that what only asks what an
 * environment is, a material's film say, brings no map into a build). Its label is the message
 * `choice.env.<name>` in each catalogue.
 */
export const ENVIRONMENT_REGISTRY = {
  sky: { kind: 'sky' },
  none: { kind: 'none' },
  park: { kind: 'map' },
  sunset: { kind: 'map' },
  studio: { kind: 'map' },
  city: { kind: 'map' },
} as const satisfies Record<string, EnvironmentEntry>;

/** An environment by its name in the registry. */
export type NamedEnvironment = keyof typeof ENVIRONMENT_REGISTRY;
/** The registry's names, in the order every interface lists them. */
export const ENVIRONMENTS = Object.keys(ENVIRONMENT_REGISTRY) as NamedEnvironment[];
/** A uniform coloured environment (text `color:R,G,B`, environmentColor.ts). */
export interface ColorEnvironment {
  readonly color: EnvironmentColor;
}
/** An environment: a name in the registry, or a uniform colour. */
export type Environment = NamedEnvironment | ColorEnvironment;
/** The environments shown from an HDR map. */
export type HdrEnvironment = {
  [K in NamedEnvironment]: (typeof ENVIRONMENT_REGISTRY)[K] extends { readonly kind: 'map' } ? K : never;
}[NamedEnvironment];

type KindOf<E extends Environment> = E extends NamedEnvironment
  ? (typeof ENVIRONMENT_REGISTRY)[E] extends { readonly kind: infer K }
    ? K
    : never
  : 'color';
const isNamed = (env: unknown): env is NamedEnvironment => typeof env === 'string' && Object.hasOwn(ENVIRONMENT_REGISTRY, env);

/** How `env` is drawn (its type follows the name: the kind of a given environment is known where its name is). */
export const environmentKind = <E extends Environment>(env: E): KindOf<E> =>
  (isNamed(env) ? (ENVIRONMENT_REGISTRY as Readonly<Record<NamedEnvironment, EnvironmentEntry>>)[env].kind : 'color') as KindOf<E>;
export const isHdrEnvironment = (env: Environment): env is HdrEnvironment => environmentKind(env) === 'map';
/** The colour of a uniform environment, or null for one of the registry's. */
export const environmentColor = (env: Environment): EnvironmentColor | null => (isNamed(env) ? null : env.color);
export const HDR_ENVIRONMENTS = ENVIRONMENTS.filter(isHdrEnvironment);

/** The environment shown in place of an HDR one until its map arrives, or when it fails to load. */
export const STAND_IN_ENVIRONMENT = 'sky' satisfies Environment;

/** What an environment may be, as every message (URL, element, CLI) states it. */
export const ENVIRONMENT_EXPECTED = `one of ${ENVIRONMENTS.join(', ')}, or ${ENVIRONMENT_COLOR_EXPECTED}`;
/** The same as a catalogue's values (`expected.environment`). */
export const ENVIRONMENT_EXPECTED_VALUES = {
  names: ENVIRONMENTS.join(', '),
  form: ENVIRONMENT_COLOR_FORM,
  min: ENVIRONMENT_COLOR_DOMAIN.min,
  max: ENVIRONMENT_COLOR_DOMAIN.max,
} as const;

/**
 * An environment as text (URL, attribute, command line): a name or `color:R,G,B`; or why not
 * (`problem`, in English, where a colour's text says more than ENVIRONMENT_EXPECTED; else null).
 */
export function readEnvironment(text: string): { readonly env: Environment } | { readonly problem: string | null } {
  if (isNamed(text)) return { env: text };
  const reading = readEnvironmentColor(text);
  return 'color' in reading ? { env: { color: reading.color } } : reading;
}

/** An environment as text: its name or `color:R,G,B` (what readEnvironment reads back). */
export const environmentText = (env: Environment): string => (isNamed(env) ? env : environmentColorText(env.color));
