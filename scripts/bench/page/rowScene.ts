/** A benchmark row's scene: the demo's BubbleView with the row's settings and quality, and the plain textured sphere in the bubble's place for the floor rows. */
import {
  DataTexture,
  Mesh,
  MeshBasicMaterial,
  RGBAFormat,
  SRGBColorSpace,
  type ShaderMaterial,
  SphereGeometry,
  type WebGLRenderer,
} from 'three';
import {
  createBackgroundMaterial,
  environmentDefines,
  updateBackgroundMaterial,
} from '../../../src/bubbleMaterials/environmentMaterial.ts';
import { environmentKind } from '../../../src/environments/environments.ts';
import { BubbleView } from '../../../src/view/bubbleView.ts';
import { resolveFrame } from '../../../src/view/drawnFrame.ts';
import type { FilmSettings } from '../../../src/settings/filmSettings.ts';
import { AUTO } from '../../../src/settings/parameterRow.ts';
import type { BenchRowSpec, EarlierModel } from '../benchRow.ts';

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

/**
 * Draws the bubble by an earlier model of its light (BenchRowSpec.earlierModel), patched into its
 * program: `whiteWalls`, tfcReflectedRadiance (shaders/bubbleMaterials/environment.glsl) returns the
 * light's white; `rgbProduct`, in the sky, the film is shown as without an environment (one table
 * plane, its XYZ: the walls' RGB product) and its program gets the sky's TFC_ENVIRONMENT, with a sky
 * behind it as the view draws one. Returns the film the view is shown and what the model added to the scene.
 */
function earlierModel(
  view: BubbleView,
  model: EarlierModel,
  film: FilmSettings,
): { shown: (film: FilmSettings) => FilmSettings; added: Mesh<SphereGeometry, ShaderMaterial> | null } {
  const m = view.bubble.material;
  m.customProgramCacheKey = () => model;
  if (model === 'whiteWalls') {
    m.onBeforeCompile = (shader) => {
      const walls = /vec3 tfcReflectedRadiance\(vec3 direction\) \{/;
      if (!walls.test(shader.fragmentShader)) throw new Error('rowScene: the bubble shader has no tfcReflectedRadiance to make white');
      shader.fragmentShader = shader.fragmentShader.replace(walls, '$&\n  return vec3(1.0);');
    };
    return { shown: (f) => f, added: null };
  }
  if (environmentKind(film.env) !== 'sky') throw new Error('rowScene: the RGB product is drawn in the sky');
  const sky = { env: 'sky', envRotationDeg: 0, exposure: film.exposure } as const;
  m.onBeforeCompile = (shader) => {
    shader.defines = { ...shader.defines, ...environmentDefines(sky) };
  };
  const background = new Mesh(new SphereGeometry(50, 64, 32), createBackgroundMaterial());
  updateBackgroundMaterial(background.material, sky, null);
  view.scene.add(background);
  return { shown: (f) => ({ ...f, env: 'none' }), added: background };
}

/** A row's view, how a film is shown in it (showFilm, through the row's earlier model), and what frees all of it. */
export interface RowScene {
  readonly view: BubbleView;
  show(film: FilmSettings): void;
  dispose(): void;
}

/** The row's view on `renderer`, and the textured sphere standing in for the bubble (the floor rows). */
export function rowScene(renderer: WebGLRenderer, spec: Pick<BenchRowSpec, 'kind' | 'earlierModel' | 'settings' | 'quality'>): RowScene {
  const view = new BubbleView(renderer, spec.quality);
  const earlier = spec.earlierModel === null ? null : earlierModel(view, spec.earlierModel, spec.settings);
  const show = (film: FilmSettings) => showFilm(view, earlier ? earlier.shown(film) : film);
  show(spec.settings);
  if (spec.earlierModel === 'rgbProduct' && view.bubble.material.defines.TFC_ENVIRONMENT_MATRIX !== undefined)
    throw new Error('rowScene: the RGB product is drawn from one table plane');
  const sphere = spec.kind === 'textured' ? new MeshBasicMaterial({ map: checkerTexture() }) : null;
  if (sphere) {
    view.bubble.visible = false;
    view.scene.add(new Mesh(view.bubble.geometry, sphere));
  }
  return {
    view,
    show,
    // The bubble's material goes with the view, and its onBeforeCompile with it.
    dispose: () => {
      view.dispose();
      sphere?.map?.dispose();
      sphere?.dispose();
      earlier?.added?.geometry.dispose();
      earlier?.added?.material.dispose();
    },
  };
}
