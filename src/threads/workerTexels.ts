import { WorkerRequests } from './workerRequests.ts';

/** What a texels worker is asked: the key, and the input its texels are computed from. */
export interface TexelsRequest<Input> {
  readonly key: string;
  readonly input: Input;
}

/** … and what it answers: the key and its texels (transferred, not copied). */
export interface TexelsReply {
  readonly key: string;
  readonly texels: Float32Array;
}

/**
 * Float texels that follow from a key (a light's spectral transform, a dispersive film's row terms),
 * computed from the key's input in a module Web Worker that `serveTexels` runs, or on the caller's
 * thread where there is none or it fails; the last `keep` keys' texels are kept, so the same key
 * is not computed again. The input is made on the caller's thread, so that the worker's code needs
 * only what computes the texels from it (a light's weights, not the lights' data).
 */
export class WorkerTexels<Input> {
  private readonly kept = new Map<string, Float32Array>();
  /** whenReady's promises, by key, kept when its texels arrive */
  private readonly waiting = new Map<string, (() => void)[]>();
  private readonly requests: WorkerRequests<TexelsReply>;

  constructor(
    /** Makes the worker: `new Worker(new URL('./file.ts', import.meta.url), { type: 'module' })` in the module that owns it. */
    make: () => Worker,
    /** The input of a key's texels, made on this thread (structured-cloned to the worker). */
    private readonly inputOf: (key: string) => Input,
    private readonly compute: (input: Input) => Float32Array,
    private readonly keep: number,
  ) {
    // The keys asked of a worker that failed are computed on this thread when next asked for, or
    // at once where a promise waits for them.
    this.requests = new WorkerRequests<TexelsReply>(
      make,
      (reply) => this.hold(reply.key, reply.texels),
      (keys) => keys.filter((key) => this.waiting.has(key)).forEach((key) => this.of(key)),
    );
  }

  /** The texels of `key`, computed on this thread unless at hand. */
  of(key: string): Float32Array {
    const kept = this.kept.get(key);
    if (kept) return kept;
    const texels = this.compute(this.inputOf(key));
    this.hold(key, texels);
    return texels;
  }

  /**
   * Whether the texels of `key` are at hand. If not, the worker is asked for them (once) and the
   * answer is false until they arrive; where there is no worker they are computed here at once (true).
   */
  ready(key: string): boolean {
    if (this.kept.has(key)) return true;
    if (this.requests.ask(key, () => ({ key, input: this.inputOf(key) }) satisfies TexelsRequest<Input>)) return false;
    this.of(key);
    return true;
  }

  /** A promise kept once the texels of `key` are at hand: asked of the worker (once), or where there is none computed here at once. */
  whenReady(key: string): Promise<void> {
    if (this.ready(key)) return Promise.resolve();
    return new Promise((resolve) => this.waiting.set(key, [...(this.waiting.get(key) ?? []), resolve]));
  }

  private hold(key: string, texels: Float32Array): void {
    this.kept.delete(key);
    this.kept.set(key, texels);
    for (const old of this.kept.keys()) if (this.kept.size > this.keep) this.kept.delete(old);
    for (const resolve of this.waiting.get(key) ?? []) resolve();
    this.waiting.delete(key);
  }
}

/** In a worker module: answers each TexelsRequest with its key and `compute(input)`, transferred. */
export function serveTexels<Input>(compute: (input: Input) => Float32Array): void {
  addEventListener('message', (e: MessageEvent<TexelsRequest<Input>>) => {
    const { key, input } = e.data;
    const texels = compute(input);
    postMessage({ key, texels } satisfies TexelsReply, { transfer: [texels.buffer] });
  });
}
