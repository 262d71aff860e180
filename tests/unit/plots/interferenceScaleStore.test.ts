/**
 * The interference colour scale off the main thread: the worker's answer is the scale computed on
 * this thread (the same code on both sides of a message), the store calls each waiting plot back
 * once it arrives, and computes the scale itself where there is no worker or it fails.
 */
import { afterEach, describe, expect, it, vi } from 'vitest';
import { XYZ_TO_LINEAR_SRGB } from '../../../src/physics/colorConversions.ts';
import { type ScaleColor, type ScaleRequest, interferenceScaleOf } from '../../../src/plots/interferenceScale.ts';
import type { ScaleReply } from '../../../src/plots/interferenceScaleWorker.ts';
import { fakeWorkerClass, loadWorkerScope, nextTask } from '../fakeWorker.ts';

const WORKER = '../../src/plots/interferenceScaleWorker.ts';
const REQUEST: ScaleRequest = {
  stack: { nOutside: 1, nFilm: 'water', nInside: 1, angleDeg: 30 },
  maxThicknessNm: 1200,
  count: 12,
  options: { illuminant: 'D65', polarization: 'unpolarized', normalization: 'white', xyzToLinearRgb: XYZ_TO_LINEAR_SRGB },
};
type Message = ScaleRequest & { readonly key: string };

afterEach(() => {
  vi.unstubAllGlobals();
  vi.resetModules();
});

describe('the interference scale off the main thread', () => {
  it("the worker's answer is the scale computed here", async () => {
    const { handler, posted } = await loadWorkerScope<ScaleReply>(WORKER);
    expect(handler, 'the worker listens for messages').not.toBeNull();
    handler!(new MessageEvent('message', { data: { ...REQUEST, key: 'k' } }));
    expect(posted).toEqual([{ key: 'k', colors: interferenceScaleOf(REQUEST) }]);
  });

  it('the store asks its worker once per scale and calls every plot waiting for it back', async () => {
    const FakeWorker = await fakeWorkerClass<Message, ScaleReply>(WORKER);
    vi.stubGlobal('Worker', FakeWorker);
    const { interferenceScaleFor } = await import('../../../src/plots/interferenceScaleStore.ts');
    const arrived: ScaleColor[][] = [];
    expect(interferenceScaleFor(REQUEST, (c) => arrived.push(c))).toBeNull();
    expect(interferenceScaleFor(REQUEST, (c) => arrived.push(c))).toBeNull();
    expect(FakeWorker.made).toHaveLength(1);
    expect(FakeWorker.made[0]!.options.type).toBe('module');
    expect(FakeWorker.made[0]!.url.pathname.endsWith('/interferenceScaleWorker.ts')).toBe(true);
    expect(FakeWorker.made[0]!.requests).toHaveLength(1);
    await nextTask();
    expect(arrived).toEqual([interferenceScaleOf(REQUEST), interferenceScaleOf(REQUEST)]);
  });

  it('without Workers (Node, here), the store computes the scale at once', async () => {
    expect(typeof Worker).toBe('undefined');
    const { interferenceScaleFor } = await import('../../../src/plots/interferenceScaleStore.ts');
    expect(interferenceScaleFor(REQUEST, () => expect.unreachable('no call back'))).toEqual(interferenceScaleOf(REQUEST));
  });

  it('after its worker fails, the store computes the scales pending and calls their plots back', async () => {
    const FakeWorker = await fakeWorkerClass<Message, ScaleReply>(WORKER, true);
    vi.stubGlobal('Worker', FakeWorker);
    const { interferenceScaleFor } = await import('../../../src/plots/interferenceScaleStore.ts');
    const arrived: ScaleColor[][] = [];
    expect(interferenceScaleFor(REQUEST, (c) => arrived.push(c))).toBeNull();
    await nextTask();
    expect(arrived).toEqual([interferenceScaleOf(REQUEST)]);
    // Later scales are computed here at once.
    expect(interferenceScaleFor({ ...REQUEST, count: 5 }, () => expect.unreachable('no call back'))).toEqual(
      interferenceScaleOf({ ...REQUEST, count: 5 }),
    );
  });
});
