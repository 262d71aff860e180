import { Material } from 'three';

/** three's hooks on a material that the film takes part in. */
const HOOK_NAMES = ['onBeforeCompile', 'customProgramCacheKey', 'onBeforeRender'] as const;
type HookName = (typeof HOOK_NAMES)[number];
type Hook = (...args: unknown[]) => unknown;

/** What the film does in each hook, after the user's: its edit of the shader, its program key, its update before a draw. */
export interface FilmHooks {
  readonly onBeforeCompile: Material['onBeforeCompile'];
  /** the whole program key, given the user's */
  readonly customProgramCacheKey: (userKey: string) => string;
  readonly onBeforeRender: Material['onBeforeRender'];
}

/**
 * Puts the film into three's hooks on `m`, each as an accessor: setting one sets the user's (the
 * hooks `m` already had are the user's first ones); reading one gives the user's, then the film's.
 * So a user's onBeforeCompile edits three's shader as written, then the film is written in; and a
 * user who chains by three's idiom (reads the hook, sets one that calls what it read) keeps every
 * earlier hook: a call from inside another of the same hook is the user's part only, and the
 * film's runs once, when the outermost returns. three's default program key (the text of
 * onBeforeCompile) is taken from the user's onBeforeCompile, not from ours.
 */
export function chainHooks(m: Material, film: FilmHooks): void {
  // Unbound: only compared with the hooks a user sets.
  // eslint-disable-next-line @typescript-eslint/unbound-method
  const threeKey = Material.prototype.customProgramCacheKey as Hook;
  const user = {} as Record<HookName, Hook>;
  const userKeyOfThree: Hook = () => user.onBeforeCompile.toString();
  const setUser = (name: HookName, f: Hook) => (user[name] = name === 'customProgramCacheKey' && f === threeKey ? userKeyOfThree : f);
  const finish: Record<HookName, (result: unknown, args: unknown[]) => unknown> = {
    onBeforeCompile: (_, args) => film.onBeforeCompile(...(args as Parameters<FilmHooks['onBeforeCompile']>)),
    customProgramCacheKey: (key) => film.customProgramCacheKey(key as string),
    onBeforeRender: (_, args) => film.onBeforeRender(...(args as Parameters<FilmHooks['onBeforeRender']>)),
  };
  for (const name of HOOK_NAMES) {
    // Unbound: each is called on `m` (apply below), and three's default program key is onBeforeCompile's own text.
    // eslint-disable-next-line @typescript-eslint/unbound-method
    setUser(name, m[name] as Hook);
    let depth = 0;
    const chained = new WeakMap<Hook, Hook>();
    const chain = (hook: Hook): Hook => {
      const known = chained.get(hook);
      if (known) return known;
      const f: Hook = (...args) => {
        depth++;
        let result: unknown;
        try {
          result = hook.apply(m, args);
        } finally {
          depth--;
        }
        return depth === 0 ? finish[name](result, args) : result;
      };
      chained.set(hook, f);
      return f;
    };
    Object.defineProperty(m, name, { configurable: true, get: () => chain(user[name]), set: (f: Hook) => setUser(name, f) });
  }
}
