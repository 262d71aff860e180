/**
 * The GPU timer reports each timed draw once, in the order drawn, as soon as its query's result is
 * available and not before; a disjoint event or a lost context drops what is pending unreported.
 * The WebGL context is a fake whose queries finish when the test says.
 */
import type { WebGLRenderer } from 'three';
import { describe, expect, it } from 'vitest';
import { GpuTimer } from '../../../src/gpu/gpuTimer.ts';

const TIME_ELAPSED_EXT = 0x88bf;
const GPU_DISJOINT_EXT = 0x8fbb;
const QUERY_RESULT = 0x8866;
const QUERY_RESULT_AVAILABLE = 0x8867;

interface FakeQuery {
  ns: number | null;
}

/** A WebGL2 context with the timer extension (unless `withTimer` is false) whose query results are set by `finish`. */
function fakeContext(withTimer = true) {
  const state = { lost: false, disjoint: false, active: null as FakeQuery | null, deleted: [] as FakeQuery[], made: [] as FakeQuery[] };
  const gl = {
    QUERY_RESULT,
    QUERY_RESULT_AVAILABLE,
    getExtension: (name: string) =>
      withTimer && name === 'EXT_disjoint_timer_query_webgl2' ? { TIME_ELAPSED_EXT, GPU_DISJOINT_EXT } : null,
    createQuery: () => {
      const q: FakeQuery = { ns: null };
      state.made.push(q);
      return q;
    },
    beginQuery: (target: number, q: FakeQuery) => {
      expect(target).toBe(TIME_ELAPSED_EXT);
      expect(state.active).toBeNull();
      state.active = q;
    },
    endQuery: (target: number) => {
      expect(target).toBe(TIME_ELAPSED_EXT);
      state.active = null;
    },
    getQueryParameter: (q: FakeQuery, pname: number) => (pname === QUERY_RESULT_AVAILABLE ? q.ns !== null : q.ns),
    deleteQuery: (q: FakeQuery) => state.deleted.push(q),
    getParameter: (pname: number) => pname === GPU_DISJOINT_EXT && state.disjoint,
    isContextLost: () => state.lost,
  };
  const renderer = { getContext: () => gl } as unknown as WebGLRenderer;
  return { renderer, state, finish: (i: number, ms: number) => (state.made[i]!.ns = ms * 1e6) };
}

describe('the GPU timer', () => {
  it('is null where the context cannot time draws', () => {
    expect(GpuTimer.of(fakeContext(false).renderer)).toBeNull();
  });

  it('times the draw inside its query, and reports results in order once available, each once', () => {
    const { renderer, state, finish } = fakeContext();
    const timer = GpuTimer.of(renderer)!;
    const reported: [string, number][] = [];
    const drawn: string[] = [];
    for (const name of ['a', 'b', 'c']) {
      timer.time(
        () => {
          expect(state.active).not.toBeNull();
          drawn.push(name);
        },
        (ms) => reported.push([name, ms]),
      );
    }
    expect(drawn).toEqual(['a', 'b', 'c']);
    timer.poll();
    expect(reported).toEqual([]);
    // The second finishes first: nothing is reported out of order.
    finish(1, 7);
    timer.poll();
    expect(reported).toEqual([]);
    finish(0, 3);
    timer.poll();
    expect(reported).toEqual([
      ['a', 3],
      ['b', 7],
    ]);
    finish(2, 0.5);
    timer.poll();
    timer.poll();
    expect(reported).toEqual([
      ['a', 3],
      ['b', 7],
      ['c', 0.5],
    ]);
    expect(state.deleted).toEqual(state.made);
  });

  it.each([
    ['a disjoint event', 'disjoint', true],
    ['a lost context', 'lost', false],
  ] as const)('%s drops the pending draws unreported, deleting their queries unless the context is lost', (_, what, deleted) => {
    const { renderer, state, finish } = fakeContext();
    const timer = GpuTimer.of(renderer)!;
    const reported: number[] = [];
    timer.time(
      () => {},
      (ms) => reported.push(ms),
    );
    finish(0, 2);
    state[what] = true;
    timer.poll();
    // Dropped, not held back: once the context is well again, nothing comes.
    state[what] = false;
    timer.poll();
    expect(reported).toEqual([]);
    // The lost context's queries are not touched: deleting them would warn in the restored one.
    expect(state.deleted).toEqual(deleted ? state.made : []);
  });
});
