// A record of floats packed TFC_TEXEL_FLOATS to an RGBA texel (src/gpu/texelRecord.ts), read by its
// fields' names: a field's define is its offset in floats from the record's start, so the reads
// follow the order TypeScript packs. `record` is the array of the record's texels as fetched
// (vec4[PREFIX_TEXELS]); a vec2 field takes the float at its offset and the next.
#ifndef THIN_FILM_TEXEL_RECORD
#define THIN_FILM_TEXEL_RECORD

#define TFC_RECORD_FLOAT(record, offset) record[(offset) / TFC_TEXEL_FLOATS][(offset) % TFC_TEXEL_FLOATS]
#define TFC_RECORD_VEC2(record, offset) vec2(TFC_RECORD_FLOAT(record, offset), TFC_RECORD_FLOAT(record, (offset) + 1))

#endif
