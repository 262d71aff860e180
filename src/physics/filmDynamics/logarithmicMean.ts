/** Below this |δ| the series 1 − δ²/3 replaces δ/atanh δ (its next term, 4δ⁴/45, is under 1e-13 there). */
export const LOG_MEAN_SERIES_BELOW = 1e-3;

/**
 * The logarithmic mean L(a, b) = (a − b)/(ln a − ln b) of two non-negative numbers, L(a, a) = a and
 * L(0, b) = 0, written as m·δ/atanh δ with m = (a + b)/2 and δ = (a − b)/(a + b) so it stays
 * accurate as a → b. It is the edge thickness that makes Δ ln η = Δη/L exact, which keeps a film
 * resting in the profile e^(−a cos θ) exactly at rest (docs/flow.md#the-step).
 */
export function logarithmicMean(a: number, b: number): number {
  const sum = a + b;
  if (sum <= 0) return 0;
  const delta = (a - b) / sum;
  const mean = 0.5 * sum;
  if (Math.abs(delta) < LOG_MEAN_SERIES_BELOW) return mean * (1 - (delta * delta) / 3);
  if (Math.abs(delta) >= 1) return 0;
  return (mean * delta) / Math.atanh(delta);
}
