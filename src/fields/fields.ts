import { drainageField } from './drainageField.ts';
import { flowField } from './flowField.ts';
import { swirlField } from './swirlField.ts';
import type { FieldSettings, ThicknessField, Vec3 } from './thicknessField.ts';
import { uniformField } from './uniformField.ts';

/**
 * Every thickness field, by its name in the URL (`field=`): the one place a field is registered.
 * The schema's choices, the shader's TFC_THICKNESS_FIELD and the table's range all come from here.
 */
export const THICKNESS_FIELDS = {
  uniform: uniformField,
  drainage: drainageField,
  swirl: swirlField,
  flow: flowField,
} as const satisfies Record<string, ThicknessField>;

export type FieldName = keyof typeof THICKNESS_FIELDS;
export const FIELDS = Object.keys(THICKNESS_FIELDS) as FieldName[];

/** Every setting some field reads (each field's `reads`). */
const FIELD_READS: ReadonlySet<string> = new Set(FIELDS.flatMap((name) => THICKNESS_FIELDS[name].reads));

/**
 * Whether the setting `key` applies under the field `name`: a setting no field reads is not the
 * fields' (it applies under each); one some field reads applies only under the fields that read it.
 */
export const settingApplies = (key: string, name: FieldName): boolean =>
  !FIELD_READS.has(key) || (THICKNESS_FIELDS[name].reads as readonly string[]).includes(key);

/** The thickness in nm at `p` of the field `s.field` (the TypeScript twin of the shader's `tfcThicknessAt`). */
export const thicknessAt = (p: Vec3, s: FieldSettings & { readonly field: FieldName }): number =>
  THICKNESS_FIELDS[s.field].thicknessAt(p, s);

/** The largest thickness the field reaches, which the film table must cover. */
export const maxFieldThicknessNm = (s: FieldSettings & { readonly field: FieldName }): number =>
  THICKNESS_FIELDS[s.field].maxThicknessNm(s);
