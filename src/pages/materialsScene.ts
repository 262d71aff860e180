import {
  type BufferGeometry,
  Color,
  CylinderGeometry,
  DataTexture,
  DoubleSide,
  Group,
  LatheGeometry,
  Mesh,
  MeshPhysicalMaterial,
  type MeshPhysicalMaterialParameters,
  PerspectiveCamera,
  Scene,
  SphereGeometry,
  TorusKnotGeometry,
  Vector2,
} from 'three';
import { spectralIridescence } from '../meshMaterial/spectralIridescence.ts';
import { type SpectralIridescenceOptions } from '../meshMaterial/spectralIridescenceOptions.ts';
import { XYZ_TO_LINEAR_SRGB, applyMatrix3 } from '../physics/colorConversions.ts';
import { type NamedMedium } from '../physics/namedMedia.ts';
import { transparentIndexAt } from '../physics/medium.ts';
import { filmXyz } from '../physics/spectralIntegration.ts';
import { STACK_PRESETS } from '../physics/stackPresets.ts';
import { SODIUM_D_NM } from '../film/filmMedia.ts';
import { SWATCH_STACKS } from './stackSwatches.ts';

/** What makes a physical material spectral: the WebGL entry's spectralIridescence, or the WebGPU entry's (materials.html?renderer=webgpu). */
export type Upgrade = (m: MeshPhysicalMaterial, options?: SpectralIridescenceOptions) => MeshPhysicalMaterial;

/** Which iridescence each side shows: three.js's on the left and ours on the right, or one of them on both. */
export const VIEWS = ['side by side', 'three.js', 'spectral'] as const;
export type View = (typeof VIEWS)[number];

/** A thickness map: the glTF convention's green channel running 0 → 1 along u (min → max thickness), a little wavy along v. */
function thicknessMap(): DataTexture {
  const size = 64;
  const data = new Uint8Array(4 * size * size);
  for (let y = 0; y < size; y++)
    for (let x = 0; x < size; x++) {
      const g = Math.min(1, Math.max(0, x / (size - 1) + 0.08 * Math.sin((2 * Math.PI * y) / size)));
      data.set([0, Math.round(255 * g), 0, 255], 4 * (y * size + x));
    }
  const t = new DataTexture(data, size, size);
  t.needsUpdate = true;
  return t;
}

/** The shapes, none a sphere: a torus knot, a parabolic dish, and a lamp (shade, stem, foot) of lathes and cylinders. */
function shapes(): { name: string; parts: { geometry: BufferGeometry; y: number }[]; x: number; y: number }[] {
  const dish = new LatheGeometry(
    Array.from({ length: 24 }, (_, i) => new Vector2(0.62 * (i / 23), 0.45 * (i / 23) ** 2)),
    64,
  );
  const shade = new LatheGeometry([new Vector2(0.38, 0), new Vector2(0.3, 0.12), new Vector2(0.16, 0.34), new Vector2(0.1, 0.38)], 64);
  return [
    { name: 'torus knot', parts: [{ geometry: new TorusKnotGeometry(0.36, 0.12, 200, 28), y: 0 }], x: 0, y: 0.72 },
    { name: 'dish', parts: [{ geometry: dish, y: 0 }], x: -0.48, y: -0.72 },
    {
      name: 'lamp',
      parts: [
        { geometry: shade, y: 0.22 },
        { geometry: new CylinderGeometry(0.025, 0.025, 0.6, 16), y: -0.08 },
        { geometry: new CylinderGeometry(0.2, 0.22, 0.05, 48), y: -0.38 },
      ],
      x: 0.5,
      y: -0.62,
    },
  ];
}

/** The film both sides share: the glTF iridescence parameters as three.js maps them, over a dark glossy dielectric. */
export const FILM: MeshPhysicalMaterialParameters = {
  color: 0x000000,
  roughness: 0.12,
  metalness: 0,
  ior: 1.5,
  iridescence: 1,
  iridescenceIOR: 1.8,
  iridescenceThicknessMinimum: 100,
  iridescenceThicknessMaximum: 800,
  side: DoubleSide,
};

/**
 * The films on metals, in a row between the torus knots, each a coin: a named film on a named metal, its
 * thickness in nm across the coin by the thickness map (minimum → maximum), or one thickness set
 * by the page's slider (anodized titanium, `TITANIUM_OXIDE_NM`).
 */
export const METALS = [
  // A protective silica overcoat on a gold mirror: gold's yellow, shifted gently as the coat thickens.
  { name: 'gold', film: 'SiO2', base: 'Au', thicknessNm: { min: 80, max: 320 } },
  // Anodized titanium: the oxide's thickness (and so the anodizing voltage) is the slider's.
  { name: 'anodized titanium', film: 'TiO2', base: 'Ti', thicknessNm: null },
  // Temper colours: a magnetite film on iron, 15–65 nm across the coin: straw, brown, purple, blue.
  { name: 'tempered steel', film: 'Fe3O4', base: 'Fe', thicknessNm: { min: 15, max: 65 } },
] as const satisfies readonly { name: string; film: NamedMedium; base: NamedMedium; thicknessNm: { min: number; max: number } | null }[];

/** The anodized titanium's oxide thickness (nm): the slider's range and first value (a blue at 60 nm). */
export const TITANIUM_OXIDE_NM = { min: 10, max: 250, initial: 60 } as const;

/** linear sRGB of a bare metal at normal incidence under D65, each in [0, 1]: three.js's metal takes it as its colour (F0). */
function bareColor(base: NamedMedium): Color {
  const rgb = applyMatrix3(XYZ_TO_LINEAR_SRGB, filmXyz({ nOutside: 1, nFilm: 1, nInside: base, thicknessNm: 0, angleDeg: 0 }));
  return new Color(...rgb.map((v) => Math.min(1, Math.max(0, v))));
}

/** A one-texel thickness map of green 0: the thickness is the material's minimum while the table spans to its maximum. */
function minimumThicknessMap(): DataTexture {
  const t = new DataTexture(new Uint8Array([0, 0, 0, 255]), 1, 1);
  t.needsUpdate = true;
  return t;
}

/** Each metal twice: three.js's film over a metal of the bare metal's colour, and the spectral film on the named metal. */
function metalMaterials(map: DataTexture, fixed: DataTexture, upgrade: Upgrade) {
  return METALS.map((m) => {
    const range = m.thicknessNm ?? { min: TITANIUM_OXIDE_NM.initial, max: TITANIUM_OXIDE_NM.max };
    const film: MeshPhysicalMaterialParameters = {
      roughness: 0.15,
      iridescence: 1,
      iridescenceThicknessMinimum: range.min,
      iridescenceThicknessMaximum: range.max,
      iridescenceThicknessMap: m.thicknessNm ? map : fixed,
    };
    const threes = new MeshPhysicalMaterial({
      ...film,
      color: bareColor(m.base),
      metalness: 1,
      iridescenceIOR: transparentIndexAt(m.film, SODIUM_D_NM),
    });
    // The metal is opaque: black and non-metal, the film over it is all the coin reflects.
    const ours = upgrade(new MeshPhysicalMaterial({ ...film, color: 0x000000, metalness: 0 }), { film: m.film, base: m.base });
    return { threes, ours };
  });
}

type Triple = readonly [number, number, number];

/**
 * The stacks of films, in a column between the knots below the coins: each a named object of the
 * spectral material with the preset's films as its option `layers` over its inside (`base`). A coated lens is a
 * flattened sphere, a lens's front element seen in its dark barrel; nacre lines the inside of a
 * shell, a half sphere open to the camera. three.js's iridescence has no stack of films: they are
 * spectral in every view.
 */
const STACK_OBJECTS: Readonly<
  Record<(typeof SWATCH_STACKS)[number], { name: string; shape: () => SphereGeometry; y: number; rotation: Triple; scale: Triple }>
> = {
  arCoating: { name: 'coated lens', shape: () => new SphereGeometry(0.26, 64, 32), y: 0.32, rotation: [0.2, -0.55, 0], scale: [1, 1, 0.3] },
  nacre: {
    name: 'nacre shell',
    shape: () => new SphereGeometry(0.3, 64, 24, 0, 2 * Math.PI, 0, Math.PI / 2),
    y: -0.72,
    rotation: [-Math.PI + 0.85, 0, 0.3],
    scale: [1.15, 0.45, 0.85],
  },
};

/** Each stack's object: a black glossy surface whose reflection is all the stack's. */
function stackMeshes(upgrade: Upgrade): Mesh<SphereGeometry, MeshPhysicalMaterial>[] {
  return SWATCH_STACKS.map((preset) => {
    const { films, nInside } = STACK_PRESETS[preset];
    const o = STACK_OBJECTS[preset];
    const surface = new MeshPhysicalMaterial({ color: 0x000000, roughness: 0.08, metalness: 0, iridescence: 1, side: DoubleSide });
    const mesh = new Mesh(o.shape(), upgrade(surface, { layers: films, base: nInside }));
    mesh.name = o.name;
    mesh.position.set(0, o.y, 0.5);
    mesh.rotation.set(...o.rotation);
    mesh.scale.set(...o.scale);
    return mesh;
  });
}

export interface ExampleScene {
  readonly scene: Scene;
  readonly camera: PerspectiveCamera;
  /** Shows `view` (the materials each side uses; the metals' row shows the spectral film unless the view is three.js's). */
  show(view: View): void;
  /** Sets the anodized titanium's oxide thickness (nm, within TITANIUM_OXIDE_NM). */
  setTitaniumOxideNm(thicknessNm: number): void;
  dispose(): void;
}

/**
 * The example scene: the three shapes twice, left and right of the centre, one material each
 * for three.js's iridescence and for the spectral film, with the same parameters; between them
 * the films on metals (METALS) and the stacks of films (STACK_OBJECTS), made spectral by `upgrade`.
 */
export function exampleScene(aspect: number, upgrade: Upgrade = spectralIridescence): ExampleScene {
  const map = thicknessMap();
  const threes = new MeshPhysicalMaterial({ ...FILM, iridescenceThicknessMap: map });
  const ours = upgrade(new MeshPhysicalMaterial({ ...FILM, iridescenceThicknessMap: map }));
  const scene = new Scene();
  const sides = [-1.15, 1.15].map((x) => {
    const side = new Group();
    side.position.x = x;
    for (const s of shapes()) {
      for (const p of s.parts) {
        const mesh = new Mesh(p.geometry, threes);
        mesh.position.set(s.x, s.y + p.y, 0);
        mesh.name = s.name;
        side.add(mesh);
      }
    }
    scene.add(side);
    return side;
  });
  sides[0]!.rotation.set(0.35, 0.4, 0);
  sides[1]!.rotation.set(0.35, 0.4, 0);
  const fixed = minimumThicknessMap();
  const metals = metalMaterials(map, fixed, upgrade);
  const coin = new CylinderGeometry(0.17, 0.17, 0.035, 64);
  const coins = METALS.map((m, i) => {
    const mesh = new Mesh<CylinderGeometry, MeshPhysicalMaterial>(coin, metals[i]!.ours);
    mesh.name = m.name;
    mesh.position.set(0.42 * (i - 1), 1.3, 0.4);
    mesh.rotation.set(Math.PI / 2 - 0.2, 0, 0.3);
    scene.add(mesh);
    return mesh;
  });
  const stacks = stackMeshes(upgrade);
  scene.add(...stacks);
  const camera = new PerspectiveCamera(38, aspect, 0.1, 50);
  camera.position.set(0, 0.25, 5.2);
  camera.lookAt(0, 0, 0);
  const set = (side: Group, m: MeshPhysicalMaterial) => side.traverse((o) => o instanceof Mesh && (o.material = m));
  return {
    scene,
    camera,
    show(view) {
      set(sides[0]!, view === 'spectral' ? ours : threes);
      set(sides[1]!, view === 'three.js' ? threes : ours);
      coins.forEach((c, i) => (c.material = view === 'three.js' ? metals[i]!.threes : metals[i]!.ours));
    },
    setTitaniumOxideNm(thicknessNm) {
      const titanium = metals[METALS.findIndex((m) => m.thicknessNm === null)]!;
      for (const m of [titanium.threes, titanium.ours]) m.iridescenceThicknessMinimum = thicknessNm;
    },
    dispose() {
      scene.traverse((o) => o instanceof Mesh && (o.geometry as BufferGeometry).dispose());
      for (const m of [threes, ours, ...metals.flatMap((m) => [m.threes, m.ours]), ...stacks.map((s) => s.material)]) m.dispose();
      map.dispose();
      fixed.dispose();
    },
  };
}
