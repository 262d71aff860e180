import type { BubbleView } from '../view/bubbleView.ts';
import type { FrameReport } from '../view/frameReport.ts';

/** The film's time (s) as the app asks for it: read when the clock starts, set as it runs. */
export interface FilmClock {
  readonly timeSeconds: () => number;
  readonly setTimeSeconds: (t: number) => void;
}

/**
 * When a view draws. Frames are drawn on demand — one per request — and in a loop only while the
 * film animates, the table is coarse (the frames after a change complete it: FilmTable) or a
 * flowing film is short of its time; and only while the surface is on screen (IntersectionObserver)
 * in a visible page. Nothing is drawn before `start` has the view's programs compiled
 * (BubbleView.prepare). While the film animates, its time follows the clock.
 */
export class FrameLoop {
  private pending = 0;
  private onScreen = true;
  private prepared = false;
  private disposed = false;
  /** Whether the film's time follows the clock, and the clock's time (ms) at the film's time 0. */
  private clockRunning = false;
  private clockOrigin = 0;
  private readonly screen: IntersectionObserver;
  private readonly onVisibility = () => {
    // A hidden page draws nothing: shown again, the film goes on from the time it showed.
    if (document.hidden) this.clockRunning = false;
    this.wake();
  };

  /**
   * `animating` says whether the film's time should follow the clock, which sets the app's film
   * time (`clock`); `draw` draws one frame at the animation frame's time `now` (ms) and reports it,
   * `follows` saying whether the film's time followed the clock in this loop's frame just before
   * too (the time between is then a frame's).
   */
  constructor(
    private readonly view: Pick<BubbleView, 'prepare'>,
    surface: HTMLElement,
    private readonly animating: () => boolean,
    private readonly clock: FilmClock,
    private readonly draw: (now: number, follows: boolean) => FrameReport,
  ) {
    this.screen = new IntersectionObserver((entries) => this.setOnScreen(entries.some((e) => e.isIntersecting)));
    this.screen.observe(surface);
    document.addEventListener('visibilitychange', this.onVisibility);
  }

  /** Whether the film's time follows the clock (each frame then shows its film time, and is complete for it). */
  get looping(): boolean {
    return this.clockRunning;
  }

  /** Compiles the view's programs while the page goes on; the first frame follows. */
  start(): void {
    void this.view.prepare().then(() => {
      if (this.disposed) return;
      this.prepared = true;
      this.request();
    });
  }

  /** A frame follows, if the bubble is shown and its programs are ready (a frame already asked for will do). */
  request(): void {
    if (this.pending || !this.showing || !this.prepared) return;
    this.pending = requestAnimationFrame((now) => this.frame(now));
  }

  dispose(): void {
    this.disposed = true;
    cancelAnimationFrame(this.pending);
    this.clockRunning = false;
    this.screen.disconnect();
    document.removeEventListener('visibilitychange', this.onVisibility);
  }

  private get showing(): boolean {
    return this.onScreen && !document.hidden;
  }

  /** Whether the bubble is on screen (an IntersectionObserver's verdict). */
  private setOnScreen(visible: boolean): void {
    if (visible === this.onScreen) return;
    this.onScreen = visible;
    this.wake();
  }

  /** Restarts drawing when the bubble becomes visible again. */
  private wake(): void {
    if (this.showing) this.request();
  }

  private frame(now: number): void {
    this.pending = 0;
    if (!this.showing) {
      this.clockRunning = false;
      return;
    }
    const follows = this.clockRunning;
    if (this.animating()) {
      if (!this.clockRunning) this.clockOrigin = now - this.clock.timeSeconds() * 1000;
      this.clockRunning = true;
      this.clock.setTimeSeconds((now - this.clockOrigin) / 1000);
    } else {
      this.clockRunning = false;
    }
    const report = this.draw(now, follows && this.clockRunning);
    const film = report.film;
    const behind = film?.behind === true;
    if (this.clockRunning && film?.behind) {
      // A film simulated slower than the clock: the clock waits for it, so the time shown (and a
      // pause's frozen time) is the film's, with nothing to catch up.
      this.clockOrigin = now - film.timeSeconds * 1000;
      this.clock.setTimeSeconds(film.timeSeconds);
    }
    if (this.clockRunning || report.coarse || behind) this.request();
  }
}
