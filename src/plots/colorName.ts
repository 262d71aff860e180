/** The hues a colour is named by, around the sRGB hue circle from red. */
export const HUE_NAMES = ['red', 'orange', 'yellow', 'green', 'cyan', 'blue', 'purple', 'magenta'] as const;
export type HueName = (typeof HUE_NAMES)[number];

/** A colour's name: a hue or an achromatic name, and whether it is dark or light. */
export interface ColorName {
  readonly hue: HueName | 'black' | 'white' | 'grey';
  readonly tone: 'dark' | 'light' | null;
}

/** Where each hue begins on the HSV hue circle (degrees), in HUE_NAMES's order; red wraps around 360°. */
const HUE_STARTS_DEG = [345, 15, 45, 70, 160, 200, 255, 285] as const;
/** Below this saturation (max − min over max, of the sRGB-encoded channels) a colour is achromatic. */
const ACHROMATIC_SATURATION = 0.12;
/** Values (the largest encoded channel) that make black, dark, light and white. */
const BLACK_VALUE = 0.12;
const DARK_VALUE = 0.55;
const DARK_GREY_VALUE = 0.4;
const LIGHT_GREY_VALUE = 0.75;
const WHITE_VALUE = 0.92;
/** A colour this pale (saturation below it, value at least DARK_VALUE) is a light one. */
const PALE_SATURATION = 0.55;

/**
 * A short name for an 8-bit sRGB colour, from its HSV hue, saturation and value (on the encoded
 * channels, as a viewer sees them): achromatic colours are black, grey (dark or light) or white;
 * others are one of eight hues, dark at about half value and below, light when pale.
 */
export function colorName([r, g, b]: readonly [number, number, number]): ColorName {
  const max = Math.max(r, g, b) / 255;
  const min = Math.min(r, g, b) / 255;
  const saturation = max === 0 ? 0 : (max - min) / max;
  if (saturation < ACHROMATIC_SATURATION || max < BLACK_VALUE) {
    if (max < BLACK_VALUE) return { hue: 'black', tone: null };
    if (max > WHITE_VALUE) return { hue: 'white', tone: null };
    return { hue: 'grey', tone: max < DARK_GREY_VALUE ? 'dark' : max > LIGHT_GREY_VALUE ? 'light' : null };
  }
  const hueDeg = hsvHueDeg(r, g, b);
  // Red spans the wrap (from its start to 360°, and 0° to orange's start).
  const later = HUE_STARTS_DEG.filter((start, i) => i > 0 && hueDeg >= start).length;
  const hue = HUE_NAMES[hueDeg >= HUE_STARTS_DEG[0] ? 0 : later]!;
  return { hue, tone: max < DARK_VALUE ? 'dark' : saturation < PALE_SATURATION ? 'light' : null };
}

/** The HSV hue in [0, 360) of a colour that is not grey. */
function hsvHueDeg(r: number, g: number, b: number): number {
  const max = Math.max(r, g, b);
  const span = max - Math.min(r, g, b);
  const sector = max === r ? (g - b) / span : max === g ? 2 + (b - r) / span : 4 + (r - g) / span;
  return (sector * 60 + 360) % 360;
}
