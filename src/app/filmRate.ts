/** The film's rate is measured over the animation frames of this long (ms). */
const RATE_WINDOW_MS = 2000;

/**
 * How fast film time goes by against the clock while a view animates: film seconds per second over
 * the last RATE_WINDOW_MS, from the film time each frame shows (1 where it keeps real time at
 * simulation speed 1; less where its steps cannot keep up and the clock waits for it).
 */
export class FilmRate {
  private readonly frames: { readonly now: number; readonly filmSeconds: number }[] = [];

  /** A frame at `now` (ms) showed the film at `filmSeconds`; a film made anew (its time gone back) starts the measure again. */
  frame(now: number, filmSeconds: number): void {
    const last = this.frames.at(-1);
    if (last && (filmSeconds < last.filmSeconds || now <= last.now)) this.frames.length = 0;
    this.frames.push({ now, filmSeconds });
    while (this.frames.length > 2 && now - this.frames[1]!.now >= RATE_WINDOW_MS) this.frames.shift();
  }

  /** The frames measured are not a running film's (it stopped, or its settings changed). */
  reset(): void {
    this.frames.length = 0;
  }

  /** Film seconds per second, or null before two frames. */
  get rate(): number | null {
    const [first, last] = [this.frames[0], this.frames.at(-1)];
    if (!first || !last || last.now === first.now) return null;
    return ((last.filmSeconds - first.filmSeconds) * 1000) / (last.now - first.now);
  }
}
