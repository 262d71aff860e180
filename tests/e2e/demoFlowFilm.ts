/**
 * The demo's flowing film read back as its bubble samples it: the texels of the padded film its
 * material's `uFlowFilm` holds (a render target's texture: three's `texture.renderTarget`), read
 * through the view's renderer, and decoded here into the float64 twin's cell order.
 */
import type { Texture, WebGLRenderTarget } from 'three';
import { paddedTexelIndex } from '../../src/gpuFilmDynamics/flowAtlas.ts';
import { FLOW_FILM } from '../../src/gpuFilmDynamics/flowTexels.ts';
import { texelFloat } from './harness/filmReadback.ts';

/** The demo's globals (src/pages/demo.ts). */
export type Demo = Window & {
  bubbleView: import('../../src/view/bubbleView.ts').BubbleView;
  bubbleApp: import('../../src/app/bubbleApp.ts').BubbleApp;
};
/** A page with the reader installFilmReader gives it. */
export type FilmReader = Window & { flowFilmTexels: () => number[] };

/**
 * Gives the page `flowFilmTexels`, the padded film's texels as the bubble samples them now. Runs in
 * the page (self-contained): pass it to `page.addInitScript` (every load) or `page.evaluate` (this one).
 */
export function installFilmReader(): void {
  (window as unknown as FilmReader).flowFilmTexels = () => {
    const view = (window as unknown as Demo).bubbleView;
    const texture = view.bubble.material.uniforms.uFlowFilm!.value as Texture & { renderTarget: WebGLRenderTarget };
    const target = texture.renderTarget;
    const texels = new Float32Array(4 * target.width * target.height);
    view.renderer.readRenderTargetPixels(target, 0, 0, target.width, target.height, texels);
    return [...texels];
  };
}

/** The padded film's texels (a FLOW_FILM per texel; one ring of ghosts round each face of n × n cells) as η and intact per cell, in the twin's cell order. */
export function paddedFilmCells(texels: ArrayLike<number>, n: number): { eta: Float32Array; intact: Uint8Array } {
  const [eta, intact] = [new Float32Array(6 * n * n), new Uint8Array(6 * n * n)];
  const m = n + 2;
  for (let c = 0; c < eta.length; c++) {
    const [face, j, i] = [Math.floor(c / (n * n)), Math.floor(c / n) % n, c % n];
    const t = paddedTexelIndex(n, (face * m + j + 1) * m + i + 1);
    [eta[c], intact[c]] = [texelFloat(FLOW_FILM, texels, t, 'ETA'), texelFloat(FLOW_FILM, texels, t, 'INTACT')];
  }
  return { eta, intact };
}
