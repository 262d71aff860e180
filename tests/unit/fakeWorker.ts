import { vi } from 'vitest';

type Handler = (e: MessageEvent) => void;

/**
 * A worker module (its path from this folder) loaded into a stand-in of a worker's global scope:
 * its message handler, and what it posts (as structured clones, transferred buffers included).
 */
export async function loadWorkerScope<Reply>(modulePath: string): Promise<{ handler: Handler | null; posted: Reply[] }> {
  let handler: Handler | null = null;
  const posted: Reply[] = [];
  vi.stubGlobal('addEventListener', (type: string, h: Handler) => {
    if (type === 'message') handler = h;
  });
  vi.stubGlobal('postMessage', (message: Reply, options?: StructuredSerializeOptions) => posted.push(structuredClone(message, options)));
  vi.resetModules();
  await import(/* @vite-ignore */ new URL(modulePath, import.meta.url).href);
  return { handler, posted };
}

/**
 * A Worker class standing in for the browser's, running the worker module's handler a task after
 * each message (or, if `fail`, firing an error event instead); it keeps every instance and request.
 */
export async function fakeWorkerClass<Request, Reply>(modulePath: string, fail = false) {
  const scope = await loadWorkerScope<Reply>(modulePath);
  return class FakeWorker extends EventTarget {
    static made: FakeWorker[] = [];
    readonly requests: Request[] = [];
    constructor(
      readonly url: URL,
      readonly options: WorkerOptions,
    ) {
      super();
      FakeWorker.made.push(this);
    }
    postMessage(request: Request): void {
      this.requests.push(request);
      setTimeout(() => {
        if (fail) return void this.dispatchEvent(new Event('error'));
        scope.handler!(new MessageEvent('message', { data: structuredClone(request) }));
        this.dispatchEvent(new MessageEvent('message', { data: scope.posted.shift() }));
      });
    }
    terminate(): void {}
  };
}

export const nextTask = () => new Promise((resolve) => setTimeout(resolve));
