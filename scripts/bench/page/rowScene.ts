/** A benchmark row's scene: the demo's BubbleView with the row's settings and quality, and the plain textured sphere in the bubble's place for the floor rows. */
import { DataTexture, Mesh, MeshBasicMaterial, RGBAFormat, SRGBColorSpace, type WebGLRenderer } from 'three';
import { BubbleView } from '../../../src/view/bubbleView.ts';
import { resolveFrame } from '../../../src/view/drawnFrame.ts';
import type { FilmSettings } from '../../../src/settings/filmSettings.ts';
import { AUTO } from '../../../src/settings/parameterRow.ts';
import type { BenchRowSpec } from '../benchRow.ts';

/** A 256² sRGB texture for the floor row: the sphere then costs one texture fetch per pixel. */
function checkerTexture(): DataTexture {
  const size = 256;
  const data = new Uint8Array(4 * size * size);
  for (let i = 0; i < size * size; i++) {
    const v = (((i % size) >> 4) + ((i / size) >> 4)) % 2 ? 220 : 90;
    data.set([v, (v * 3) >> 2, 255 - v, 255], 4 * i);
  }
  const t = new DataTexture(data, size, size, RGBAFormat);
  t.colorSpace = SRGBColorSpace;
  t.needsUpdate = true;
  return t;
}

/**
 * Shows `film` in the view as a frozen app's frame would, but with the method asked for even where
 * the app draws another in its place (the bench times each method, `fourier`'s dispersive fallback included).
 */
export function showFilm(view: BubbleView, film: FilmSettings): void {
  const frame = resolveFrame(
    { ...film, animate: false, probe: [0.5, 0.5], pixelRatio: AUTO },
    { ...view.offers, choice: null, devicePixelRatio: 1 },
  );
  view.show({ ...frame, film: { ...frame.film, mode: film.mode } });
}

/** The row's view on `renderer`, and the textured sphere standing in for the bubble (the floor rows); `dispose` frees all of it. */
export function rowScene(renderer: WebGLRenderer, spec: BenchRowSpec): { view: BubbleView; dispose: () => void } {
  const view = new BubbleView(renderer, spec.quality);
  showFilm(view, spec.settings);
  if (!spec.reflections) {
    // The model before environment reflections: tfcReflectedRadiance (shaders/bubbleMaterials/environment.glsl) returns the light's white.
    const m = view.bubble.material;
    m.onBeforeCompile = (shader) => {
      const walls = /vec3 tfcReflectedRadiance\(vec3 direction\) \{/;
      if (!walls.test(shader.fragmentShader)) throw new Error('rowScene: the bubble shader has no tfcReflectedRadiance to make white');
      shader.fragmentShader = shader.fragmentShader.replace(walls, '$&\n  return vec3(1.0);');
    };
    m.customProgramCacheKey = () => 'walls reflect white';
  }
  const sphere = spec.kind === 'textured' ? new MeshBasicMaterial({ map: checkerTexture() }) : null;
  if (sphere) {
    view.bubble.visible = false;
    view.scene.add(new Mesh(view.bubble.geometry, sphere));
  }
  return {
    view,
    // The bubble's material goes with the view, and its onBeforeCompile with it.
    dispose: () => {
      view.dispose();
      sphere?.map?.dispose();
      sphere?.dispose();
    },
  };
}
