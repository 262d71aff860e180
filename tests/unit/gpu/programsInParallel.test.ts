import { describe, expect, it } from 'vitest';
import { ProgramsInParallel } from '../../../src/view/programsInParallel.ts';

/** A compile that resolves when told, counting how often it was started. */
function deferredCompile() {
  const state = { started: 0, finish: () => {} };
  const compile = () => {
    state.started++;
    return new Promise<void>((resolve) => (state.finish = resolve));
  };
  return { state, compile };
}

describe('ProgramsInParallel: a frame waits for its programs, compiled once per key', () => {
  it('not ready until the compile resolves; the compile is started once however often it is asked', async () => {
    const programs = new ProgramsInParallel();
    const { state, compile } = deferredCompile();
    expect(programs.ready('a', compile)).toBe(false);
    expect(programs.ready('a', compile)).toBe(false);
    expect([state.started, programs.busy]).toEqual([1, true]);
    state.finish();
    await programs.compile('a', compile);
    expect([programs.ready('a', compile), programs.busy, state.started]).toEqual([true, false, 1]);
  });

  it('a compile overtaken by another key does not mark its own key ready', async () => {
    const programs = new ProgramsInParallel();
    const first = deferredCompile();
    const second = deferredCompile();
    programs.ready('a', first.compile);
    const b = programs.compile('b', second.compile);
    first.state.finish();
    await Promise.resolve();
    expect(programs.busy).toBe(true);
    second.state.finish();
    await b;
    expect([programs.ready('b', second.compile), programs.busy]).toEqual([true, false]);
  });

  it('after forget (a restored context) the same key compiles again', async () => {
    const programs = new ProgramsInParallel();
    const { state, compile } = deferredCompile();
    const done = programs.compile('a', compile);
    state.finish();
    await done;
    programs.forget();
    expect(programs.ready('a', compile)).toBe(false);
    expect(state.started).toBe(2);
  });
});
