import { GAMUT_MAPPINGS } from '../physics/colorConversions.ts';
import { DAYLIGHT_CCT_DOMAIN_K, LIGHT_ABOUT, NAMED_ILLUMINANTS } from '../physics/illuminants.ts';
import { LINE_DOMAIN_NM, LINE_PREFIX } from '../physics/lightLines.ts';
import { MEDIUM_NAMES, namedRangeNm, namedSource } from '../physics/namedMedia.ts';
import { CASE_FIELDS, CASE_FLAGS, MAX_WAVELENGTHS } from './colorCase.ts';
import { CELL_HEIGHT_2D_PX, MAX_CHART_COLUMNS, MAX_CHART_PIXELS, STRIP_HEIGHT_PX } from './chartLayout.ts';
import { MAX_CASES, MAX_CASES_NESTING_DEPTH } from './parseJsonArray.ts';
import { DESCRIPTION_COLUMN, optionLines } from './optionLines.ts';
import { MAX_TABLE_ROWS } from './tableValues.ts';

/** One line per named light and one for `line:NM`: its name and what it is. */
const lightLines = (): string =>
  [
    ...NAMED_ILLUMINANTS.map((name) => `  ${name}`.padEnd(DESCRIPTION_COLUMN) + LIGHT_ABOUT[name]),
    `  ${LINE_PREFIX}NM`.padEnd(DESCRIPTION_COLUMN) + `one line at NM nm, in [${LINE_DOMAIN_NM.min}, ${LINE_DOMAIN_NM.max}]`,
    `  K`.padEnd(DESCRIPTION_COLUMN) + `CIE daylight at a CCT of K kelvin, in [${DAYLIGHT_CCT_DOMAIN_K.min}, ${DAYLIGHT_CCT_DOMAIN_K.max}]`,
  ].join('\n');

/** One line per named medium: its name, what it is and whose values, and where the source gives them. */
const mediaLines = (): string =>
  MEDIUM_NAMES.map((name) => {
    const { min, max } = namedRangeNm(name);
    return `  ${name}`.padEnd(DESCRIPTION_COLUMN) + `${namedSource(name)}, ${min}–${max} nm`;
  }).join('\n');

/** `--help`: how to call the command. */
export const USAGE = `Colour of a thin film (a soap bubble) from the spectral interference integral.

Usage: npm run --silent color -- [flags]

One case (defaults: a 500 nm soap film in air, seen head-on, under D65):
${optionLines(CASE_FLAGS)}
                        --layers replaces --n-film; its d layers take --thickness (or each row's
                        thickness in a table)
  --gamut G             ${GAMUT_MAPPINGS.join(' | ')}: how out-of-gamut colours become 8-bit codes (clip)

Lights (for --illuminant; a line source's colour is summed over its lines):
${lightLines()}

Named media (for --n-film, --n-inside and a layer's index; --wavelengths within each one's range):
${mediaLines()}

Many cases:
  --cases FILE.json     a JSON array (at most ${MAX_CASES}) of objects with any of the fields
                        ${CASE_FIELDS.join(', ')};
                        illuminant is a name, "line:NM" or { "daylightCct": K }; lightTint [R, G, B];
                        wavelengthsNm an array
                        (at most ${MAX_WAVELENGTHS}); layers [{ "n", "thicknessNm" }, …] outside in,
                        in place of nFilm and thicknessNm, each n as nFilm, each thicknessNm a
                        number; id defaults to the case's index.
                        Nested at most ${MAX_CASES_NESTING_DEPTH} levels deep.

A table (at most ${MAX_TABLE_ROWS} rows), one row per thickness or angle, with #rrggbb:
  --from NM --to NM --step NM   over thickness (the other case flags apply to every row)
  --angles FROM:TO:STEP         over angle, at --thickness
  --format json|csv             (json)

A chart instead of a table, written to a file (at most ${MAX_CHART_COLUMNS} columns, ${MAX_CHART_PIXELS} pixels):
  --format png|svg              with --from/--to/--step: column i is row i of the table, in srgb8
  --out FILE                    the file to write (replaced atomically); stdout gets one JSON line
                                { out, format, width, height, cells }
  --height PX                   the strip's height, ${STRIP_HEIGHT_PX.min}–${STRIP_HEIGHT_PX.max} px (${STRIP_HEIGHT_PX.fallback})
  --angles FROM:TO:STEP         with --from/--to/--step: a 2-D chart, thickness along x, angle down
                                y from the top, each cell 1 × ${CELL_HEIGHT_2D_PX} px
                                Thickness ticks (nm) below the chart, angle ticks (degrees) right.
                                svg: one rect per cell, ticks as lines, labels as text.

Output: a JSON array, one object per case, in input order:
  { id, illuminant, lightTint, normalization, xyz, linearSrgb, srgb8, linearWideGamut, displayP3_8, reflectance,
    nFilm (or with layers nLayers: each layer's index at each wavelength), nInside }
Bad input: exit status 2, one line on stderr, nothing on stdout.
`;
