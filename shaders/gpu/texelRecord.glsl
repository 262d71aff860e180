// A record of floats packed TFC_TEXEL_FLOATS to an RGBA texel (src/gpu/texelRecord.ts), read by its
// fields' names: a field's define is its offset in floats from the record's start, so the reads
// follow the order TypeScript packs. `record` is the array of the record's texels as fetched
// (vec4[PREFIX_TEXELS]); a vector field takes the float at its offset and those after it.
#ifndef THIN_FILM_TEXEL_RECORD
#define THIN_FILM_TEXEL_RECORD

#define TFC_RECORD_FLOAT(record, offset) record[(offset) / TFC_TEXEL_FLOATS][(offset) % TFC_TEXEL_FLOATS]
#define TFC_RECORD_VEC2(record, offset) vec2(TFC_RECORD_FLOAT(record, offset), TFC_RECORD_FLOAT(record, (offset) + 1))

// A record of one texel (PREFIX_TEXELS = 1), held as the vec4 `texel`, its fields read and set at
// their offsets. An offset past the texel indexes the vec4 out of range: a compile error.
#define TFC_TEXEL_FLOAT(texel, offset) (texel)[offset]
#define TFC_TEXEL_VEC2(texel, offset) vec2((texel)[offset], (texel)[(offset) + 1])
#define TFC_TEXEL_VEC3(texel, offset) vec3(TFC_TEXEL_VEC2(texel, offset), (texel)[(offset) + 2])
#define TFC_TEXEL_VEC4(texel, offset) vec4(TFC_TEXEL_VEC3(texel, offset), (texel)[(offset) + 3])
#define TFC_SET_TEXEL_FLOAT(texel, offset, value) (texel)[offset] = (value)
#define TFC_SET_TEXEL_VEC3(texel, offset, value) (texel)[offset] = (value).x; (texel)[(offset) + 1] = (value).y; (texel)[(offset) + 2] = (value).z
#define TFC_SET_TEXEL_VEC4(texel, offset, value) TFC_SET_TEXEL_VEC3(texel, offset, value); (texel)[(offset) + 3] = (value).w

#endif
