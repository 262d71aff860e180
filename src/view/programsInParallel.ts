/**
 * The programs a view's next frame draws with, compiled without blocking the page where the GPU
 * compiles in parallel (KHR_parallel_shader_compile): a change that needs a new program keeps the
 * frame shown until it is ready, as a new light keeps the table shown until its transform is at hand.
 * `key` names what picks the programs (their defines and the renderer state three keys them by).
 */
export class ProgramsInParallel {
  private readyFor = '';
  private compiling: { readonly key: string; readonly done: Promise<void> } | null = null;

  /** Whether the programs for `key` are ready; if not, starts `compile` for it (once) and says no until it has resolved. */
  ready(key: string, compile: () => Promise<unknown>): boolean {
    if (key === this.readyFor) return true;
    void this.compile(key, compile);
    return false;
  }

  /** Compiles the programs for `key` with `compile` unless they are ready or on their way; resolves when they are ready. */
  compile(key: string, compile: () => Promise<unknown>): Promise<void> {
    if (key === this.readyFor) return Promise.resolve();
    if (this.compiling?.key === key) return this.compiling.done;
    const compiling = {
      key,
      done: compile().then(() => {
        if (this.compiling !== compiling) return;
        this.compiling = null;
        this.readyFor = key;
      }),
    };
    this.compiling = compiling;
    return compiling.done;
  }

  /** Whether programs are being compiled for a frame not yet drawn. */
  get busy(): boolean {
    return this.compiling !== null;
  }

  /** Forgets what was compiled (a restored context has none of it). */
  forget(): void {
    this.readyFor = '';
    this.compiling = null;
  }
}
