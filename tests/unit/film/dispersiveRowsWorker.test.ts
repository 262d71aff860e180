/**
 * A dispersive film's row terms computed in the Web Worker are the main thread's, bit for bit (the
 * same code on both sides of a message); the store asks the worker once per key, has the terms once
 * its answer arrives, keeps the last few keys, and computes them itself where there is no worker.
 */
import { afterEach, describe, expect, it, vi } from 'vitest';
import { dispersiveRows, dispersiveRowsKey, dispersiveRowsLength } from '../../../src/film/dispersiveRows.ts';
import type { Medium } from '../../../src/physics/medium.ts';
import { DEFAULT_FILM_QUALITY } from '../../../src/settings/filmQuality.ts';
import type { TexelsReply, TexelsRequest } from '../../../src/threads/workerTexels.ts';
import { fakeWorkerClass, loadWorkerScope, nextTask } from '../fakeWorker.ts';

const WORKER = '../../src/film/dispersiveRowsWorker.ts';
const LAYOUT = { ...DEFAULT_FILM_QUALITY.table, rows: 6, spectralBins: DEFAULT_FILM_QUALITY.dispersiveSpectralBins };
const FILM = { nOutside: 1, nFilm: 'water', nInside: 1, polarization: 'unpolarized' } as const;
const keyOf = (nFilm: Medium) => dispersiveRowsKey({ ...FILM, nFilm }, LAYOUT);
const KEY = keyOf('water');

/** The main thread's terms, written into an array of their length. */
function inlineRows(): Float32Array {
  const data = new Float32Array(dispersiveRowsLength(LAYOUT));
  dispersiveRows(FILM, LAYOUT, data);
  return data;
}

afterEach(() => {
  vi.unstubAllGlobals();
  vi.resetModules();
});

describe("a dispersive film's row terms off the main thread", () => {
  it("the worker's answer is the main thread's terms, bit for bit, and fills every float", async () => {
    const { handler, posted } = await loadWorkerScope<TexelsReply>(WORKER);
    expect(handler, 'the worker listens for messages').not.toBeNull();
    handler!(new MessageEvent('message', { data: { key: KEY, input: KEY } }));
    expect(posted).toHaveLength(1);
    expect(posted[0]!.key).toBe(KEY);
    const inline = inlineRows();
    expect(posted[0]!.texels).toStrictEqual(inline);
    // Both halves of every row and bin written: water's Fresnel terms are never all zero in a texel.
    for (let texel = 0; texel < inline.length / 4; texel++) expect(inline.slice(4 * texel, 4 * texel + 4).some((v) => v !== 0)).toBe(true);
  });

  it('the store asks its module worker once per key, has the terms when the answer arrives, and keeps the last four keys', async () => {
    const FakeWorker = await fakeWorkerClass<TexelsRequest<string>, TexelsReply>(WORKER);
    vi.stubGlobal('Worker', FakeWorker);
    const store = await import('../../../src/film/dispersiveRowsStore.ts');
    expect(store.dispersiveRowsReady(KEY)).toBe(false);
    expect(store.dispersiveRowsReady(KEY)).toBe(false);
    expect(FakeWorker.made).toHaveLength(1);
    expect(FakeWorker.made[0]!.url.pathname.endsWith('/dispersiveRowsWorker.ts')).toBe(true);
    expect(FakeWorker.made[0]!.requests).toEqual([{ key: KEY, input: KEY }]);
    await nextTask();
    expect(store.dispersiveRowsReady(KEY)).toBe(true);
    expect(store.dispersiveRowsOf(KEY)).toStrictEqual(inlineRows());
    // Four more films: the first is let go and asked for again.
    const others = [1.4, 1.5, 1.6, 1.7].map((a) => keyOf({ cauchy: [a, 3000, 0] }));
    for (const key of others) expect(store.dispersiveRowsReady(key)).toBe(false);
    await nextTask();
    for (const key of others) expect(store.dispersiveRowsReady(key)).toBe(true);
    expect(store.dispersiveRowsReady(KEY)).toBe(false);
    expect(FakeWorker.made[0]!.requests).toHaveLength(6);
    await nextTask();
    expect(store.dispersiveRowsReady(KEY)).toBe(true);
  });

  it('without Workers (Node, here), the store computes the terms at once', async () => {
    expect(typeof Worker).toBe('undefined');
    const store = await import('../../../src/film/dispersiveRowsStore.ts');
    expect(store.dispersiveRowsReady(KEY)).toBe(true);
    expect(store.dispersiveRowsOf(KEY)).toStrictEqual(inlineRows());
  });
});
