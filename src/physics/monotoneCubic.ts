/**
 * A monotone piecewise-cubic Hermite interpolant (F. N. Fritsch and R. E. Carlson, "Monotone
 * piecewise cubic interpolation", SIAM J. Numer. Anal. 17, 238–246 (1980), DOI 10.1137/0717021):
 * it passes through every node exactly, has a continuous first derivative, and between two nodes
 * stays between their values, so it adds no overshoot (a positive k stays positive).
 * Tangents: the mean of the neighbouring secants, 0 at a local extremum, one-sided at the ends,
 * then scaled down where α² + β² > 9 (the paper's sufficient condition for monotonicity).
 * Domain: xs strictly ascending (at least 2 nodes), x within [xs[0], xs[last]].
 */
export function monotoneCubic(xs: readonly number[], ys: readonly number[]): (x: number) => number {
  const last = xs.length - 1;
  const h = xs.slice(0, last).map((x, i) => xs[i + 1]! - x);
  const secant = h.map((hi, i) => (ys[i + 1]! - ys[i]!) / hi);
  const m = xs.map((_, i) => {
    if (i === 0) return secant[0]!;
    if (i === last) return secant[last - 1]!;
    const [a, b] = [secant[i - 1]!, secant[i]!];
    return a * b <= 0 ? 0 : (a + b) / 2;
  });
  secant.forEach((d, i) => {
    if (d === 0) {
      m[i] = 0;
      m[i + 1] = 0;
      return;
    }
    const [alpha, beta] = [m[i]! / d, m[i + 1]! / d];
    const r2 = alpha * alpha + beta * beta;
    if (r2 > 9) {
      const tau = 3 / Math.sqrt(r2);
      m[i] = tau * alpha * d;
      m[i + 1] = tau * beta * d;
    }
  });
  return (x: number): number => {
    if (!(x >= xs[0]! && x <= xs[last]!)) throw new RangeError(`monotoneCubic: ${x} is outside [${xs[0]}, ${xs[last]}]`);
    let i = 0;
    while (i < last - 1 && x > xs[i + 1]!) i++;
    const hi = h[i]!;
    const t = (x - xs[i]!) / hi;
    if (t === 0) return ys[i]!;
    if (t === 1) return ys[i + 1]!;
    const t2 = t * t;
    const t3 = t2 * t;
    // y_i + Δy·(3t² − 2t³) + h·(m_i(t³ − 2t² + t) + m_{i+1}(t³ − t²)): a flat segment gives y_i exactly.
    return ys[i]! + (ys[i + 1]! - ys[i]!) * (3 * t2 - 2 * t3) + hi * (m[i]! * (t3 - 2 * t2 + t) + m[i + 1]! * (t3 - t2));
  };
}
