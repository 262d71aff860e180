/**
 * The light's spectral transform computed in the Web Worker is the main thread's, bit for bit (the
 * same code on both sides of a message); the store that asks the worker has the texels once its
 * answer arrives, and computes them itself where there is no worker or it fails.
 */
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { afterEach, describe, expect, it, vi } from 'vitest';
import { type SpectralLight, spectralLightKey, spectralTransformTexels } from '../../../src/film/spectralTransformTexels.ts';
import type { SpectralTransformReply, SpectralTransformRequest } from '../../../src/film/spectralTransformWorker.ts';

const LIGHT: SpectralLight = { illuminant: 'D93', normalization: 'paper' };
const KEY = spectralLightKey(LIGHT);
/** The main thread's texels for LIGHT, computed once (an FFT of 2¹⁸ points per channel). */
let inline: Float32Array | null = null;
const inlineTexels = () => (inline ??= spectralTransformTexels(LIGHT));

type Handler = (e: MessageEvent<SpectralTransformRequest>) => void;

/** The worker module loaded into a stand-in of a worker's global scope: its message handler, and what it posts (as structured clones, the buffers transferred). */
async function loadWorkerScope(): Promise<{ handler: Handler; posted: SpectralTransformReply[] }> {
  let handler: Handler | null = null;
  const posted: SpectralTransformReply[] = [];
  vi.stubGlobal('addEventListener', (type: string, h: Handler) => {
    if (type === 'message') handler = h;
  });
  vi.stubGlobal('postMessage', (message: SpectralTransformReply, options: StructuredSerializeOptions) =>
    posted.push(structuredClone(message, options)),
  );
  vi.resetModules();
  await import('../../../src/film/spectralTransformWorker.ts');
  expect(handler, 'the worker listens for messages').not.toBeNull();
  return { handler: handler!, posted };
}

/** A Worker standing in for the browser's, running the worker module's handler a task after each message. */
async function fakeWorkerClass(fail = false) {
  const scope = await loadWorkerScope();
  return class FakeWorker extends EventTarget {
    static made: FakeWorker[] = [];
    readonly requests: SpectralTransformRequest[] = [];
    constructor(
      readonly url: URL,
      readonly options: WorkerOptions,
    ) {
      super();
      FakeWorker.made.push(this);
    }
    postMessage(request: SpectralTransformRequest): void {
      this.requests.push(request);
      setTimeout(() => {
        if (fail) return void this.dispatchEvent(new Event('error'));
        scope.handler(new MessageEvent('message', { data: structuredClone(request) }));
        this.dispatchEvent(new MessageEvent('message', { data: scope.posted.shift() }));
      });
    }
    terminate(): void {}
  };
}

const nextTask = () => new Promise((resolve) => setTimeout(resolve));

afterEach(() => {
  vi.unstubAllGlobals();
  vi.resetModules();
});

describe('the spectral transform off the main thread', () => {
  it("the worker's answer is the main thread's texels, bit for bit", async () => {
    const { handler, posted } = await loadWorkerScope();
    handler(new MessageEvent('message', { data: { key: KEY } }));
    expect(posted).toHaveLength(1);
    expect(posted[0]!.key).toBe(KEY);
    expect(posted[0]!.texels).toStrictEqual(inlineTexels());
  });

  it('the store asks its module worker once, and has the texels when the answer arrives', async () => {
    const FakeWorker = await fakeWorkerClass();
    vi.stubGlobal('Worker', FakeWorker);
    const store = await import('../../../src/film/spectralTransformStore.ts');
    expect(store.spectralTransformTexelsReady(KEY)).toBe(false);
    expect(store.spectralTransformTexelsReady(KEY)).toBe(false);
    const [worker] = FakeWorker.made;
    expect(FakeWorker.made).toHaveLength(1);
    expect(worker!.options.type).toBe('module');
    expect(existsSync(fileURLToPath(worker!.url)), `${worker!.url} is a file`).toBe(true);
    expect(worker!.url.pathname.endsWith('/spectralTransformWorker.ts')).toBe(true);
    expect(worker!.requests).toEqual([{ key: KEY }]);
    await nextTask();
    expect(store.spectralTransformTexelsReady(KEY)).toBe(true);
    expect(store.spectralTransformTexelsOf(KEY)).toStrictEqual(inlineTexels());
  });

  it('without Workers (Node, here), the store computes the texels at once', async () => {
    expect(typeof Worker).toBe('undefined');
    const store = await import('../../../src/film/spectralTransformStore.ts');
    expect(store.spectralTransformTexelsReady(KEY)).toBe(true);
    expect(store.spectralTransformTexelsOf(KEY)).toStrictEqual(inlineTexels());
  });

  it('after its worker fails, the store computes the texels itself', async () => {
    const FakeWorker = await fakeWorkerClass(true);
    vi.stubGlobal('Worker', FakeWorker);
    const store = await import('../../../src/film/spectralTransformStore.ts');
    expect(store.spectralTransformTexelsReady(KEY)).toBe(false);
    await nextTask();
    expect(store.spectralTransformTexelsReady(KEY)).toBe(true);
    expect(FakeWorker.made).toHaveLength(1);
    expect(store.spectralTransformTexelsOf(KEY)).toStrictEqual(inlineTexels());
  });
});
