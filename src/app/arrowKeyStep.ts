/** Shift makes an arrow key's step this many times longer. */
const SHIFT_FACTOR = 5;

const ARROWS: Readonly<Record<string, readonly [number, number]>> = {
  ArrowLeft: [-1, 0],
  ArrowRight: [1, 0],
  ArrowUp: [0, -1],
  ArrowDown: [0, 1],
};

/**
 * How far an arrow key moves a probe (x to the right, y down): `step` along its direction,
 * SHIFT_FACTOR times as far with Shift; null for any other key.
 */
export function arrowKeyStep(e: Pick<KeyboardEvent, 'key' | 'shiftKey'>, step: number): readonly [number, number] | null {
  const arrow = ARROWS[e.key];
  if (!arrow) return null;
  const length = step * (e.shiftKey ? SHIFT_FACTOR : 1);
  return [arrow[0] * length, arrow[1] * length];
}
