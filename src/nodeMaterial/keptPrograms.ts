import { KEPT_PASSES } from '../film/keptPasses.ts';

/**
 * What a table fill made for each of its last KEPT_PASSES programs (a constant and a dispersive
 * film, say), as the GLSL table pass keeps them: going back to a film drawn before builds no node.
 */
export class KeptPrograms<T> {
  private readonly kept = new Map<string, T>();

  constructor(private readonly release: (made: T) => void) {}

  /** What was made for `program`, else `make()`'s, kept; the least recently used beyond the count released. */
  of(program: string, make: () => T): T {
    const known = this.kept.get(program);
    this.kept.delete(program);
    const made = known ?? make();
    this.kept.set(program, made);
    for (const [name, old] of this.kept)
      if (this.kept.size > KEPT_PASSES) {
        this.kept.delete(name);
        this.release(old);
      }
    return made;
  }

  /** Releases everything kept. */
  clear(): void {
    for (const made of this.kept.values()) this.release(made);
    this.kept.clear();
  }
}
