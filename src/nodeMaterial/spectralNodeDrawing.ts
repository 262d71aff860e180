import { lazyModule } from '../meshMaterial/lazyModule.ts';

/** The WebGPU entry's drawing of the film (nodeDrawing.ts): its nodes, table, lighting model and data. */
export type NodeDrawing = typeof import('./nodeDrawing.ts');

/**
 * The film's drawing, a chunk of its own in a user's build, fetched the first time a material is
 * made spectral, so that an app's start loads only what checks the options. Until it is here, a
 * spectral material is drawn with three's film (whenSpectralReady waits for it).
 */
export const nodeDrawing = lazyModule<NodeDrawing>(() => import('./nodeDrawing.ts'));
