/**
 * The table pass keeps a material, with its program, for each of this many sets of defines (a
 * constant and a dispersive film, say), so going back to a film drawn before compiles nothing.
 */
export const KEPT_PASSES = 2;

/** The table pass's material name: three names its programs after it (renderer.info.programs). */
export const TABLE_PASS_NAME = 'tfcFilmTablePass';
