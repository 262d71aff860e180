import { ShaderMaterial } from 'three';
import { describe, expect, it } from 'vitest';
import { KEPT_DEFINE_SETS, setDefines } from '../../../src/gpu/materialDefines.ts';

/** A material and how often three would have been told to free its programs (its `dispose` event). */
function watched(defines: Record<string, number> = {}) {
  const m = new ShaderMaterial({ defines });
  const counts = { disposed: 0 };
  m.addEventListener('dispose', () => counts.disposed++);
  return { m, counts };
}

describe('setDefines: a material keeps the programs of its last KEPT_DEFINE_SETS sets of defines', () => {
  it('the same defines change nothing: no new version, nothing freed', () => {
    const { m, counts } = watched({ A: 1 });
    const version = m.version;
    setDefines(m, { A: 1 });
    expect([m.version, counts.disposed]).toEqual([version, 0]);
  });

  it('going back and forth among KEPT_DEFINE_SETS sets frees nothing; each change asks for its program (a new version)', () => {
    const { m, counts } = watched({ SET: 0 });
    const version = m.version;
    for (let round = 0; round < 3; round++) for (let set = 0; set < KEPT_DEFINE_SETS; set++) setDefines(m, { SET: set });
    expect(counts.disposed).toBe(0);
    expect(m.defines).toEqual({ SET: KEPT_DEFINE_SETS - 1 });
    expect(m.version).toBeGreaterThan(version);
  });

  it('a set beyond them frees all, and the count starts again from that set', () => {
    const { m, counts } = watched({ SET: 0 });
    for (let set = 1; set <= KEPT_DEFINE_SETS; set++) setDefines(m, { SET: set });
    expect(counts.disposed).toBe(1);
    // Held now: the last set only; KEPT_DEFINE_SETS − 1 others fit before the next free.
    for (let set = 100; set < 100 + KEPT_DEFINE_SETS - 1; set++) setDefines(m, { SET: set });
    expect(counts.disposed).toBe(1);
    setDefines(m, { SET: 999 });
    expect(counts.disposed).toBe(2);
  });

  it('a material made without defines counts no set for them; kept = 1 frees on every new set', () => {
    const { m, counts } = watched();
    for (let set = 0; set < KEPT_DEFINE_SETS; set++) setDefines(m, { SET: set });
    expect(counts.disposed).toBe(0);
    const pass = watched({ SET: 0 });
    setDefines(pass.m, { SET: 1 }, 1);
    setDefines(pass.m, { SET: 0 }, 1);
    expect(pass.counts.disposed).toBe(2);
  });
});
