/** A table fill's programs: the last ones kept and made once, the one used least recently released. */
import { describe, expect, it } from 'vitest';
import { KEPT_PASSES } from '../../../src/film/keptPasses.ts';
import { KeptPrograms } from '../../../src/nodeMaterial/keptPrograms.ts';

describe('KeptPrograms', () => {
  it('makes a program once while it is kept, and releases the least recently used beyond the count', () => {
    const released: string[] = [];
    let made = 0;
    const kept = new KeptPrograms<{ name: string }>((p) => released.push(p.name));
    const of = (name: string) => kept.of(name, () => (made++, { name }));
    const first = of('constant');
    const names = Array.from({ length: KEPT_PASSES - 1 }, (_, i) => `film ${i}`);
    names.forEach(of);
    expect(of('constant')).toBe(first);
    expect([made, released]).toEqual([KEPT_PASSES, []]);
    of('dispersive');
    // 'constant' was used last but one: the first of the others goes.
    expect(released).toEqual([names[0] ?? 'constant']);
    kept.clear();
    expect(released).toHaveLength(KEPT_PASSES + 1);
  });

  it('builds a program ahead of its use once, however often asked, and counts a used one as built', async () => {
    const kept = new KeptPrograms<{ name: string }>(() => {});
    const compiles: string[] = [];
    let finish = () => {};
    const compile = (p: { name: string }) => {
      compiles.push(p.name);
      return new Promise<void>((resolve) => (finish = resolve));
    };
    const make = () => ({ name: 'dispersive' });
    const first = kept.build('dispersive', make, compile);
    const again = kept.build('dispersive', make, compile);
    expect([compiles, kept.isBuilt('dispersive')]).toEqual([['dispersive'], false]);
    finish();
    await Promise.all([first, again]);
    expect(kept.isBuilt('dispersive')).toBe(true);
    kept.of('constant', () => ({ name: 'constant' }));
    expect(kept.isBuilt('constant')).toBe(true);
    await kept.build('constant', make, compile);
    expect(compiles).toEqual(['dispersive']);
  });
});
