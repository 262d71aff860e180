import type { Catalogue } from '../i18n/en.ts';
import { PlotPanel } from '../plots/plotPanel.ts';
import { probeDescription } from '../plots/probeDescription.ts';
import type { BubbleView } from '../view/bubbleView.ts';
import type { DrawnFrame } from '../view/drawnFrame.ts';
import { LiveDescription } from './liveDescription.ts';

/** While the swirl animates, the plots follow the probed film this often. */
const PLOT_INTERVAL_MS = 250;

export interface FilmAtProbeParts {
  readonly view: BubbleView;
  /** The element the bubble is shown in: the probe's ring and the live description are placed after it. */
  readonly surface: HTMLElement;
  /** Where the plots go, if any; they are redrawn when this element's box changes (e.g. a drawer opens). */
  readonly plots: HTMLElement | undefined;
  readonly cat: Catalogue;
  /** The frame drawn: the settings asked for (with the probe) and the film drawn for them. */
  readonly frame: () => DrawnFrame;
  /** Whether the film's time follows the clock (FrameLoop.looping): the plots then follow it every PLOT_INTERVAL_MS. */
  readonly looping: () => boolean;
  /** A sentence on the film's time against the clock and its grid while the frame governor keeps them (the live description adds it), or null. */
  readonly filmTime?: () => string | null;
}

/**
 * What the app shows of the film at the probe: the plots (where it has a place for them), a ring
 * over the bubble where the probe is (with the plots), and the live description (once the user
 * has changed the view). They follow a complete frame in a task of their own, so the frame is
 * shown first, from the probe's pixel of that frame (BubbleView.probe, back a frame or two later),
 * one reading at a time; a reading for settings set since is dropped.
 */
export class FilmAtProbe {
  private readonly panel: PlotPanel | null;
  private readonly marker: HTMLElement | null;
  private readonly live: LiveDescription;
  private readonly plotsResize: ResizeObserver | null;
  /** The task that brings the plots up to date after a complete frame, while it is due. */
  private timer = 0;
  /** Whether the last frame drawn was complete (the plots may follow it). */
  private completeShown = false;
  /** Whether the plots are due for the frame shown, and when (ms) they were last brought up to date. */
  private due = true;
  private lastMs = -Infinity;
  /** Whether a reading is on its way, and how many times the settings were set (a reading for older ones is dropped). */
  private probing = false;
  private settingsSet = 0;
  private disposed = false;

  constructor(private readonly parts: FilmAtProbeParts) {
    const { surface, plots, cat } = parts;
    const doc = surface.ownerDocument;
    this.panel = plots ? new PlotPanel(doc, cat) : null;
    if (this.panel) plots!.append(this.panel.element);
    this.marker = this.panel ? Object.assign(doc.createElement('div'), { className: 'tfb-probe-marker' }) : null;
    if (this.marker) surface.after(this.marker);
    this.live = new LiveDescription(surface);
    // The plots' box changed (a drawer opened): the plots follow the frame shown, or the next one.
    this.plotsResize = plots
      ? new ResizeObserver(() => {
          this.due = true;
          if (this.completeShown) this.schedule();
        })
      : null;
    if (plots) this.plotsResize!.observe(plots);
  }

  /** The user changed the view: from now on the live description speaks. */
  userChanged(): void {
    this.live.start();
  }

  /** The frame shown is out of date for the plots (a resize, a restored context, the environment arrived): they follow the next complete one. */
  markDue(): void {
    this.due = true;
  }

  /** New settings: the plots wait for their complete frame, and a reading for the old ones is dropped. */
  settingsChanged(): void {
    this.settingsSet++;
    this.completeShown = false;
    this.due = true;
  }

  /** A frame was drawn; a complete one (not from a coarse table, environment shown, film at its time) is followed. */
  frameShown(complete: boolean): void {
    this.completeShown = complete;
    if (complete) this.schedule();
  }

  dispose(): void {
    this.disposed = true;
    clearTimeout(this.timer);
    this.plotsResize?.disconnect();
    this.panel?.element.remove();
    this.marker?.remove();
    this.live.remove();
  }

  /** Brings the plots up to date in a task of their own, after the complete frame shown. */
  private schedule(): void {
    if (this.timer) return;
    this.timer = window.setTimeout(() => {
      this.timer = 0;
      // Settings set since and their complete frame not shown yet (an input event came first): that frame will do it.
      if (this.completeShown) this.update(performance.now());
    });
  }

  /** Reads the probe of the frame shown, if the plots are due (or the film animates and their interval has passed). */
  private update(now: number): void {
    const changed = this.due;
    const due = changed || (this.parts.looping() && now - this.lastMs > PLOT_INTERVAL_MS);
    if ((!this.panel && !this.live.started) || this.probing || this.parts.view.contextLost || !due) return;
    const frame = this.parts.frame();
    this.placeMarker(frame.asked.probe);
    this.due = false;
    this.lastMs = now;
    this.probing = true;
    this.read(frame, changed);
  }

  private placeMarker([fx, fy]: readonly [number, number]): void {
    if (!this.marker) return;
    const { offsetLeft, offsetTop, clientWidth, clientHeight } = this.parts.surface;
    Object.assign(this.marker.style, { left: `${offsetLeft + fx * clientWidth}px`, top: `${offsetTop + fy * clientHeight}px` });
  }

  /** Shows the probe's reading for the frame when it is back, unless the settings were set again meanwhile. */
  private read({ asked: s, film: drawn, field, displayP3 }: DrawnFrame, changed: boolean): void {
    const set = this.settingsSet;
    const { view, cat } = this.parts;
    view
      .probe(...s.probe)
      .then(
        (reading) => {
          if (this.disposed || set !== this.settingsSet) return;
          // The film as drawn (its governed knobs as the frame has them), under the method asked for.
          const film = { ...drawn, mode: s.mode };
          this.panel?.update(film, field.maxThicknessNm, s.probe, reading, displayP3);
          // Said after the user's changes only, not on each animation step (a screen reader would never rest).
          const filmTime = this.parts.filmTime?.() ?? null;
          const said = probeDescription(film, s.probe, reading, cat);
          if (this.live.started && changed) this.live.say(filmTime ? `${said} ${filmTime}` : said);
        },
        // The context was lost before the pixel came back: the plots follow the restored view.
        () => (this.due = true),
      )
      .finally(() => {
        this.probing = false;
        // Settings set meanwhile, their complete frame shown already: their plots are still due.
        if (!this.disposed && this.due && this.completeShown) this.schedule();
      });
  }
}
