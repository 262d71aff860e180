/**
 * The example page (materials.html): three.js's iridescence and the spectral film side by side on
 * meshes that are not spheres, under an HDR environment; a view toggle; the ΔE00 between the two
 * at the probed pixel (the scene drawn once with each material, the pixel read back from each);
 * and two stacks of films in the scene, a coated lens and a nacre shell, named with the
 * reference's colours at two angles, in the page's language.
 */
import { arrowKeyStep } from '../app/arrowKeyStep.ts';
import { shownPixelRatio } from '../settings/pixelRatio.ts';
import { AgXToneMapping, EquirectangularReflectionMapping, type Mesh, Vector3 } from 'three';
import { isSpectralIridescence } from '../meshMaterial/spectralFilm.ts';
import { materialsUnder } from '../meshMaterial/materialsUnder.ts';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { environmentTexture, loadEnvironmentPixels } from '../bubbleMaterials/environmentMaps.ts';
import { TITANIUM_OXIDE_NM, VIEWS, type View, exampleScene } from './materialsScene.ts';
import { anodizingText } from './anodizingVoltage.ts';
import { type PageRenderer, pageRenderer } from './materialsRenderer.ts';
import { pixelDeltaE00 } from '../physics/pixelDeltaE.ts';
import { catalogueFor, message } from '../i18n/messages.ts';
import { SWATCH_ANGLES_DEG, SWATCH_STACKS, coatedLensPercent, stackSwatchRgb8 } from './stackSwatches.ts';

const element = <T extends HTMLElement>(selector: string): T => {
  const e = document.querySelector<T>(selector);
  if (!e) throw new Error(`materials.html must hold ${selector}`);
  return e;
};
const canvas = element<HTMLCanvasElement>('#scene');
const select = element<HTMLSelectElement>('#view');
const readout = element<HTMLParagraphElement>('#readout');
const mark = element<HTMLDivElement>('#probe-mark');
const titanium = element<HTMLInputElement>('#titanium');
const titaniumValue = element<HTMLOutputElement>('#titanium-value');
const stacks = element<HTMLDivElement>('#stacks');

const page: PageRenderer = await pageRenderer(canvas);
const renderer = page.renderer;
renderer.setPixelRatio(shownPixelRatio());
renderer.toneMapping = AgXToneMapping;
renderer.toneMappingExposure = 1.6;
const example = exampleScene(innerWidth / innerHeight, page.upgrade);
const controls = new OrbitControls(example.camera, canvas);
let view: View = 'side by side';
/** The probe in CSS pixels from the canvas's top left (null: the right torus knot's first vertex, once drawn). */
let probe: { x: number; y: number } | null = null;
let frames = 0;

for (const v of VIEWS) select.append(new Option(v, v));
Object.assign(titanium, { min: String(TITANIUM_OXIDE_NM.min), max: String(TITANIUM_OXIDE_NM.max), step: '1' });
titanium.value = String(TITANIUM_OXIDE_NM.initial);

/** Gives the anodized titanium the slider's oxide thickness, and the slider's text (the voltage that grows it). */
function setTitanium(): void {
  const text = anodizingText(Number(titanium.value));
  titaniumValue.textContent = text;
  titanium.setAttribute('aria-valuetext', text);
  example.setTitaniumOxideNm(Number(titanium.value));
}
setTitanium();

/** The scene's coated lens and nacre shell: each a swatch per angle (SWATCH_ANGLES_DEG) and its name, in the page's language. */
function showStacks(): void {
  const cat = catalogueFor(document.documentElement.lang);
  const { coated, bare } = coatedLensPercent();
  const names = {
    arCoating: message(cat, 'materials.coatedLens', { coated: coated.toFixed(2), bare: bare.toFixed(2) }),
    nacre: cat['materials.nacre'],
  };
  const rows = SWATCH_STACKS.map((name) => {
    const row = document.createElement('p');
    for (const angle of SWATCH_ANGLES_DEG) {
      const rgb8 = stackSwatchRgb8(name, angle);
      const s = swatch(rgb8);
      s.title = `${angle}° ${hex(rgb8)}`;
      row.append(s, ' ');
    }
    row.append(names[name]);
    return row;
  });
  stacks.replaceChildren(Object.assign(document.createElement('p'), { textContent: cat['materials.stacks'] }), ...rows);
}

function resize(): void {
  renderer.setSize(innerWidth, innerHeight, false);
  example.camera.aspect = innerWidth / innerHeight;
  example.camera.updateProjectionMatrix();
}

/** Draws `v` (default: the chosen view) and returns the 8-bit pixel at the probe, read at once. */
function draw(v: View = view): number[] {
  example.show(v);
  renderer.render(example.scene, example.camera);
  frames++;
  document.body.dataset.frames = String(frames);
  const p = probe ?? { x: 0, y: 0 };
  return readPixel(p.x, p.y);
}

/** The 8-bit pixel drawn at (x, y) CSS pixels from the canvas's top left, read at once (none on WebGPU). */
function readPixel(x: number, y: number): number[] {
  const r = renderer.getPixelRatio();
  return page.readPixel(Math.round(x * r), canvas.height - 1 - Math.round(y * r)) ?? [];
}

const hex = (p: readonly number[]) => `#${p.map((v) => v.toString(16).padStart(2, '0')).join('')}`;

/** Shows the two materials' pixels at the probe and their ΔE00, then the chosen view. */
function update(): void {
  if (!probe) {
    // The right knot's vertex nearest the camera: on the knot, facing the view.
    const knot = example.scene.getObjectsByProperty('name', 'torus knot')[1] as Mesh;
    const positions = knot.geometry.getAttribute('position');
    const v = new Vector3();
    let nearest = new Vector3(0, 0, -Infinity);
    for (let i = 0; i < positions.count; i++) {
      knot.localToWorld(v.fromBufferAttribute(positions, i));
      if (v.z > nearest.z) nearest = v.clone();
    }
    const point = nearest.project(example.camera);
    probe = { x: ((point.x + 1) / 2) * canvas.clientWidth, y: ((1 - point.y) / 2) * canvas.clientHeight };
  }
  const threes = draw('three.js');
  const ours = draw('spectral');
  draw();
  mark.style.left = `${probe.x}px`;
  mark.style.top = `${probe.y}px`;
  if (threes.length === 0) return void (readout.textContent = `${page.name}: the probe reads pixels on WebGLRenderer only.`);
  readout.replaceChildren(
    `At the probe: three.js `,
    swatch(threes),
    ` ${hex(threes)}, spectral `,
    swatch(ours),
    ` ${hex(ours)}; ΔE00 ${pixelDeltaE00(threes, ours).toFixed(1)}`,
  );
}

function swatch(p: readonly number[]): HTMLSpanElement {
  const s = document.createElement('span');
  s.className = 'swatch';
  s.style.background = hex(p);
  return s;
}

/** An arrow key moves the probe this many CSS pixels (with Shift, five times as far). */
const PROBE_STEP_PX = 10;
canvas.addEventListener('keydown', (e) => {
  const move = arrowKeyStep(e, PROBE_STEP_PX);
  if (!move || !probe) return;
  e.preventDefault();
  const clamp = (v: number, max: number) => Math.min(max, Math.max(0, v));
  probe = { x: clamp(probe.x + move[0], canvas.clientWidth - 1), y: clamp(probe.y + move[1], canvas.clientHeight - 1) };
  update();
});

titanium.addEventListener('input', () => {
  setTitanium();
  draw();
});
select.addEventListener('change', () => {
  view = select.value as View;
  draw();
});
controls.addEventListener('change', () => draw());
canvas.addEventListener('click', (e) => {
  const box = canvas.getBoundingClientRect();
  probe = { x: e.clientX - box.left, y: e.clientY - box.top };
  update();
});
addEventListener('resize', () => {
  resize();
  update();
});

showStacks();
resize();
Promise.all([loadEnvironmentPixels('park'), ...materialsUnder(example.scene, isSpectralIridescence).map(page.whenReady)]).then(
  () => {
    const texture = environmentTexture('park', example)!;
    texture.mapping = EquirectangularReflectionMapping;
    example.scene.environment = texture;
    example.scene.background = texture;
    update();
  },
  (e: unknown) => {
    readout.textContent = `The environment could not be loaded: ${String(e)}`;
  },
);

/** The 8-bit pixel at the centre of a named mesh (a metal's coin), as last drawn. */
function pixelOf(name: string): number[] {
  const point = example.scene.getObjectByName(name)!.getWorldPosition(new Vector3()).project(example.camera);
  return readPixel(((point.x + 1) / 2) * canvas.clientWidth, ((1 - point.y) / 2) * canvas.clientHeight);
}

/** For the benchmark and the tests: the example scene, a way to draw one view, a named mesh's pixel. */
window.materialsPage = { renderer, draw: (v: View) => draw(v), pixelOf };

declare global {
  interface Window {
    materialsPage?: { renderer: PageRenderer['renderer']; draw(view: View): number[]; pixelOf(name: string): number[] };
  }
}
