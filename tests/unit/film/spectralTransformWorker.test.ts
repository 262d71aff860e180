/**
 * The light's spectral transform computed in the Web Worker from the light's weights is the main
 * thread's, bit for bit (the same code on both sides of a message); the store that asks the worker has the texels once its
 * answer arrives, and computes them itself where there is no worker or it fails.
 */
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { afterEach, describe, expect, it, vi } from 'vitest';
import { spectralLightKey, spectralTransformTexels } from '../../../src/film/spectralTransformTexels.ts';
import type { SpectralLight } from '../../../src/physics/spectralWeights.ts';
import { type SpectralWeights, spectralWeights } from '../../../src/physics/spectralWeights.ts';
import type {
  TexelsReply as SpectralTransformReply,
  TexelsRequest as SpectralTransformRequest,
} from '../../../src/threads/workerTexels.ts';
import { fakeWorkerClass, loadWorkerScope, nextTask } from '../fakeWorker.ts';

const LIGHT: SpectralLight = { illuminant: 'D93', normalization: 'paper', lightTint: [1, 0.5, 0.2] };
const KEY = spectralLightKey(LIGHT);
/** What the store sends the worker for LIGHT: the key and the light's weights (the worker holds no light's data). */
const REQUEST = { key: KEY, input: spectralWeights(LIGHT.illuminant, LIGHT.normalization, LIGHT.lightTint) };
/** The main thread's texels for LIGHT, computed once (an FFT of 2¹⁸ points per channel). */
let inline: Float32Array | null = null;
const inlineTexels = () => (inline ??= spectralTransformTexels(REQUEST.input));

const WORKER = '../../src/film/spectralTransformWorker.ts';

afterEach(() => {
  vi.unstubAllGlobals();
  vi.resetModules();
});

describe('the spectral transform off the main thread', () => {
  it("the worker's answer is the main thread's texels, bit for bit", async () => {
    const { handler, posted } = await loadWorkerScope<SpectralTransformReply>(WORKER);
    expect(handler, 'the worker listens for messages').not.toBeNull();
    handler!(new MessageEvent('message', { data: REQUEST }));
    expect(posted).toHaveLength(1);
    expect(posted[0]!.key).toBe(KEY);
    expect(posted[0]!.texels).toStrictEqual(inlineTexels());
  });

  it('the store asks its module worker once, and has the texels when the answer arrives', async () => {
    const FakeWorker = await fakeWorkerClass<SpectralTransformRequest<SpectralWeights>, SpectralTransformReply>(WORKER);
    vi.stubGlobal('Worker', FakeWorker);
    const store = await import('../../../src/film/spectralTransformStore.ts');
    expect(store.spectralTransformTexelsReady(KEY)).toBe(false);
    expect(store.spectralTransformTexelsReady(KEY)).toBe(false);
    const [worker] = FakeWorker.made;
    expect(FakeWorker.made).toHaveLength(1);
    expect(worker!.options.type).toBe('module');
    expect(existsSync(fileURLToPath(worker!.url)), `${worker!.url} is a file`).toBe(true);
    expect(worker!.url.pathname.endsWith('/spectralTransformWorker.ts')).toBe(true);
    expect(worker!.requests).toEqual([REQUEST]);
    await nextTask();
    expect(store.spectralTransformTexelsReady(KEY)).toBe(true);
    expect(store.spectralTransformTexelsOf(KEY)).toStrictEqual(inlineTexels());
  });

  it("the store's promise is kept when the worker's answer arrives, not before", async () => {
    const FakeWorker = await fakeWorkerClass<SpectralTransformRequest<SpectralWeights>, SpectralTransformReply>(WORKER);
    vi.stubGlobal('Worker', FakeWorker);
    const store = await import('../../../src/film/spectralTransformStore.ts');
    let kept = false;
    const ready = store.spectralTransformTexelsWhenReady(KEY).then(() => (kept = true));
    await Promise.resolve();
    expect(kept).toBe(false);
    expect(FakeWorker.made[0]!.requests).toEqual([REQUEST]);
    await ready;
    expect(store.spectralTransformTexelsReady(KEY)).toBe(true);
    expect(store.spectralTransformTexelsOf(KEY)).toStrictEqual(inlineTexels());
    await expect(store.spectralTransformTexelsWhenReady(KEY)).resolves.toBeUndefined();
    expect(FakeWorker.made[0]!.requests).toHaveLength(1);
  });

  it("after its worker fails, the store's promise is kept with the texels computed here", async () => {
    const FakeWorker = await fakeWorkerClass<SpectralTransformRequest<SpectralWeights>, SpectralTransformReply>(WORKER, true);
    vi.stubGlobal('Worker', FakeWorker);
    const store = await import('../../../src/film/spectralTransformStore.ts');
    await store.spectralTransformTexelsWhenReady(KEY);
    expect(store.spectralTransformTexelsOf(KEY)).toStrictEqual(inlineTexels());
  });

  it('without Workers (Node, here), the store computes the texels at once', async () => {
    expect(typeof Worker).toBe('undefined');
    const store = await import('../../../src/film/spectralTransformStore.ts');
    expect(store.spectralTransformTexelsReady(KEY)).toBe(true);
    expect(store.spectralTransformTexelsOf(KEY)).toStrictEqual(inlineTexels());
  });

  it('after its worker fails, the store computes the texels itself', async () => {
    const FakeWorker = await fakeWorkerClass<SpectralTransformRequest<SpectralWeights>, SpectralTransformReply>(WORKER, true);
    vi.stubGlobal('Worker', FakeWorker);
    const store = await import('../../../src/film/spectralTransformStore.ts');
    expect(store.spectralTransformTexelsReady(KEY)).toBe(false);
    await nextTask();
    expect(store.spectralTransformTexelsReady(KEY)).toBe(true);
    expect(FakeWorker.made).toHaveLength(1);
    expect(store.spectralTransformTexelsOf(KEY)).toStrictEqual(inlineTexels());
  });
});
