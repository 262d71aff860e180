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

/** The principal square root (Re ≥ 0), formed without cancellation. */
export function cSqrt(z: Complex): Complex {
  if (z.re === 0 && z.im === 0) return { re: 0, im: 0 };
  const m = Math.sqrt((Math.abs(z.re) + Math.hypot(z.re, z.im)) / 2);
  return z.re >= 0 ? { re: m, im: z.im / (2 * m) } : { re: Math.abs(z.im) / (2 * m), im: z.im >= 0 ? m : -m };
}

/**
 * A refractive index at one wavelength: a real n, or ñ = n + ik with k ≥ 0 for an absorbing medium
 * (docs/physics.md#absorbing-media). A complex value with k = 0 is the real index n, bit for bit.
 */
export type RefractiveIndex = number | Complex;

/** ñ as a complex number. */
export const asComplex = (n: RefractiveIndex): Complex => (typeof n === 'number' ? { re: n, im: 0 } : n);

/** The real index n when there is no absorption (k = 0), else null. */
export const realIndex = (n: RefractiveIndex): number | null => (typeof n === 'number' ? n : n.im === 0 ? n.re : null);

/** z · n: a real scale where n is real (so the real path is unchanged), a complex product otherwise. */
export function cTimesIndex(z: Complex, n: RefractiveIndex): Complex {
  const real = realIndex(n);
  return real === null ? cMul(z, n as Complex) : cScale(z, real);
}

/** Whether two indices are the same number (n and k). */
export const sameIndex = (a: RefractiveIndex, b: RefractiveIndex): boolean => {
  const [x, y] = [asComplex(a), asComplex(b)];
  return x.re === y.re && x.im === y.im;
};
