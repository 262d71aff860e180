/**
 * A module loaded apart from the entry that needs it (a chunk of its own in a user's build), once,
 * the first time it is asked for; until then, and while it loads, `loaded` is null.
 */
export interface LazyModule<T> {
  /** Loads the module, once: the same promise for every call. */
  readonly load: () => Promise<T>;
  /** The module where it is loaded, else null. */
  readonly loaded: () => T | null;
}

/** `importer`: `() => import('./module.ts')`, written where bundlers find it. */
export function lazyModule<T>(importer: () => Promise<T>): LazyModule<T> {
  let module: T | null = null;
  let loading: Promise<T> | null = null;
  return {
    load: () => (loading ??= importer().then((m) => (module = m))),
    loaded: () => module,
  };
}
