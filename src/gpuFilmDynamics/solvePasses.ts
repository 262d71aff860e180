import type { Texture, WebGLRenderTarget } from 'three';
import type { ChebyshevSchedule } from '../physics/filmDynamics/chebyshevSchedule.ts';
import type { PassName } from './flowPasses.ts';
import type { FlowTargets } from './flowTargets.ts';
import { SWEEP_GUESS, SWEEP_PREVIOUS_GUESS, ZERO_GUESS } from './flowTexels.ts';
import type { FlowUniformName } from './flowUniforms.ts';

/** What a draw points its uniforms at: the targets the passes before it wrote, and values. */
export type DrawInputs = Partial<Record<FlowUniformName, Texture | readonly number[] | number>>;

/** A pass drawn into a target, its inputs set first. */
export type DrawPass = (pass: PassName, target: WebGLRenderTarget, inputs: DrawInputs) => void;

/**
 * Passes 1 to 5 of the twin's stepFilm from a film and its edge velocities: the cell velocity and
 * its halo, the edge prediction (u*, c_e), and the surfactant solve, its weights, its system and
 * the schedule's Chebyshev sweeps from δ = 0, each into its target of `t`. Returns the sweep's
 * target that holds the solved increment δ (a SURFACTANT_SWEEP's X).
 */
export function drawPredictionAndSolve(
  draw: DrawPass,
  t: FlowTargets,
  state: { readonly film: Texture; readonly edgeVelocity: Texture },
  schedule: Pick<ChebyshevSchedule, 'momentum' | 'step'>,
): WebGLRenderTarget {
  draw('reconstruct', t.cellVelocity, { uEdgeVelocity: state.edgeVelocity });
  draw('pad', t.paddedCellVelocity, { uField: t.cellVelocity.texture });
  draw('predict', t.prediction, {
    uFilm: state.film,
    uCellVelocity: t.cellVelocity.texture,
    uPaddedCellVelocity: t.paddedCellVelocity.texture,
  });
  draw('weights', t.weights, { uPrediction: t.prediction.texture });
  draw('system', t.system, { uSurfactantWeights: t.weights.texture });
  const [one, other] = t.sweeps;
  const { momentum, step } = schedule;
  const coefficients = (k: number) => ({ uChebyshevMomentum: momentum[k]!, uChebyshevStep: step[k]! });
  draw('sweep', one, {
    uSurfactantRhs: t.system.texture,
    uGuess: t.system.texture,
    uGuessChannel: ZERO_GUESS,
    uPreviousGuessChannel: ZERO_GUESS,
    ...coefficients(0),
  });
  let x = one;
  for (let k = 1; k < step.length; k++) {
    const next = x === one ? other : one;
    draw('sweep', next, { uGuess: x.texture, uGuessChannel: SWEEP_GUESS, uPreviousGuessChannel: SWEEP_PREVIOUS_GUESS, ...coefficients(k) });
    x = next;
  }
  return x;
}
