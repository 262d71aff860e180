/**
 * The Web Worker that computes dispersive films' row terms off the main thread
 * (dispersiveRowsStore.ts starts it): a message { key, input } (the input: the key, dispersiveRowsKey) is answered with
 * { key, texels }, the texels transferred, not copied.
 */
import { serveTexels } from '../threads/workerTexels.ts';
import { dispersiveRowsOfKey } from './dispersiveRows.ts';

serveTexels(dispersiveRowsOfKey);
