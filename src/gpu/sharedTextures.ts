/**
 * Textures (or other GPU resources: the spectral iridescence's film tables) shared by their
 * holders (materials, table passes): holders asking for the same key share one texture (several
 * bubbles on a page upload it once), and a texture no holder uses any more is disposed, so a long
 * session of light changes keeps only the textures in use.
 */
export class SharedTextures<T extends { dispose(): void }> {
  private readonly entries = new Map<string, { readonly texture: T; readonly holders: Set<object> }>();
  /** The key each holder uses, so asking for another lets go of the old texture. */
  private readonly heldKey = new WeakMap<object, string>();

  constructor(private readonly create: (key: string) => T) {}

  /** The texture for `key`, held by `holder` until it asks for another or calls `release`. */
  hold(key: string, holder: object): T {
    const previous = this.heldKey.get(holder);
    if (previous !== key) {
      if (previous !== undefined) this.letGo(holder, previous);
      this.heldKey.set(holder, key);
    }
    let entry = this.entries.get(key);
    if (!entry) {
      entry = { texture: this.create(key), holders: new Set() };
      this.entries.set(key, entry);
    }
    entry.holders.add(holder);
    return entry.texture;
  }

  /** Whether some holder holds the texture for `key` (`hold` would not create it). */
  has(key: string): boolean {
    return this.entries.has(key);
  }

  /** `holder` needs no texture from here any more (it is disposed, or its method needs none). */
  release(holder: object): void {
    const key = this.heldKey.get(holder);
    if (key === undefined) return;
    this.heldKey.delete(holder);
    this.letGo(holder, key);
  }

  private letGo(holder: object, key: string): void {
    const entry = this.entries.get(key);
    if (!entry) return;
    entry.holders.delete(holder);
    if (entry.holders.size > 0) return;
    entry.texture.dispose();
    this.entries.delete(key);
  }
}
