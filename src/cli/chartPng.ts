import { PNG } from 'pngjs';
import { fonts, renderPixels } from 'js-pixel-fonts';
import type { ChartLayout } from './chartLayout.ts';

/** Ticks and labels are black on the white margins. */
const INK = [0, 0, 0] as const;
const PAPER = [255, 255, 255] as const;

/**
 * A chart as PNG bytes (8-bit RGBA, every pixel opaque): each cell filled with its srgb8 exactly,
 * the margins white, labels in the 7-px "Seven plus" pixel font of js-pixel-fonts.
 */
export function chartPng(layout: ChartLayout): Buffer {
  const png = new PNG({ width: layout.width, height: layout.height });
  const put = (x: number, y: number, [r, g, b]: readonly number[]) => {
    if (x < 0 || y < 0 || x >= layout.width || y >= layout.height) return;
    const at = (y * layout.width + x) * 4;
    png.data[at] = r ?? 0;
    png.data[at + 1] = g ?? 0;
    png.data[at + 2] = b ?? 0;
    png.data[at + 3] = 255;
  };
  for (let y = 0; y < layout.height; y++) for (let x = 0; x < layout.width; x++) put(x, y, PAPER);
  for (const c of layout.cells) {
    for (let y = c.y; y < c.y + c.height; y++) for (let x = c.x; x < c.x + c.width; x++) put(x, y, c.srgb8);
  }
  for (const t of layout.ticks) {
    for (let y = Math.floor(t.y1); y <= Math.floor(t.y2); y++) {
      for (let x = Math.floor(t.x1); x <= Math.floor(t.x2); x++) put(x, y, INK);
    }
  }
  for (const label of layout.labels) {
    const pixels = renderPixels(label.text, fonts.sevenPlus);
    const textWidth = Math.max(...pixels.map((row) => row.length));
    const left = label.anchor === 'middle' ? Math.round(label.x - textWidth / 2) : label.x;
    // Keep a label at the left edge whole rather than cut.
    const x0 = Math.max(0, Math.min(left, layout.width - textWidth));
    pixels.forEach((row, dy) => row.forEach((on, dx) => on && put(x0 + dx, Math.round(label.y) + dy, INK)));
  }
  return PNG.sync.write(png);
}
