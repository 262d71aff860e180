/**
 * `say` called at most once per `intervalMs`, with the latest value: the first value goes at once,
 * later ones within the interval wait for its end, and only the last of them is said. `cancel`
 * drops a value still waiting.
 */
export function latestThrottle<T>(say: (value: T) => void, intervalMs: number): { push: (value: T) => void; cancel: () => void } {
  let timer: ReturnType<typeof setTimeout> | null = null;
  let waiting: { value: T } | null = null;
  const open = () => {
    timer = null;
    if (!waiting) return;
    const { value } = waiting;
    waiting = null;
    say(value);
    timer = setTimeout(open, intervalMs);
  };
  return {
    push: (value) => {
      waiting = { value };
      if (!timer) open();
    },
    cancel: () => {
      if (timer) clearTimeout(timer);
      timer = null;
      waiting = null;
    },
  };
}
