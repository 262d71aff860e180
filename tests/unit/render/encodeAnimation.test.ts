import { PNG } from 'pngjs';
import sharp from 'sharp';
import UPNG from 'upng-js';
import { describe, expect, it } from 'vitest';
import { encodeAnimation } from '../../../scripts/render/encodeAnimation.ts';

/** A frame of `width`×`height` whose every byte is set from its index and `seed` (no two frames alike, every channel and alpha varied). */
function frame(width: number, height: number, seed: number): { png: Buffer; rgba: Uint8Array } {
  const png = new PNG({ width, height });
  for (let i = 0; i < png.data.length; i++) png.data[i] = (i * 7 + seed * 31 + ((i >> 2) % width) * 3) & 0xff;
  // Opaque pixels only where WebP must keep colour exactly: a transparent pixel's colour may be dropped.
  for (let i = 3; i < png.data.length; i += 4) png.data[i] = 255;
  return { png: PNG.sync.write(png), rgba: Uint8Array.from(png.data) };
}

const FRAMES = [0, 1, 2].map((seed) => frame(40, 30, seed));

/** Both encoders decoded by a reader of their own format: every frame its input exactly (lossless), in order, each shown frameMs. */
describe('encodeAnimation', () => {
  it('writes an APNG whose frames are the input frames, each shown frameMs', async () => {
    const { file, width, height } = await encodeAnimation(
      FRAMES.map((f) => f.png),
      250,
      'apng',
    );
    expect([width, height]).toEqual([40, 30]);
    const apng = UPNG.decode(Uint8Array.from(file).buffer);
    expect([apng.width, apng.height, apng.frames.map((f) => f.delay)]).toEqual([40, 30, [250, 250, 250]]);
    const decoded = UPNG.toRGBA8(apng).map((f) => new Uint8Array(f));
    decoded.forEach((rgba, i) => expect(Buffer.compare(Buffer.from(rgba), Buffer.from(FRAMES[i]!.rgba)), `frame ${i}`).toBe(0));
  });

  it('writes a lossless animated WebP whose frames are the input frames, each shown frameMs', async () => {
    const { file } = await encodeAnimation(
      FRAMES.map((f) => f.png),
      100,
      'webp',
    );
    const meta = await sharp(file, { pages: -1 }).metadata();
    expect([meta.format, meta.pages, meta.delay, meta.loop]).toEqual(['webp', 3, [100, 100, 100], 0]);
    const webp = await sharp(file, { pages: -1 }).ensureAlpha().raw().toBuffer();
    const bytes = 40 * 30 * 4;
    FRAMES.forEach((f, i) => expect(Buffer.compare(webp.subarray(i * bytes, (i + 1) * bytes), Buffer.from(f.rgba)), `frame ${i}`).toBe(0));
  });

  it('refuses frames of different sizes and no frames at all', async () => {
    await expect(encodeAnimation([FRAMES[0]!.png, frame(30, 40, 0).png], 100, 'apng')).rejects.toThrow('the frames differ in size');
    await expect(encodeAnimation([], 100, 'webp')).rejects.toThrow('at least one frame');
  });
});
