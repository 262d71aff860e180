/**
 * Texel records: fields laid out in their order, TEXEL_FLOATS to a texel; a field packed by name
 * reads back by name, the way shaders/gpu/texelRecord.glsl reads it (texel offset / 4, channel
 * offset % 4), whatever the order of the fields.
 */
import { describe, expect, it } from 'vitest';
import { TEXEL_FLOATS, type TexelRecord, packTexelRecord, texelRecord, texelRecordDefines } from '../../../src/gpu/texelRecord.ts';

type Fields = Readonly<Record<string, 1 | 2 | 3 | 4>>;

/** A field of record `index` as the GLSL macros read it: from the record's texels, by its offset. */
function readField(r: TexelRecord<Fields>, data: Float32Array, index: number, name: string): number | [number, number] {
  const texels = Array.from({ length: r.texels }, (_, t) => data.subarray((index * r.texels + t) * 4, (index * r.texels + t + 1) * 4));
  const float = (offset: number) => texels[Math.floor(offset / TEXEL_FLOATS)]![offset % TEXEL_FLOATS]!;
  const offset = r.offsets[name]!;
  return r.fields[name] === 2 ? [float(offset), float(offset + 1)] : float(offset);
}

describe('texel records', () => {
  it('lay fields out in order, a vec2 across a texel boundary if it falls there, and round the record up to whole texels', () => {
    const r = texelRecord('TFC_TEST', { A: 1, B: 2, C: 2, D: 1 });
    expect(r.offsets).toEqual({ A: 0, B: 1, C: 3, D: 5 });
    expect([r.texels, r.floats]).toEqual([2, 8]);
    expect(texelRecordDefines(r)).toEqual({
      TFC_TEXEL_FLOATS: 4,
      TFC_TEST_TEXELS: 2,
      TFC_TEST_A: 0,
      TFC_TEST_B: 1,
      TFC_TEST_C: 3,
      TFC_TEST_D: 5,
    });
  });

  it('take vec3 and vec4 fields, and refuse a value of another width by its define', () => {
    const r = texelRecord('TFC_TEST', { A: 3, B: 1, C: 4 });
    expect([r.offsets, r.texels]).toEqual([{ A: 0, B: 3, C: 4 }, 2]);
    const data = new Float32Array(r.floats);
    packTexelRecord(r, data, 0, { A: [1, 2, 3], B: 4, C: [5, 6, 7, 8] });
    expect([...data]).toEqual([1, 2, 3, 4, 5, 6, 7, 8]);
    const loose: TexelRecord<Fields> = r;
    expect(() => packTexelRecord(loose, data, 0, { A: [1, 2], B: 4, C: [5, 6, 7, 8] })).toThrow(
      'TFC_TEST_A: 2 floats given for a field of 3',
    );
  });

  it('a record of 4 floats is one texel; of 5, two', () => {
    expect(texelRecord('TFC_TEST', { A: 2, B: 2 }).texels).toBe(1);
    expect(texelRecord('TFC_TEST', { A: 2, B: 2, C: 1 }).texels).toBe(2);
  });

  it('what is packed by name reads back by name, in every record of an array, whatever the order of the fields', () => {
    const values = { A: 1.5, B: [2.5, -3] as const, C: [4, 5.25] as const, D: -6 };
    const orders: Fields[] = [
      { A: 1, B: 2, C: 2, D: 1 },
      { D: 1, C: 2, A: 1, B: 2 },
      { B: 2, A: 1, D: 1, C: 2 },
    ];
    const packed = orders.map((fields) => {
      const r: TexelRecord<Fields> = texelRecord('TFC_TEST', fields);
      const data = new Float32Array(3 * r.floats);
      for (let i = 0; i < 3; i++) packTexelRecord(r, data, i, { ...values, A: values.A + i });
      return { r, data };
    });
    // The orders pack differently …
    expect(packed[0]!.data).not.toEqual(packed[1]!.data);
    // … and read the same.
    for (const { r, data } of packed)
      for (let i = 0; i < 3; i++) {
        expect(readField(r, data, i, 'A')).toBe(1.5 + i);
        expect(readField(r, data, i, 'B')).toEqual([2.5, -3]);
        expect(readField(r, data, i, 'C')).toEqual([4, 5.25]);
        expect(readField(r, data, i, 'D')).toBe(-6);
      }
  });
});
