/**
 * Frames (PNG screenshots of one size) as one animated picture, each frame lossless so it decodes
 * to the pixels captured: an APNG by upng-js (cnum 0: every colour kept; sharp's libvips writes no
 * APNG), an animated WebP by sharp (libwebp, lossless).
 */
import { PNG } from 'pngjs';
import sharp from 'sharp';
import UPNG from 'upng-js';
import type { TimeLapseFormat } from '../../src/cli/timeLapseOptions.ts';

type Encoder = (pngs: readonly Buffer[], size: { width: number; height: number }, frameMs: number) => Promise<Buffer>;

const ENCODERS: Record<TimeLapseFormat, Encoder> = {
  apng: (pngs, { width, height }, frameMs) => {
    // Each frame's RGBA bytes as an ArrayBuffer of its own (pngjs's may be a view into a larger one).
    const rgba = pngs.map((png) => Uint8Array.from(PNG.sync.read(png).data).buffer);
    const delays = pngs.map(() => frameMs);
    return Promise.resolve(Buffer.from(UPNG.encode(rgba, width, height, 0, delays)));
  },
  webp: (pngs, _size, frameMs) =>
    sharp([...pngs], { join: { animated: true } })
      .webp({ lossless: true, loop: 0, delay: pngs.map(() => frameMs) })
      .toBuffer(),
};

/** The animation of `pngs` in order, each shown `frameMs`, looping forever; an Error if the frames differ in size. */
export async function encodeAnimation(
  pngs: readonly Buffer[],
  frameMs: number,
  format: TimeLapseFormat,
): Promise<{ file: Buffer; width: number; height: number }> {
  // Each PNG's size, from its IHDR chunk (its first, right after the 8-byte signature).
  const sizes = pngs.map((png) => ({ width: png.readUInt32BE(16), height: png.readUInt32BE(20) }));
  const [size] = sizes;
  if (!size) throw new Error('an animation has at least one frame');
  if (sizes.some((s) => s.width !== size.width || s.height !== size.height)) throw new Error('the frames differ in size');
  return { file: await ENCODERS[format](pngs, size, frameMs), ...size };
}
