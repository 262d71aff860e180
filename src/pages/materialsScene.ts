import {
  type BufferGeometry,
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
  TorusKnotGeometry,
  Vector2,
} from 'three';
import { spectralIridescence } from '../material/spectralIridescence.ts';

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

export interface ExampleScene {
  readonly scene: Scene;
  readonly camera: PerspectiveCamera;
  /** Shows `view` (the materials each side uses). */
  show(view: View): void;
  dispose(): void;
}

/**
 * The example scene: the three shapes twice, left and right of the centre, one material each
 * for three.js's iridescence and for the spectral film, with the same parameters.
 */
export function exampleScene(aspect: number): ExampleScene {
  const map = thicknessMap();
  const threes = new MeshPhysicalMaterial({ ...FILM, iridescenceThicknessMap: map });
  const ours = spectralIridescence(new MeshPhysicalMaterial({ ...FILM, iridescenceThicknessMap: map }));
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
    },
    dispose() {
      scene.traverse((o) => o instanceof Mesh && (o.geometry as BufferGeometry).dispose());
      threes.dispose();
      ours.dispose();
      map.dispose();
    },
  };
}
