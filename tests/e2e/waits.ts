/**
 * How long a browser test waits for a dispersive film's first frame in full. Its table (150 bins a
 * texel, Fresnel per bin) is built band by band in the app's frames, at about three times its own
 * cost. Here, beside a busy core and another worker, that takes 50–60 s a page on SwiftShader.
 * Four times that leaves room for a slower machine.
 */
export const DISPERSIVE_FIRST_FRAME_MS = 240_000;

/**
 * How long a browser test waits for the first frame in full of a stack of films that follows the
 * field: its table runs the stack's recursion through every layer for each bin of each texel, built
 * band by band in the app's frames. A 20-layer stack takes ~40 s on llvmpipe beside another worker
 * (the tests' 4-layer one a few seconds); four times that leaves room for a slower machine.
 */
export const STACK_FIRST_FRAME_MS = 160_000;
