import { type Complex } from './complex.ts';

/**
 * A medium known at a few wavelengths: ñ = n + ik at each (λ in nm strictly ascending), linear in
 * λ between them and constant beyond the first and the last (artistMetal.ts: a metal from three
 * channels).
 */
export interface SampledIndex {
  readonly sampled: readonly (readonly [lambdaNm: number, n: number, k: number])[];
}

export const isSampledIndex = (m: unknown): m is SampledIndex => typeof m === 'object' && m !== null && 'sampled' in m;

/** ñ at λ in nm. */
export function sampledIndexAt({ sampled }: SampledIndex, lambdaNm: number): Complex {
  const last = sampled.length - 1;
  let i = 0;
  while (i < last - 1 && lambdaNm > sampled[i + 1]![0]) i++;
  const [l0, n0, k0] = sampled[i]!;
  const [l1, n1, k1] = sampled[Math.min(i + 1, last)]!;
  const t = l1 === l0 ? 0 : Math.min(1, Math.max(0, (lambdaNm - l0) / (l1 - l0)));
  return { re: n0 + t * (n1 - n0), im: k0 + t * (k1 - k0) };
}
