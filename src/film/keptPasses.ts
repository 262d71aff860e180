/**
 * The table pass keeps the programs of this many sets of defines (a constant and a dispersive film,
 * say), so going back to a film drawn before compiles nothing: on a GPU that compiles on the
 * calling thread (SwiftShader) a compile is a stall of several frames.
 */
export const KEPT_PASSES = 2;

/** The table pass's material name: three names its programs after it (renderer.info.programs). */
export const TABLE_PASS_NAME = 'tfcFilmTablePass';
