import { ColorManagement, SRGBColorSpace, type WebGLRenderer } from 'three';
import { DisplayP3ColorSpace, DisplayP3ColorSpaceImpl } from 'three/addons/math/ColorSpaces.js';

/** Whether each renderer's canvas can show Display P3, once asked. */
const displayP3Support = new WeakMap<WebGLRenderer, boolean>();

/** The space a view's drawing buffer takes: Display P3 (made known to three's colour management on first use) or sRGB. */
export function drawingBufferSpace(displayIsP3: boolean): string {
  if (!displayIsP3) return SRGBColorSpace;
  if (!ColorManagement.spaces[DisplayP3ColorSpace]) ColorManagement.define({ [DisplayP3ColorSpace]: DisplayP3ColorSpaceImpl });
  return DisplayP3ColorSpace;
}

/**
 * Whether `renderer`'s canvas can show Display P3: whether its drawing buffer takes the space
 * (browsers without the attribute, or that ignore the value, stay sRGB). Asked once per renderer,
 * as setting the space reallocates the drawing buffer.
 */
export function drawsDisplayP3(renderer: WebGLRenderer): boolean {
  let supported = displayP3Support.get(renderer);
  if (supported === undefined) {
    const gl = renderer.getContext();
    const space = renderer.outputColorSpace;
    renderer.outputColorSpace = drawingBufferSpace(true);
    supported = 'drawingBufferColorSpace' in gl && gl.drawingBufferColorSpace === 'display-p3';
    renderer.outputColorSpace = space;
    displayP3Support.set(renderer, supported);
  }
  return supported;
}
