/**
 * What the node figures (nodeFigures.ts) draw on three.js's WebGPURenderer, named once for the page
 * (page/nodeBench.ts) and the Markdown: the backends, the sphere's materials, and the option
 * changes of a spectral node material whose long tasks are counted.
 */
import type { SpectralIridescenceOptions } from '../../src/packageEntries/webgpu.ts';

/** WebGPURenderer's backends: WebGL2 (`forceWebGL`, in the ordinary launch) and WebGPU (in a launch of its own, scripts/chromium.ts). */
export const NODE_BACKENDS = ['webgl', 'webgpu'] as const;
export type NodeBackend = (typeof NODE_BACKENDS)[number];
export const NODE_BACKEND_LABELS: Readonly<Record<NodeBackend, string>> = { webgl: 'WebGL2 backend', webgpu: 'WebGPU backend' };

/** The sphere's materials, the floor first: each a MeshPhysicalNodeMaterial with the same film parameters (page/nodeScene.ts). */
export const NODE_MATERIALS = {
  floor: { spectral: false, label: 'the floor: the same MeshPhysicalNodeMaterial, iridescence 0' },
  'three.js': { spectral: false, label: "three.js's node iridescence (iridescence 1)" },
  table: { spectral: true, label: 'spectral `table` (default)' },
  exact: { spectral: true, label: 'spectral `exact`' },
} as const;
export type NodeMaterialName = keyof typeof NODE_MATERIALS;
export const NODE_MATERIAL_NAMES = Object.keys(NODE_MATERIALS) as NodeMaterialName[];

/** The modes whose film the error grids measure (scripts/harness/nodeFilmProbe.ts). */
export const NODE_GRID_MODES = ['table', 'exact'] as const;

/** A spectral node material's option changes, made one after another on the `table` sphere: [what, the change]. */
export const NODE_OPTION_CHANGES: readonly (readonly [string, SpectralIridescenceOptions])[] = [
  ['light D65 → D93', { illuminant: 'D93' }],
  ['polarisation unpolarised → s', { polarization: 's' }],
  ['mode table → exact', { mode: 'exact' }],
  ['mode exact → table', { mode: 'table' }],
  ['film medium iridescenceIOR 1.33 → water', { film: 'water' }],
];

/** The page's performance marks around option change `i`: made, and its frame drawn (nodeFigures.ts reads the tasks between them from a trace). */
export const changeMarks = (i: number): readonly [string, string] => [`option change ${i}`, `option change ${i} drawn`];
