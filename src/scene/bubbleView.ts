import {
  BackSide,
  ColorManagement,
  Mesh,
  PerspectiveCamera,
  Scene,
  ShaderMaterial,
  SphereGeometry,
  SRGBColorSpace,
  WebGLRenderer,
} from 'three';
import { DisplayP3ColorSpace, DisplayP3ColorSpaceImpl } from 'three/addons/math/ColorSpaces.js';
import { createBubbleMaterial, updateBubbleUniforms } from '../render/bubbleMaterial.ts';
import { DEFAULT_FILM_QUALITY, type FilmQuality } from '../render/filmQuality.ts';
import { FilmTable } from '../render/filmTable.ts';
import { type FilmSettings } from '../render/filmSettings.ts';
import { shaderSource } from '../render/shaderSource.ts';

ColorManagement.define({ [DisplayP3ColorSpace]: DisplayP3ColorSpaceImpl });

/** The camera sits on +z; the unit bubble (seen under 2·asin(1/4) = 29°) fills ~83 % of the 35° view's height. */
const CAMERA_DISTANCE = 4;
const FOV_DEG = 35;

/**
 * A bubble on a canvas: renderer, camera, environment, the film material and its table.
 * Renders on demand: `render()` draws one frame; the caller's loop runs only while animating.
 */
export class BubbleView {
  readonly renderer: WebGLRenderer;
  readonly camera = new PerspectiveCamera(FOV_DEG, 1, 0.1, 100);
  readonly scene = new Scene();
  readonly table: FilmTable;
  readonly bubble: Mesh<SphereGeometry, ShaderMaterial>;
  private readonly sky: Mesh<SphereGeometry, ShaderMaterial>;
  /** Whether the canvas really shows Display P3 (false where the browser cannot). */
  displayIsP3 = false;
  private settings: FilmSettings;

  constructor(
    canvas: HTMLCanvasElement,
    settings: FilmSettings,
    readonly quality: FilmQuality = DEFAULT_FILM_QUALITY,
  ) {
    this.renderer = new WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
    this.settings = settings;
    this.table = new FilmTable(quality);
    this.camera.position.set(0, 0, CAMERA_DISTANCE);
    this.bubble = new Mesh(new SphereGeometry(1, 128, 64), createBubbleMaterial(settings, quality));
    this.sky = new Mesh(
      new SphereGeometry(50, 32, 16),
      new ShaderMaterial({
        side: BackSide,
        defines: { ENVIRONMENT: 1 },
        vertexShader: 'varying vec3 vDirection; void main() { vDirection = position; gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0); }',
        fragmentShader: `${shaderSource('environment.glsl')}
varying vec3 vDirection;
void main() { gl_FragColor = vec4(environmentRadiance(vDirection), 1.0);
#include <colorspace_fragment>
}`,
      }),
    );
    this.scene.add(this.sky, this.bubble);
    this.apply(settings);
  }

  get current(): FilmSettings {
    return this.settings;
  }

  /** Takes new settings (already validated); rebuilds the table only if it depends on them. */
  apply(s: FilmSettings): void {
    this.settings = s;
    const wantP3 = s.space === 'display-p3' || s.space === 'wide-gamut';
    this.renderer.outputColorSpace = wantP3 ? DisplayP3ColorSpace : SRGBColorSpace;
    const gl = this.renderer.getContext();
    this.displayIsP3 = wantP3 && 'drawingBufferColorSpace' in gl && gl.drawingBufferColorSpace === 'display-p3';
    if (wantP3 && !this.displayIsP3) this.renderer.outputColorSpace = SRGBColorSpace;
    this.sky.visible = s.env === 'sky';
    if (s.mode === 'table') this.table.update(this.renderer, s);
    updateBubbleUniforms(this.bubble.material, s, this.quality, s.mode === 'table' ? this.table : null, this.displayIsP3);
  }

  /** Matches the drawing buffer to the canvas's CSS box. */
  resize(width: number, height: number, pixelRatio = 1): void {
    this.renderer.setPixelRatio(pixelRatio);
    this.renderer.setSize(width, height, false);
    this.camera.aspect = width / Math.max(1, height);
    this.camera.updateProjectionMatrix();
  }

  render(): void {
    this.renderer.render(this.scene, this.camera);
  }

  dispose(): void {
    this.table.dispose();
    this.bubble.geometry.dispose();
    this.bubble.material.dispose();
    this.sky.geometry.dispose();
    this.sky.material.dispose();
    this.renderer.dispose();
  }
}
