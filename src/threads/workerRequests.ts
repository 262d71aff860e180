/**
 * Requests by key to a module Web Worker, each asked once while it is pending. Where there are no
 * Workers (Node), the constructor refuses (a page's CSP), or the worker fails to load or run,
 * `ask` answers false and the caller computes on its own thread; the requests pending when it
 * failed are handed to `onFail`, to be computed there too.
 */
export class WorkerRequests<Reply extends { readonly key: string }> {
  /** The worker, made when first needed; null where there is none or it failed. */
  private worker: Worker | null | undefined;
  private readonly pending = new Set<string>();

  constructor(
    /** Makes the worker: `new Worker(new URL('./file.ts', import.meta.url), { type: 'module' })` in the module that owns it, where bundlers find it. */
    private readonly make: () => Worker,
    private readonly onReply: (reply: Reply) => void,
    private readonly onFail: (pendingKeys: readonly string[]) => void = () => {},
  ) {}

  /**
   * Whether the worker has the request `key` (asked now, or already pending); false: there is no
   * worker, compute it here. `request` makes the message, only when it is sent.
   */
  ask(key: string, request: () => unknown): boolean {
    const w = this.theWorker();
    if (!w) return false;
    if (!this.pending.has(key)) {
      this.pending.add(key);
      w.postMessage(request());
    }
    return true;
  }

  private theWorker(): Worker | null {
    if (this.worker !== undefined) return this.worker;
    this.worker = null;
    if (typeof Worker === 'undefined') return null;
    try {
      const w = this.make();
      w.addEventListener('message', (e: MessageEvent<Reply>) => {
        this.pending.delete(e.data.key);
        this.onReply(e.data);
      });
      const fail = () => {
        w.terminate();
        this.worker = null;
        const keys = [...this.pending];
        this.pending.clear();
        this.onFail(keys);
      };
      w.addEventListener('error', fail);
      w.addEventListener('messageerror', fail);
      this.worker = w;
    } catch {
      // The constructor refused (a SecurityError): no worker.
    }
    return this.worker;
  }
}
