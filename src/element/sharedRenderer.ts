import type { WebGLRenderer } from 'three';
import { createBubbleRenderer } from '../view/bubbleRenderer.ts';

let renderer: WebGLRenderer | null = null;
let users = 0;

/**
 * One WebGL renderer for every <thin-film-bubble> on a page: each element draws with it and
 * copies the frame to its own canvas, so shader programs are compiled and spectral textures
 * uploaded once per page, and a page of bubbles holds one WebGL context, not one each. (Each
 * view frees its own resources; the shared spectral textures go with their last user.)
 */
export function acquireSharedRenderer(): WebGLRenderer {
  renderer ??= createBubbleRenderer(document.createElement('canvas'));
  users++;
  return renderer;
}

/** Gives the renderer back; the last user's release frees it and its context. */
export function releaseSharedRenderer(): void {
  if (--users > 0 || !renderer) return;
  renderer.dispose();
  renderer.forceContextLoss();
  renderer = null;
}
