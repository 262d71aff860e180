// XYZ -> three.js's working space (linear sRGB, eq 19), the matrix every shader that shows the
// film's colour applies to tfcFilmXyz (set by filmColorUniforms, src/film/filmColor.ts).
#ifndef THIN_FILM_WORKING_SPACE
#define THIN_FILM_WORKING_SPACE
uniform mat3 uXyzToLinearWorking;
#endif
