import { type EnvironmentPixels, loadEnvironmentPixels } from '../bubbleMaterials/environmentMaps.ts';
import { STAND_IN_ENVIRONMENT, isHdrEnvironment } from '../environments/environments.ts';
import type { FilmSettings } from '../settings/filmSettings.ts';
import { cpuBubbleImage } from '../bubbleTwins/cpuBubbleImage.ts';
import { environmentStatusText } from './environmentStatusText.ts';
import { type Catalogue, EN } from '../i18n/en.ts';

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

/** The settings and HDR map a still image shows: an HDR environment that fails to load gives way to the sky, and says so. */
async function withEnvironment(
  settings: FilmSettings,
  say: (text: string) => void,
  cat: Catalogue,
): Promise<[FilmSettings, EnvironmentPixels | null]> {
  const env = settings.env;
  if (!isHdrEnvironment(env)) return [settings, null];
  say(environmentStatusText({ state: 'loading', env }, cat));
  try {
    return [settings, await loadEnvironmentPixels(env)];
  } catch (error) {
    say(environmentStatusText({ state: 'failed', env, reason: error instanceof Error ? error.message : String(error) }, cat));
    return [{ ...settings, env: STAND_IN_ENVIRONMENT }, null];
  }
}

/**
 * Without WebGL2: puts a message and a still image of the bubble, computed on the CPU by
 * src/physics (cpuBubbleImage), where the WebGL canvas was; `done` is called once it is drawn.
 * Text goes in as textContent only.
 */
export function showCpuFallback(
  webglCanvas: HTMLCanvasElement,
  settings: FilmSettings,
  done: () => void = () => {},
  cat: Catalogue = EN,
): HTMLElement {
  const document = webglCanvas.ownerDocument;
  const figure = document.createElement('figure');
  figure.className = 'cpu-fallback';
  const caption = document.createElement('figcaption');
  caption.setAttribute('role', 'alert');
  caption.textContent = cat['app.cpuFallback'];
  const image = document.createElement('canvas');
  image.width = image.height = FALLBACK_IMAGE_PX;
  image.setAttribute('role', 'img');
  image.setAttribute('aria-label', cat['app.cpuImage']);
  const status = document.createElement('p');
  status.className = 'environment-status';
  figure.append(caption, image);
  webglCanvas.replaceWith(figure);
  const say = (text: string) => {
    status.textContent = text;
    if (!status.isConnected) caption.after(status);
  };
  // The image takes about a second: let the message show first.
  void withEnvironment(settings, say, cat).then(([shown, map]) =>
    setTimeout(() => {
      const pixels = cpuBubbleImage(shown, FALLBACK_IMAGE_PX, FALLBACK_IMAGE_PX, map);
      image.getContext('2d')?.putImageData(new ImageData(pixels, FALLBACK_IMAGE_PX, FALLBACK_IMAGE_PX), 0, 0);
      if (shown === settings) status.remove();
      done();
    }),
  );
  return figure;
}
