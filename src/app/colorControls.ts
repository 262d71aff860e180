import type GUI from 'lil-gui';
import type { Controller } from 'lil-gui';
import type { NumberDomain } from '../input/validate.ts';
import { ENVIRONMENTS, type Environment, type NamedEnvironment, environmentColor } from '../environments/environments.ts';
import { ENVIRONMENT_COLOR_DOMAIN } from '../environments/environmentColor.ts';
import { LIGHT_TINT_DOMAIN, type LightTint } from '../physics/lightTint.ts';
import type { Catalogue, MessageKey } from '../i18n/en.ts';
import { type ParameterRow, choiceKey, labelKey } from '../settings/parameterRow.ts';
import type { ViewSettings } from '../settings/viewParameters.ts';

/* The panel's controls of a colour given as linear sRGB: a light's tint, a uniform environment. */

type Triple = readonly [number, number, number];

/** The sliders' step. */
const RGB_STEP = 0.01;
/** The panel's choice for a uniform coloured environment, after the registry's names (its label `choice.env.color`). */
export const UNIFORM_COLOR = 'color';
/** Where the environment's sliders start when the environment given is a name: the light's white. */
const COLOR_START: Triple = [1, 1, 1];

/** Three sliders, R, G and B, over `domain`, named by the catalogue's `labels`: the sliders and the colour they hold. */
function addRgbSliders(folder: GUI, initial: Triple, domain: NumberDomain, labels: readonly MessageKey[], cat: Catalogue) {
  const rgb = { r: initial[0], g: initial[1], b: initial[2] };
  const sliders = (['r', 'g', 'b'] as const).map((c, i) => folder.add(rgb, c, domain.min, domain.max, RGB_STEP).name(cat[labels[i]!]));
  return { sliders, rgb: (): Triple => [rgb.r, rgb.g, rgb.b] };
}

/** A light's tint: a slider for each of R, G and B (linear sRGB) over the tint's domain. */
export function addTintControl(
  folder: GUI,
  row: ParameterRow<ViewSettings>,
  initial: LightTint,
  cat: Catalogue,
): () => Partial<ViewSettings> {
  const { rgb } = addRgbSliders(folder, initial, LIGHT_TINT_DOMAIN, ['panel.tintRed', 'panel.tintGreen', 'panel.tintBlue'], cat);
  return () => ({ [row.key]: rgb() });
}

/**
 * An environment: a list of the registry's names and `color`, a uniform colour whose R, G and B
 * sliders (over its domain) are shown while it is chosen; they start at the colour given, else at
 * the light's white.
 */
export function addEnvironmentControl(
  folder: GUI,
  row: ParameterRow<ViewSettings>,
  initial: Environment,
  cat: Catalogue,
): { readonly join: () => Partial<ViewSettings>; readonly shows: (c: Controller) => boolean } {
  const given = environmentColor(initial);
  const choice = { name: given ? UNIFORM_COLOR : (initial as NamedEnvironment) };
  const listed = Object.fromEntries([...ENVIRONMENTS, UNIFORM_COLOR].map((v) => [cat[choiceKey(row.key, v)], v]));
  folder.add(choice, 'name', listed).name(cat[labelKey(row.key)]);
  const labels: MessageKey[] = ['panel.environmentRed', 'panel.environmentGreen', 'panel.environmentBlue'];
  const { sliders, rgb } = addRgbSliders(folder, given ?? COLOR_START, ENVIRONMENT_COLOR_DOMAIN, labels, cat);
  const chosen = (): Environment => (choice.name === UNIFORM_COLOR ? { color: rgb() } : (choice.name as NamedEnvironment));
  return { join: () => ({ [row.key]: chosen() }), shows: (c) => !sliders.includes(c) || choice.name === UNIFORM_COLOR };
}
