/**
 * The TypeScript ↔ GLSL contract for floats packed into RGBA float texels: a record's fields by
 * name, each a float or a vec2 to a vec4, laid out in the order listed, TEXEL_FLOATS to a texel.
 * The shader reads (and a pass writes) a field through shaders/gpu/texelRecord.glsl by its define,
 * `PREFIX_FIELD` (its offset in floats from the record's start), never by a swizzle or a number:
 * both sides take the offsets from here, so reordering the fields cannot change what is drawn.
 */

/** The floats of an RGBA texel. */
export const TEXEL_FLOATS = 4;

/** A field's floats: a float, a vec2, a vec3 or a vec4. */
export type FieldWidth = 1 | 2 | 3 | 4;

export interface TexelRecord<F extends Readonly<Record<string, FieldWidth>>> {
  /** The prefix of its defines, e.g. `TFC_AIRY_ROW`. */
  readonly prefix: string;
  /** Each field's floats. */
  readonly fields: F;
  /** Each field's offset in floats from the record's start. */
  readonly offsets: Readonly<Record<keyof F, number>>;
  /** The texels of one record (`PREFIX_TEXELS`). */
  readonly texels: number;
  /** The floats of one record, its last texel's unused ones included. */
  readonly floats: number;
}

/** A record of `fields`, in their order, with its defines named `${prefix}_${field}`. */
export function texelRecord<const F extends Readonly<Record<string, FieldWidth>>>(prefix: string, fields: F): TexelRecord<F> {
  const offsets = {} as Record<keyof F, number>;
  let used = 0;
  for (const [name, width] of Object.entries(fields) as [keyof F, FieldWidth][]) {
    offsets[name] = used;
    used += width;
  }
  const texels = Math.ceil(used / TEXEL_FLOATS);
  return { prefix, fields, offsets, texels, floats: texels * TEXEL_FLOATS };
}

/** The defines of shaders/gpu/texelRecord.glsl and of the record: each field's offset, and the record's texels. */
export function texelRecordDefines(r: TexelRecord<Readonly<Record<string, FieldWidth>>>): Record<string, number> {
  return {
    TFC_TEXEL_FLOATS: TEXEL_FLOATS,
    [`${r.prefix}_TEXELS`]: r.texels,
    ...Object.fromEntries(Object.entries(r.offsets).map(([name, offset]) => [`${r.prefix}_${name}`, offset])),
  };
}

/** A field's value: a number for a float, [x, y, …] for a vector (either, for a field of several widths). */
export type FieldValues<F extends Readonly<Record<string, FieldWidth>>> = {
  readonly [K in keyof F]: [F[K]] extends [1]
    ? number
    : [F[K]] extends [2]
      ? readonly [number, number]
      : [F[K]] extends [3]
        ? readonly [number, number, number]
        : [F[K]] extends [4]
          ? readonly [number, number, number, number]
          : number | readonly number[];
};

/** Writes the record `index` of `data` (records packed one after another from float 0), each field by name. */
export function packTexelRecord<F extends Readonly<Record<string, FieldWidth>>>(
  r: TexelRecord<F>,
  data: Float32Array | Float64Array,
  index: number,
  values: FieldValues<F>,
): void {
  const at = index * r.floats;
  for (const name of Object.keys(r.fields) as (keyof F)[]) {
    const value = values[name];
    if (typeof value === 'number') data[at + r.offsets[name]] = value;
    else if (value.length === r.fields[name]) data.set(value, at + r.offsets[name]);
    else throw new Error(`${r.prefix}_${String(name)}: ${value.length} floats given for a field of ${r.fields[name]}`);
  }
}
