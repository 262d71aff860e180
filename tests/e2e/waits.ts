/**
 * How long a browser test waits for a dispersive film's first frame in full. Its table (150 bins a
 * texel, Fresnel per bin) is built band by band in the app's frames, at about three times its own
 * cost. Here, beside a busy core and another worker, that takes 50–60 s a page on SwiftShader.
 * Four times that leaves room for a slower machine.
 */
export const DISPERSIVE_FIRST_FRAME_MS = 240_000;
