import { THICKNESS_FIELDS } from '../fields/fields.ts';
import type GUI from 'lil-gui';
import type { WebGLRenderer } from 'three';
import { type Catalogue, EN } from '../i18n/en.ts';
import { PlotPanel } from '../plots/plotPanel.ts';
import { probeDescription } from '../plots/probeDescription.ts';
import { addAccessStyles } from './accessStyles.ts';
import { arrowKeyStep } from './arrowKeyStep.ts';
import { latestThrottle } from './latestThrottle.ts';
import type { BubbleView } from '../scene/bubbleView.ts';
import { createControlPanel } from './controlPanel.ts';
import { environmentStatusText } from './environmentStatusText.ts';
import { shownMethod } from './shownMethod.ts';
import { startsClosed } from './startsClosed.ts';
import type { FilmSettings } from '../settings/filmSettings.ts';
import type { AppSettings, ViewSettings } from '../settings/viewParameters.ts';

/** While the swirl animates, the plots follow the probed film this often. */
const PLOT_INTERVAL_MS = 250;
/** The live description says the film at the probe at most this often (the latest state wins). */
const DESCRIPTION_INTERVAL_MS = 1000;
/** An arrow key moves the probe this far (a fraction of the view; with Shift, five times as far). */
const PROBE_STEP = 0.01;

export interface BubbleAppParts {
  readonly view: BubbleView;
  /**
   * The element the bubble is shown in: its CSS box sizes the view; a press on it (mouse, pen or
   * touch; not on the panel) moves the probe there, and the probe follows while the press drags.
   */
  readonly surface: HTMLElement;
  /** Called after each frame is drawn (e.g. to copy a shared renderer's canvas to the page). */
  readonly present?: () => void;
  /**
   * Where the lil-gui panel goes, if any. It starts closed where the page's CSS says so
   * (startsClosed, read from this element).
   */
  readonly controls?: HTMLElement;
  /** Where the plots go, if any; they are redrawn when this element's box changes (e.g. a drawer opens). */
  readonly plots?: HTMLElement;
  /**
   * Where a line on the HDR environment goes while it loads, or if it failed, and the line saying
   * that the method asked for is drawn with another (shownMethod) (role status; text only).
   */
  readonly messages?: HTMLElement;
  /** Called when the panel or a press on the bubble changes the settings. */
  readonly onChange?: (s: ViewSettings) => void;
  /** Called after every frame; `complete` is false for a frame drawn from a coarse table (another follows). */
  readonly onFrame?: (complete: boolean) => void;
  /**
   * The element that shows the bubble to the user (default `surface`): it takes focus, is labelled
   * (role application), and its arrow keys move the probe.
   */
  readonly focusable?: HTMLElement;
  /** The language of every text the app shows (default English). */
  readonly catalogue?: Catalogue;
}

/**
 * A bubble on a page: the view, its controls and plots, and when to draw. Frames are drawn on
 * demand — one per change — and in a loop only while the swirl animates and the bubble is both
 * on screen (IntersectionObserver) and in a visible page.
 */
export class BubbleApp {
  private gui: GUI | null = null;
  private readonly panel: PlotPanel | null;
  private onScreen = true;
  private pending = 0;
  /** The task that brings the plots up to date after a complete frame, while it is due. */
  private plotTimer = 0;
  /** Whether the last frame drawn was complete (the plots may follow it). */
  private completeShown = false;
  /** Whether the view's programs are compiled (no frame before), and whether the app is disposed. */
  private prepared = false;
  private disposed = false;
  /** The surface's size the view was last fitted to. */
  private fitted = '';
  private looping = false;
  private clockOrigin = 0;
  private plotsDue = true;
  private lastPlotMs = -Infinity;
  /** Whether the plots' probe is waiting for its pixel, and how many times the settings were set (a reading for older ones is dropped). */
  private probing = false;
  private settingsSet = 0;
  private readonly disconnect: () => void;
  /** A ring over the bubble where the probe is (only with plots). */
  private readonly marker: HTMLElement | null;

  /** The line saying that the HDR environment is loading or failed (in `parts.messages`). */
  private readonly environmentLine: HTMLElement;
  /** The live description of the film at the probe (aria-live polite, visually hidden), and its throttle. */
  private readonly live: HTMLElement;
  private readonly say: ReturnType<typeof latestThrottle<string>>;
  /** Whether the user has changed the view (the live description speaks only after that). */
  private describing = false;
  private readonly cat: Catalogue;

  /** The line saying that the view draws with another method than the one asked for (shownMethod). */
  private readonly methodLine: HTMLElement;

  /** The page's own settings (the view holds the film's, but for the method asked for). */
  private app: AppSettings;
  private askedMode: ViewSettings['mode'];

  constructor(
    private readonly parts: BubbleAppParts,
    initial: AppSettings,
  ) {
    this.app = { animate: initial.animate, probe: initial.probe };
    this.askedMode = parts.view.current.mode;
    const doc = parts.surface.ownerDocument;
    this.cat = parts.catalogue ?? EN;
    addAccessStyles(doc);
    this.panel = parts.plots ? new PlotPanel(doc, this.cat) : null;
    if (this.panel) parts.plots!.append(this.panel.element);
    this.marker = this.panel ? parts.surface.ownerDocument.createElement('div') : null;
    if (this.marker) {
      this.marker.className = 'tfb-probe-marker';
      parts.surface.after(this.marker);
    }
    this.environmentLine = doc.createElement('p');
    this.environmentLine.className = 'environment-status';
    this.methodLine = doc.createElement('p');
    this.methodLine.className = 'method-notice';
    this.showMethod(parts.view.current);
    this.live = Object.assign(doc.createElement('p'), { className: 'tfb-live' });
    this.live.setAttribute('aria-live', 'polite');
    parts.surface.after(this.live);
    this.say = latestThrottle((text: string) => (this.live.textContent = text), DESCRIPTION_INTERVAL_MS);
    const focusable = parts.focusable ?? parts.surface;
    focusable.tabIndex = 0;
    focusable.classList.add('tfb-focusable');
    focusable.setAttribute('role', 'application');
    focusable.setAttribute('aria-label', this.cat['bubble.label']);
    parts.view.onEnvironmentChange = () => {
      this.plotsDue = true;
      this.requestFrame();
    };
    this.buildControls();
    const probeAt = (e: PointerEvent) => {
      const box = parts.surface.getBoundingClientRect();
      const probe = [(e.clientX - box.left) / box.width, (e.clientY - box.top) / box.height] as const;
      if (probe.every((v) => v >= 0 && v <= 1)) this.change({ ...this.settings, probe });
    };
    const controls = parts.controls ?? null;
    const onPress = (e: PointerEvent) => {
      if (!e.isPrimary || e.button !== 0 || (e.target instanceof Node && controls?.contains(e.target))) return;
      parts.surface.setPointerCapture(e.pointerId);
      probeAt(e);
    };
    /** The last point of a drag (CSS pixels, ms): a drag blows on a flowing film as fast as it moves. */
    let dragged: { x: number; y: number; t: number } | null = null;
    const onDrag = (e: PointerEvent) => {
      if (!parts.surface.hasPointerCapture(e.pointerId)) return;
      probeAt(e);
      const dt = dragged ? (e.timeStamp - dragged.t) / 1000 : 0;
      if (dragged && dt > 0) {
        const box = parts.surface.getBoundingClientRect();
        const [fx, fy] = [(e.clientX - box.left) / box.width, (e.clientY - box.top) / box.height];
        parts.view.blow(fx, fy, (e.clientX - dragged.x) / dt, (e.clientY - dragged.y) / dt);
      }
      dragged = { x: e.clientX, y: e.clientY, t: e.timeStamp };
    };
    const onRelease = () => (dragged = null);
    const onKey = (e: KeyboardEvent) => {
      if ((e.key === 'b' || e.key === 'B') && !e.altKey && !e.ctrlKey && !e.metaKey) {
        this.blowAtProbe();
        return;
      }
      const move = arrowKeyStep(e, PROBE_STEP);
      if (!move || e.altKey || e.ctrlKey || e.metaKey) return;
      e.preventDefault(); // the arrows move the probe, not the page
      const [x, y] = this.settings.probe;
      const clamp = (v: number) => Math.min(1, Math.max(0, +v.toFixed(4)));
      this.change({ ...this.settings, probe: [clamp(x + move[0]), clamp(y + move[1])] });
    };
    const onVisibility = () => this.wake();
    const onRestored = () => {
      this.plotsDue = true;
      this.requestFrame();
    };
    const glCanvas = parts.view.renderer.domElement;
    glCanvas.addEventListener('webglcontextrestored', onRestored);
    const resize = new ResizeObserver(() => this.fit());
    // The plots' box changed (a drawer opened): the plots follow the frame shown, or the next one.
    const plotsResize = new ResizeObserver(() => {
      this.plotsDue = true;
      if (this.completeShown) this.schedulePlots();
    });
    const onScreen = new IntersectionObserver((entries) => this.setOnScreen(entries.some((e) => e.isIntersecting)));
    parts.surface.addEventListener('pointerdown', onPress);
    parts.surface.addEventListener('pointermove', onDrag);
    parts.surface.addEventListener('pointerup', onRelease);
    focusable.addEventListener('keydown', onKey);
    document.addEventListener('visibilitychange', onVisibility);
    resize.observe(parts.surface);
    onScreen.observe(parts.surface);
    if (parts.plots) plotsResize.observe(parts.plots);
    this.disconnect = () => {
      parts.surface.removeEventListener('pointerdown', onPress);
      parts.surface.removeEventListener('pointermove', onDrag);
      parts.surface.removeEventListener('pointerup', onRelease);
      focusable.removeEventListener('keydown', onKey);
      document.removeEventListener('visibilitychange', onVisibility);
      glCanvas.removeEventListener('webglcontextrestored', onRestored);
      resize.disconnect();
      plotsResize.disconnect();
      onScreen.disconnect();
    };
    this.fit();
    // The first frame waits for the programs, compiled while the page goes on (BubbleView.prepare).
    void parts.view.prepare().then(() => {
      if (this.disposed) return;
      this.prepared = true;
      this.requestFrame();
    });
  }

  /** The settings asked for (the view may draw another method: shownMethod). */
  get current(): ViewSettings {
    return { ...this.parts.view.current, mode: this.askedMode, ...this.app };
  }

  get renderer(): WebGLRenderer {
    return this.parts.view.renderer;
  }

  /** Shows new (validated) settings; the panel follows when `rebuildControls`. */
  set(s: ViewSettings, rebuildControls = false): void {
    const { animate, probe, ...film } = s;
    this.app = { animate, probe };
    this.showMethod(film);
    this.settingsSet++;
    this.completeShown = false;
    this.plotsDue = true;
    if (rebuildControls) this.buildControls();
    this.requestFrame();
  }

  /** Whether the bubble is on screen (an IntersectionObserver's verdict). */
  private setOnScreen(visible: boolean): void {
    if (visible === this.onScreen) return;
    this.onScreen = visible;
    this.wake();
  }

  /**
   * One frame, from a coarse table while the table is being rebuilt (FilmTable: the frames after
   * a change complete it). A frame drawn while the HDR environment is on its way, or with a flowing
   * film short of its frozen time, is not complete either. The plots follow a complete frame in a task of their own, so the frame is shown first.
   */
  private draw(): void {
    const view = this.parts.view;
    view.render(true);
    this.parts.present?.();
    this.showEnvironmentStatus();
    // A flowing film short of a frozen time is not complete (the frames after bring it there); while
    // the film animates, every frame shows its film time and is.
    const complete = !view.coarse && (!view.filmBehind || this.looping) && view.environmentStatus.state !== 'loading';
    this.completeShown = complete;
    if (complete) this.schedulePlots();
    this.parts.onFrame?.(complete);
  }

  /** Brings the plots up to date in a task of their own, after the complete frame shown. */
  private schedulePlots(): void {
    if (this.plotTimer) return;
    const drawn = this.parts.view.current;
    this.plotTimer = window.setTimeout(() => {
      this.plotTimer = 0;
      // Settings changed since (an input event came first): their own complete frame will do it.
      if (this.completeShown && this.parts.view.current === drawn) this.updatePlots(performance.now());
    });
  }

  dispose(): void {
    this.disposed = true;
    cancelAnimationFrame(this.pending);
    clearTimeout(this.plotTimer);
    this.looping = false;
    this.disconnect();
    this.gui?.destroy();
    this.panel?.element.remove();
    this.marker?.remove();
    this.environmentLine.remove();
    this.methodLine.remove();
    this.say.cancel();
    this.live.remove();
    this.parts.view.onEnvironmentChange = null;
    this.parts.view.dispose();
  }

  /** Gives the view the film settings asked for, or those it draws instead, saying why (as text, never HTML). */
  private showMethod(film: FilmSettings): void {
    const { settings, notice } = shownMethod(film, this.cat);
    this.askedMode = film.mode;
    this.parts.view.apply(settings);
    const line = this.methodLine;
    if (notice === null || !this.parts.messages) {
      line.remove();
      return;
    }
    line.textContent = notice;
    if (line.parentElement !== this.parts.messages) this.parts.messages.append(line);
  }

  /** Says (as text, never HTML) that the HDR environment is loading or failed, or removes the line once it shows. */
  private showEnvironmentStatus(): void {
    const status = this.parts.view.environmentStatus;
    const line = this.environmentLine;
    if (status.state === 'shown' || !this.parts.messages) {
      line.remove();
      return;
    }
    line.dataset.state = status.state;
    line.textContent = environmentStatusText(status, this.cat);
    if (line.parentElement !== this.parts.messages) this.parts.messages.append(line);
  }

  /** The settings shown. */
  private get settings(): ViewSettings {
    return this.current;
  }

  private get showing(): boolean {
    return this.onScreen && !document.hidden;
  }

  private get animating(): boolean {
    return this.settings.animate && THICKNESS_FIELDS[this.settings.field].animates;
  }

  private change(s: ViewSettings): void {
    this.describing = true;
    this.set({ ...s, timeSeconds: this.settings.timeSeconds });
    this.parts.onChange?.(this.settings);
  }

  /** Blows on a flowing film at the probe, to the right, five view heights a second (B, or the panel's button). */
  private blowAtProbe(): void {
    const [x, y] = this.settings.probe;
    this.parts.view.blow(x, y, 5 * this.parts.surface.clientHeight, 0);
  }

  /** Builds the panel anew: closed if the one it replaces was, else as the page's CSS says for its size. */
  private buildControls(): void {
    const { controls } = this.parts;
    const closed = this.gui ? this.gui._closed : controls !== undefined && startsClosed(controls, 'panel');
    this.gui?.destroy();
    this.gui = controls
      ? createControlPanel(
          this.settings,
          (s) => this.change(s),
          controls,
          this.cat,
          () => this.blowAtProbe(),
        )
      : null;
    if (closed) this.gui?.close();
  }

  /** Sizes the view to the surface; a frame follows only if the size changed. */
  private fit(): void {
    const { clientWidth, clientHeight } = this.parts.surface;
    if (clientWidth === 0 || clientHeight === 0) return; // hidden (display: none): nothing to draw
    const pixelRatio = Math.min(2, globalThis.devicePixelRatio || 1);
    const size = `${clientWidth}×${clientHeight}@${pixelRatio}`;
    if (size === this.fitted) return;
    this.fitted = size;
    this.parts.view.resize(clientWidth, clientHeight, pixelRatio);
    this.plotsDue = true;
    this.requestFrame();
  }

  /** Restarts drawing when the bubble becomes visible again. */
  private wake(): void {
    if (this.showing) this.requestFrame();
  }

  private requestFrame(): void {
    if (this.pending || !this.showing || !this.prepared) return;
    this.pending = requestAnimationFrame((now) => this.frame(now));
  }

  private frame(now: number): void {
    this.pending = 0;
    if (!this.showing) {
      this.looping = false;
      return;
    }
    if (this.animating) {
      if (!this.looping) this.clockOrigin = now - this.settings.timeSeconds * 1000;
      this.looping = true;
      this.parts.view.apply({ ...this.parts.view.current, timeSeconds: (now - this.clockOrigin) / 1000 });
    } else {
      this.looping = false;
    }
    this.draw();
    const view = this.parts.view;
    const filmTime = view.filmTimeSeconds;
    if (this.looping && view.filmBehind && filmTime !== null) {
      // A film simulated slower than the clock: the clock waits for it, so the time shown (and a
      // pause's frozen time) is the film's, with nothing to catch up.
      this.clockOrigin = now - filmTime * 1000;
      view.apply({ ...view.current, timeSeconds: filmTime });
    }
    if (this.looping || view.coarse || view.filmBehind) this.requestFrame();
  }

  /**
   * Probes the frame shown and, when its pixel is back (a frame or two later), redraws the plots
   * for it, unless the settings changed meanwhile; one probe at a time. Once the user has changed
   * the view, the live description follows the same reading.
   */
  private updatePlots(now: number): void {
    const panel = this.panel;
    const changed = this.plotsDue;
    const due = changed || (this.looping && now - this.lastPlotMs > PLOT_INTERVAL_MS);
    if ((!panel && !this.describing) || this.probing || this.parts.view.contextLost || !due) return;
    const s = this.settings;
    const set = this.settingsSet;
    const [fx, fy] = s.probe;
    if (this.marker) {
      const { offsetLeft, offsetTop, clientWidth, clientHeight } = this.parts.surface;
      Object.assign(this.marker.style, { left: `${offsetLeft + fx * clientWidth}px`, top: `${offsetTop + fy * clientHeight}px` });
    }
    this.plotsDue = false;
    this.lastPlotMs = now;
    this.probing = true;
    this.parts.view
      .probe(fx, fy)
      .then(
        (reading) => {
          if (this.disposed || set !== this.settingsSet) return;
          panel?.update(s, s.probe, reading, this.parts.view.displayIsP3);
          // Said after the user's changes only, not on each animation step (a screen reader would never rest).
          if (this.describing && changed) this.say.push(probeDescription(s, s.probe, reading, this.cat));
        },
        // The context was lost before the pixel came back: the plots follow the restored view.
        () => (this.plotsDue = true),
      )
      .finally(() => {
        this.probing = false;
        // Settings set meanwhile, their complete frame shown already: their plots are still due.
        if (!this.disposed && this.plotsDue && this.completeShown) this.schedulePlots();
      });
  }
}
