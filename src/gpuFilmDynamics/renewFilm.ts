/**
 * A new bubble after a burst (shaders/gpuFilmDynamics/renewFilm.glsl is the twin; the GPU's own, the float64
 * twin bursts once): once every rim of an opened hole has reached the far side of the sphere, so no
 * film is left, the simulation counts steps, and RENEW_DELAY_S film seconds later its film is back
 * at its start (the same seed), the holes closed. It runs on the GPU from the film's own state, so a
 * frozen view at a time after the burst draws the same pixels on every load.
 * docs/flow.md#the-gpu-port.
 */

/** Film seconds from the moment no film is left to the new bubble. */
export const RENEW_DELAY_S = 0.25;

/** The burst's count of steps at which the film renews (at least one step), or 0 for never. */
export const renewSteps = (renew: boolean, stepSeconds: number): number =>
  renew ? Math.max(1, Math.ceil(RENEW_DELAY_S / stepSeconds)) : 0;
