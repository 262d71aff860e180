import { lazyModule } from './lazyModule.ts';

/** The film's drawing (materialDrawing.ts): the shader, the table and the data they are computed from. */
export type MaterialDrawing = typeof import('./materialDrawing.ts');

/**
 * The film's drawing, a chunk of its own in a user's build, fetched the first time a material is
 * made spectral, so that an app's start loads only what checks the options. Until it is here, a
 * spectral material is drawn with three's film (whenSpectralReady waits for it).
 */
const drawing = lazyModule<MaterialDrawing>(() => import('./materialDrawing.ts'));

/** Loads the film's drawing, once. */
export const loadDrawing = drawing.load;

/** The film's drawing where it is loaded, else null. */
export const loadedDrawing = drawing.loaded;
