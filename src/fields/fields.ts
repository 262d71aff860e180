import { drainageField } from './drainageField.ts';
import { flowField } from './flowField.ts';
import { swirlField } from './swirlField.ts';
import type {
  DrawnField,
  FieldSetting,
  FieldUniforms,
  SettingValues,
  SharedFieldSettings,
  ThicknessField,
  Vec3,
} from './thicknessField.ts';
import { uniformField } from './uniformField.ts';

/**
 * Every thickness field, by its name in the URL (`field=`): the one place a field is registered.
 * The schema's choices and the rows of the fields' own settings, the settings' members, the
 * shader's TFC_THICKNESS_FIELD, the table's range and the simulations of the evolving ones
 * (src/bubbleMaterials/fieldStates.ts) all come from here.
 */
export const THICKNESS_FIELDS = {
  uniform: uniformField,
  drainage: drainageField,
  swirl: swirlField,
  flow: flowField,
} as const;

export type FieldName = keyof typeof THICKNESS_FIELDS;
export const FIELDS = Object.keys(THICKNESS_FIELDS) as FieldName[];

/** The fields whose film evolves (their `evolves`). */
export type EvolvingField = { [K in FieldName]: (typeof THICKNESS_FIELDS)[K]['evolves'] extends true ? K : never }[FieldName];

type Intersection<U> = (U extends unknown ? (u: U) => void : never) extends (i: infer I) => void ? I : never;
/** Every field's own settings, by their settings key. */
type FieldSettingRowsOfAll = Intersection<(typeof THICKNESS_FIELDS)[FieldName]['settings']>;

/** What the fields read of the settings: the shared settings and every field's own. */
export type FieldSettings = SharedFieldSettings & SettingValues<FieldSettingRowsOfAll>;

/** The own settings of every field (one declaration for a setting that fields share), in the registry's order: the rows of the schema follow. */
export const FIELD_SETTINGS = FIELDS.reduce<Record<string, FieldSetting>>((all, name) => {
  for (const [key, setting] of Object.entries<FieldSetting>(THICKNESS_FIELDS[name].settings)) {
    if (Object.hasOwn(all, key) && all[key] !== setting) throw new Error(`the fields declare their setting ${key} twice`);
    all[key] = setting;
  }
  return all;
}, {}) as FieldSettingRowsOfAll;

/** The settings the field `name` reads: the shared ones it names and its own. */
export const fieldReads = (name: FieldName): readonly (keyof FieldSettings)[] => [
  ...THICKNESS_FIELDS[name].reads,
  ...(Object.keys(THICKNESS_FIELDS[name].settings) as (keyof FieldSettings)[]),
];

/** Every setting some field reads. */
const FIELD_READS: ReadonlySet<string> = new Set(FIELDS.flatMap(fieldReads));

/**
 * Whether the setting `key` applies under the field `name`: a setting no field reads is not the
 * fields' (it applies under each); one some field reads applies only under the fields that read it.
 */
export const settingApplies = (key: string, name: FieldName): boolean =>
  !FIELD_READS.has(key) || (fieldReads(name) as readonly string[]).includes(key);

/** The thickness in nm at `p` of the field `s.field` (the TypeScript twin of the shader's `tfcThicknessAt`). */
export const thicknessAt = (p: Vec3, s: FieldSettings & { readonly field: FieldName }): number =>
  THICKNESS_FIELDS[s.field].thicknessAt(p, s);

/** What a field derives of the settings (its `derive`): null for one that derives nothing. */
type DerivedOf<F> = F extends ThicknessField<infer _R, infer _E, infer D> ? D : never;
/** What the fields `K` derive of the settings: the flowing film's parameters; null for the others. */
export type FieldDerived<K extends FieldName = FieldName> = DerivedOf<(typeof THICKNESS_FIELDS)[K]>;

/** A registered field as the functions below call it, for the settings of any field (its own are among them). */
interface AnyField {
  derive?(s: FieldSettings): FieldDerived;
  maxThicknessNm(s: FieldSettings, derived: FieldDerived): number;
  update(u: FieldUniforms, s: FieldSettings, drawn: DrawnField<FieldDerived>): void;
}
const fieldOf = (name: FieldName): AnyField => THICKNESS_FIELDS[name];

/** The field `s.field` as a frame draws it: what it derives of the settings, once, and the largest thickness it reaches. */
export function drawnField(s: FieldSettings & { readonly field: FieldName }): DrawnField<FieldDerived> {
  const field = fieldOf(s.field);
  const derived = field.derive?.(s) ?? null;
  return { derived, maxThicknessNm: field.maxThicknessNm(s, derived) };
}

/** Sets the uniforms of the field `s.field` to the settings as `drawn` (drawnField's) draws it. */
export const updateFieldUniforms = (
  u: FieldUniforms,
  s: FieldSettings & { readonly field: FieldName },
  drawn: DrawnField<FieldDerived>,
): void => fieldOf(s.field).update(u, s, drawn);

/** The largest thickness the field reaches, which the film table must cover. */
export const maxFieldThicknessNm = (s: FieldSettings & { readonly field: FieldName }): number => drawnField(s).maxThicknessNm;
