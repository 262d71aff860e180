/**
 * The cube-sphere's fields as textures (shaders/gpuFilmDynamics/flowAtlas.glsl is the twin): the six faces
 * side by side, FACES_ACROSS across and FACES_DOWN down. A cell field is a cell atlas (faces of
 * n × n texels), a padded field (one ring of ghosts, cubeSphereSampler.ts) a padded atlas (faces
 * of (n + 2)²), an edge field an edge atlas of 6n × 2n texels, edge e at (e mod 6n, e div 6n): the
 * 12n² edges exactly. docs/flow.md#the-gpu-port.
 */
export const FACES_ACROSS = 3;
export const FACES_DOWN = 2;

export interface AtlasSize {
  readonly width: number;
  readonly height: number;
}

/** An atlas of faces of side × side texels. */
export const faceAtlasSize = (side: number): AtlasSize => ({ width: FACES_ACROSS * side, height: FACES_DOWN * side });
export const edgeAtlasSize = (n: number): AtlasSize => ({ width: 2 * FACES_ACROSS * n, height: FACES_DOWN * n });

/** The texel index (row-major) of (i, j) on `face` in an atlas of faces of side × side. */
export function faceTexelIndex(side: number, face: number, i: number, j: number): number {
  const x = (face % FACES_ACROSS) * side + i;
  const y = Math.floor(face / FACES_ACROSS) * side + j;
  return y * FACES_ACROSS * side + x;
}

/** The cell atlas's texel index of cell c = (face·n + j)·n + i. */
export const cellTexelIndex = (n: number, c: number): number => faceTexelIndex(n, Math.floor(c / (n * n)), c % n, Math.floor(c / n) % n);

/** The padded atlas's texel index of padded index p = (face·m + j)·m + i, m = n + 2. */
export const paddedTexelIndex = (n: number, p: number): number => cellTexelIndex(n + 2, p);
