import type { FilmSettings } from '../render/filmSettings.ts';
import { cpuBubbleImage } from '../scene/cpuBubbleImage.ts';

/** The still image's size in pixels (square; shown scaled to fit). */
export const FALLBACK_IMAGE_PX = 240;

let webgl2: boolean | null = null;

/** Whether this browser gives a WebGL2 context (tried once per page on a canvas of its own, then released). */
export function hasWebGL2(): boolean {
  if (webgl2 === null) {
    const gl = document.createElement('canvas').getContext('webgl2');
    gl?.getExtension('WEBGL_lose_context')?.loseContext();
    webgl2 = gl !== null;
  }
  return webgl2;
}

/**
 * Without WebGL2: puts a message and a still image of the bubble, computed on the CPU by
 * src/physics (cpuBubbleImage), where the WebGL canvas was; `done` is called once it is drawn.
 * Text goes in as textContent only.
 */
export function showCpuFallback(webglCanvas: HTMLCanvasElement, settings: FilmSettings, done: () => void = () => {}): HTMLElement {
  const document = webglCanvas.ownerDocument;
  const figure = document.createElement('figure');
  figure.className = 'cpu-fallback';
  const caption = document.createElement('figcaption');
  caption.setAttribute('role', 'alert');
  caption.textContent =
    'This browser has no WebGL2, so the live bubble cannot run. Below is a still image of the same film, ' +
    'computed on the CPU from the same physics (no animation, sRGB).';
  const image = document.createElement('canvas');
  image.width = image.height = FALLBACK_IMAGE_PX;
  figure.append(caption, image);
  webglCanvas.replaceWith(figure);
  // The image takes about a second: let the message show first.
  setTimeout(() => {
    const pixels = cpuBubbleImage(settings, FALLBACK_IMAGE_PX, FALLBACK_IMAGE_PX);
    image.getContext('2d')?.putImageData(new ImageData(pixels, FALLBACK_IMAGE_PX, FALLBACK_IMAGE_PX), 0, 0);
    done();
  });
  return figure;
}
