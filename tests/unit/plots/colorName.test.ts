import { describe, expect, it } from 'vitest';
import { colorName } from '../../../src/plots/colorName.ts';

/** Anchors named by definition: the sRGB primaries and secondaries at full value, white, black, the greys between. */
const ANCHORS: [readonly [number, number, number], string][] = [
  [[255, 0, 0], 'red'],
  [[0, 255, 0], 'green'],
  [[0, 0, 255], 'blue'],
  [[255, 255, 0], 'yellow'],
  [[0, 255, 255], 'cyan'],
  [[255, 0, 255], 'magenta'],
  [[255, 255, 255], 'white'],
  [[0, 0, 0], 'black'],
  [[128, 128, 128], 'grey'],
  // Half the value of a primary is its dark shade; half-way to white its light (pale) tint.
  [[128, 0, 0], 'dark red'],
  [[0, 0, 128], 'dark blue'],
  [[255, 128, 128], 'light red'],
  [[128, 255, 255], 'light cyan'],
  // Hue half-way between red and yellow (30°), and between blue and magenta (270°).
  [[255, 128, 0], 'orange'],
  [[128, 0, 255], 'purple'],
  [[64, 64, 64], 'dark grey'],
  [[224, 224, 224], 'light grey'],
];

const text = (c: readonly [number, number, number]) => {
  const { hue, tone } = colorName(c);
  return tone ? `${tone} ${hue}` : hue;
};

describe('colorName', () => {
  it.each(ANCHORS)('names %j %s', (rgb, name) => expect(text(rgb)).toBe(name));

  it('names a colour the same at every value of its channels scaled together above the dark limit', () => {
    // Scaling all channels keeps the HSV hue and saturation: the same hue and tone from value 0.5 up.
    for (const k of [0.5, 0.75, 1]) expect(colorName([Math.round(255 * k), Math.round(51 * k), 0]).hue).toBe('red');
  });
});
