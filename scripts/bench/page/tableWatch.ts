/**
 * What a benchmark row measures of its view's film table, through the table's public API (its
 * `update` wrapped on the instance): the full tables shown, and how long the first table built at
 * once took, from the update's start until a pixel of the table is read back (the GPU done with
 * it, the pass's compile included).
 */
import { FloatType, WebGLRenderTarget, type WebGLRenderer } from 'three';
import type { FilmTable } from '../../../src/film/filmTable.ts';
import { filmTablePlanesUniforms, filmTableUniforms } from '../../../src/film/filmTableGrid.ts';

/** Waits for the GPU to finish the table `table` binds: a 1-pixel read of its render target. */
function readTablePixel(renderer: WebGLRenderer, table: FilmTable): void {
  const uniforms = { ...filmTableUniforms(), ...filmTablePlanesUniforms() };
  table.bind(uniforms);
  const texture = uniforms.uFilmTable.value;
  const target = texture?.renderTarget;
  if (!texture || !(target instanceof WebGLRenderTarget)) throw new Error('the film table binds no render target');
  const pixel = texture.type === FloatType ? new Float32Array(4) : new Uint16Array(4);
  renderer.readRenderTargetPixels(target, 0, 0, 1, 1, pixel);
}

export class TableWatch {
  /** Full tables shown since the watch began: updates that changed what `bind` binds and left no coarse table. */
  builds = 0;
  /** Milliseconds of the first table built at once (an update without `progressive`), or null before one. */
  firstBuildMs: number | null = null;

  constructor(private readonly table: FilmTable) {
    const update = table.update.bind(table);
    table.update = (renderer, s, maxThicknessNm, progressive) => {
      const started = performance.now();
      const changed = update(renderer, s, maxThicknessNm, progressive);
      if (!changed || table.coarse) return changed;
      this.builds++;
      if (!progressive && this.firstBuildMs === null) {
        readTablePixel(renderer, table);
        this.firstBuildMs = performance.now() - started;
      }
      return changed;
    };
  }

  /** Gives the table its own `update` back. */
  stop(): void {
    Reflect.deleteProperty(this.table, 'update');
  }
}
