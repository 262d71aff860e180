import type { Material, Object3D } from 'three';

/** The materials under `root` (a mesh's one or its several) that `picks` accepts, each once: the glTF upgrades' and the page's walk. */
export function materialsUnder<M extends Material>(root: Object3D, picks: (material: Material) => material is M): M[] {
  const found = new Set<M>();
  root.traverse((o) => {
    const m = (o as { material?: Material | Material[] }).material;
    for (const material of Array.isArray(m) ? m : m ? [m] : []) if (picks(material)) found.add(material);
  });
  return [...found];
}
