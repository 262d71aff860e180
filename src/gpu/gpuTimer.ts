import type { WebGLRenderer } from 'three';

/** EXT_disjoint_timer_query_webgl2's enums (the extension object carries them). */
interface TimerQueryExtension {
  readonly TIME_ELAPSED_EXT: number;
  readonly GPU_DISJOINT_EXT: number;
}

interface Pending {
  readonly query: WebGLQuery;
  readonly done: (ms: number) => void;
}

/**
 * The GPU's time for draws, read frames later without waiting for the GPU
 * (EXT_disjoint_timer_query_webgl2): a draw timed here costs no stall, where a read-back that
 * times it waits for every frame queued before it too. Results come back in the order the draws
 * were made; a disjoint event (the GPU's clock unreliable meanwhile) or a lost context drops the
 * pending ones unreported.
 */
export class GpuTimer {
  private readonly pending: Pending[] = [];

  private constructor(
    private readonly gl: WebGL2RenderingContext,
    private readonly ext: TimerQueryExtension,
  ) {}

  /** A timer for the renderer's context, or null where the GPU cannot time draws. */
  static of(renderer: WebGLRenderer): GpuTimer | null {
    const gl = renderer.getContext() as WebGL2RenderingContext; // three's renderer is WebGL2 only
    const ext = gl.getExtension('EXT_disjoint_timer_query_webgl2') as TimerQueryExtension | null;
    return ext ? new GpuTimer(gl, ext) : null;
  }

  /** Runs `draw` between a query's begin and end; `done` gets its GPU milliseconds once known (a later `poll`). */
  time(draw: () => void, done: (ms: number) => void): void {
    const query = this.gl.createQuery();
    this.gl.beginQuery(this.ext.TIME_ELAPSED_EXT, query);
    draw();
    this.gl.endQuery(this.ext.TIME_ELAPSED_EXT);
    this.pending.push({ query, done });
  }

  /** Reports the timed draws whose results are available, in order. */
  poll(): void {
    if (this.pending.length === 0) return; // the app's every frame polls: nothing to ask the context then
    const gl = this.gl;
    if (gl.isContextLost() || gl.getParameter(this.ext.GPU_DISJOINT_EXT)) return this.drop();
    while (this.pending.length > 0) {
      const { query, done } = this.pending[0]!;
      if (!gl.getQueryParameter(query, gl.QUERY_RESULT_AVAILABLE)) return;
      const ns = gl.getQueryParameter(query, gl.QUERY_RESULT) as number;
      gl.deleteQuery(query);
      this.pending.shift();
      done(ns / 1e6);
    }
  }

  /** Forgets the pending draws (their queries deleted, unless the context that made them is lost). */
  drop(): void {
    const lost = this.gl.isContextLost();
    for (const { query } of this.pending.splice(0)) if (!lost) this.gl.deleteQuery(query);
  }
}
