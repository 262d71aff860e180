/**
 * Complex arithmetic for the Fresnel and Airy formulas (float64).
 *
 * Cosines of refraction angles become imaginary under total internal reflection, and the film
 * phase becomes complex with them (docs/physics.md#complex-angles), so every quantity from
 * Snell's law onward is complex. Mirrored by `shaders/physics/complex.glsl` (vec2 = re, im).
 */
export interface Complex {
  readonly re: number;
  readonly im: number;
}

export const cAdd = (a: Complex, b: Complex): Complex => ({ re: a.re + b.re, im: a.im + b.im });

export const cSub = (a: Complex, b: Complex): Complex => ({ re: a.re - b.re, im: a.im - b.im });

export const cMul = (a: Complex, b: Complex): Complex => ({
  re: a.re * b.re - a.im * b.im,
  im: a.re * b.im + a.im * b.re,
});

export const cScale = (a: Complex, s: number): Complex => ({ re: a.re * s, im: a.im * s });

/** a / b by Smith's algorithm, which avoids overflow in |b|²; b must not be 0. */
export function cDiv(a: Complex, b: Complex): Complex {
  if (Math.abs(b.re) >= Math.abs(b.im)) {
    const t = b.im / b.re;
    const d = b.re + b.im * t;
    return { re: (a.re + a.im * t) / d, im: (a.im - a.re * t) / d };
  }
  const t = b.re / b.im;
  const d = b.re * t + b.im;
  return { re: (a.re * t + a.im) / d, im: (a.im * t - a.re) / d };
}

export const cAbs2 = (a: Complex): number => a.re * a.re + a.im * a.im;

/** e^{i z} = e^{-Im z} (cos Re z + i sin Re z). */
export function cExpI(z: Complex): Complex {
  const m = Math.exp(-z.im);
  return { re: m * Math.cos(z.re), im: m * Math.sin(z.re) };
}
