import { KEPT_PASSES } from '../film/keptPasses.ts';

/** A program kept: what was made for it, and whether its nodes and GPU program are built. */
interface Kept<T> {
  readonly made: T;
  built: boolean;
  building: Promise<void> | null;
}

/**
 * What a table fill made for each of its last KEPT_PASSES programs (a constant and a dispersive
 * film, say), as the GLSL table pass keeps them: going back to a film drawn before builds no node.
 * A program is built in place at its first use (`of`), or ahead of it off the frame (`build`).
 */
export class KeptPrograms<T> {
  private readonly kept = new Map<string, Kept<T>>();

  constructor(private readonly release: (made: T) => void) {}

  /** What was made for `program`, else `make()`'s, kept and (being used now) built; the least recently used beyond the count released. */
  of(program: string, make: () => T): T {
    const kept = this.keep(program, make);
    kept.built = true;
    return kept.made;
  }

  /** Whether `program` is built: used, or its `build` done. */
  isBuilt(program: string): boolean {
    return this.kept.get(program)?.built === true;
  }

  /** Builds `program` (made by `make` if it is not kept) by `compile`, once however often asked: the promise of that build. */
  build(program: string, make: () => T, compile: (made: T) => Promise<void>): Promise<void> {
    const kept = this.keep(program, make);
    if (kept.built) return Promise.resolve();
    return (kept.building ??= compile(kept.made).then(() => void (kept.built = true)));
  }

  /** Releases everything kept. */
  clear(): void {
    for (const { made } of this.kept.values()) this.release(made);
    this.kept.clear();
  }

  private keep(program: string, make: () => T): Kept<T> {
    const known = this.kept.get(program);
    this.kept.delete(program);
    const kept = known ?? { made: make(), built: false, building: null };
    this.kept.set(program, kept);
    for (const [name, old] of this.kept)
      if (this.kept.size > KEPT_PASSES) {
        this.kept.delete(name);
        this.release(old.made);
      }
    return kept;
  }
}
