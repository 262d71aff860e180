import type GUI from 'lil-gui';
import type { WebGLRenderer } from 'three';
import { THICKNESS_FIELDS } from '../fields/fields.ts';
import { type Catalogue, EN } from '../i18n/en.ts';
import type { BubbleView } from '../scene/bubbleView.ts';
import type { FilmSettings } from '../settings/filmSettings.ts';
import { AUTO } from '../settings/parameterRow.ts';
import { type AppSettings, type GovernedSettings, type ViewSettings, filmSettingsOf, governedValue } from '../settings/viewParameters.ts';
import { message } from '../i18n/messages.ts';
import type { BudgetChoice } from './frameBudget.ts';
import { FilmRate } from './filmRate.ts';
import { type GovernedView, FrameGovernor, devicePixelRatioShown } from './frameGovernor.ts';
import { addAccessStyles } from './accessStyles.ts';
import { createControlPanel } from './controlPanel.ts';
import { FilmAtProbe } from './filmAtProbe.ts';
import { FrameLoop } from './frameLoop.ts';
import { listenToProbeInput } from './probeInput.ts';
import { shownMethod } from './shownMethod.ts';
import { startsClosed } from './startsClosed.ts';
import { StatusLines } from './statusLines.ts';

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
 * A bubble on a page: the view, its controls and plots, and when to draw. Its rooms: FrameLoop
 * (when frames are drawn), probeInput (the pointer and keys on the bubble), FilmAtProbe (the plots,
 * the probe's ring and the live description), StatusLines (the notices in the page's messages).
 */
export class BubbleApp {
  private gui: GUI | null = null;
  private readonly cat: Catalogue;
  private readonly loop: FrameLoop;
  private readonly film: FilmAtProbe;
  private readonly status: StatusLines;
  /** What removes the app's listeners and observers (the rooms' own go with them). */
  private readonly stopListening: () => void;
  /** The surface's size the view was last fitted to. */
  private fitted = '';
  /** The page's own settings and the governed knobs as asked (the view holds the film's, but for the method asked for). */
  private app: AppSettings & GovernedSettings;
  private askedMode: ViewSettings['mode'];
  /** The document's frame governor, this app's place in it while it animates, and its choice then. */
  private readonly governor: FrameGovernor;
  private governed: GovernedView | null = null;
  private choice: BudgetChoice | null = null;
  private readonly filmRate = new FilmRate();

  constructor(
    private readonly parts: BubbleAppParts,
    initial: ViewSettings,
  ) {
    const { view, surface } = parts;
    this.app = appSettingsOf(initial);
    this.askedMode = view.current.mode;
    this.governor = FrameGovernor.of(surface.ownerDocument);
    this.cat = parts.catalogue ?? EN;
    addAccessStyles(surface.ownerDocument);
    this.film = new FilmAtProbe({
      view,
      surface,
      plots: parts.plots,
      cat: this.cat,
      settings: () => this.current,
      looping: () => this.loop.looping,
      filmTime: () => this.filmTimeText('governor.sentence'),
    });
    this.status = new StatusLines(surface.ownerDocument, parts.messages, this.cat);
    this.showMethod(filmSettingsOf(initial));
    this.loop = new FrameLoop(
      view,
      surface,
      () => this.animating,
      (now, follows) => this.draw(now, follows),
    );
    view.onEnvironmentChange = () => this.redraw();
    this.govern();
    this.fit();
    // The GPU compiles the first frame's programs while the panel is built.
    this.loop.start();
    this.buildControls();
    this.stopListening = this.listen();
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
    this.app = appSettingsOf(s);
    this.showMethod(this.filmSettings(s));
    this.filmRate.reset();
    this.govern();
    this.fit();
    this.film.settingsChanged();
    if (rebuildControls) this.buildControls();
    this.loop.request();
  }

  dispose(): void {
    if (this.governed) this.governor.leave(this.governed);
    this.governed = null;
    this.loop.dispose();
    this.film.dispose();
    this.stopListening();
    this.gui?.destroy();
    this.status.remove();
    this.parts.view.onEnvironmentChange = null;
    this.parts.view.dispose();
  }

  /** Listens to the user's input on the bubble, to the surface's size and to a restored context; returns what stops it. */
  private listen(): () => void {
    const { view, surface } = this.parts;
    const stopInput = listenToProbeInput({
      surface,
      focusable: this.parts.focusable ?? surface,
      label: this.cat['bubble.label'],
      controls: this.parts.controls ?? null,
      probe: () => this.current.probe,
      moveProbe: (probe) => this.change({ ...this.current, probe }),
      blow: (fx, fy, vxPx, vyPx) => view.blow(fx, fy, vxPx, vyPx),
      blowAtProbe: () => this.blowAtProbe(),
    });
    const onRestored = () => this.redraw();
    const glCanvas = view.renderer.domElement;
    glCanvas.addEventListener('webglcontextrestored', onRestored);
    const resize = new ResizeObserver(() => this.fit());
    resize.observe(surface);
    return () => {
      stopInput();
      glCanvas.removeEventListener('webglcontextrestored', onRestored);
      resize.disconnect();
    };
  }

  /**
   * One frame, from a coarse table while the table is being rebuilt (FilmTable: the frames after
   * a change complete it). A frame drawn while the HDR environment is on its way, or with a flowing
   * film short of its frozen time, is not complete either. The plots follow a complete frame.
   */
  private draw(now: number, follows: boolean): void {
    const view = this.parts.view;
    // A shared renderer's canvas holds another view's frame when this one did not draw.
    if (view.render(true)) this.parts.present?.();
    const cost = view.takeFrameCost();
    if (this.governed && this.loop.looping) {
      this.governor.drawn(now, { ...cost, settling: view.film.settling }, view.film.flowGrid, follows);
      const filmSeconds = view.film.timeSeconds;
      if (filmSeconds !== null) this.filmRate.frame(now, filmSeconds * view.current.simSpeed);
    }
    this.status.showEnvironment(view.environmentStatus);
    // A flowing film short of a frozen time is not complete (the frames after bring it there); while
    // the film animates, every frame shows its film time and is.
    const complete = !view.coarse && (!view.film.behind || this.loop.looping) && view.environmentStatus.state !== 'loading';
    this.film.frameShown(complete);
    this.parts.onFrame?.(complete);
  }

  /** Gives the view the film settings asked for, or those it draws instead, saying why. */
  private showMethod(film: FilmSettings): void {
    const { settings, notice } = shownMethod(film, this.cat);
    this.askedMode = film.mode;
    this.parts.view.apply(settings);
    this.status.showMethodNotice(notice);
  }

  private get animating(): boolean {
    return this.app.animate && THICKNESS_FIELDS[this.parts.view.current.field].animates;
  }

  /** The film settings the view draws: the governed knobs as asked, else as the governor chose, else their defaults (a frozen view's). */
  private filmSettings(s: ViewSettings): FilmSettings {
    return filmSettingsOf(s, this.choice ? { gridN: this.choice.gridN } : {});
  }

  /**
   * Joins the document's frame governor while the film animates (with what the user fixed), leaves
   * it otherwise: a frozen view draws the same pixels on every machine.
   */
  private govern(): void {
    const { gridN, pixelRatio, simSpeed } = this.app;
    const field = THICKNESS_FIELDS[this.parts.view.current.field];
    const wanted = this.animating
      ? {
          gridN: gridN === AUTO ? undefined : gridN,
          pixelRatio: pixelRatio === AUTO ? undefined : pixelRatio,
          simSpeedGiven: simSpeed !== AUTO,
          flows: field.evolves === true,
          baseStepsPerFrame: this.parts.view.quality.flowStepsPerFrame,
        }
      : null;
    const g = this.governed;
    // The same knobs fixed as before (JSON leaves out `apply`): it stays where it is.
    if (g && wanted && JSON.stringify(g) === JSON.stringify(wanted)) return;
    if (g) this.governor.leave(g);
    this.governed = wanted && { ...wanted, apply: (choice) => this.applyChoice(choice) };
    if (this.governed) this.governor.join(this.governed);
    else this.applyChoice(null);
  }

  /** The governor's choice (null: none, a frozen view) for the knobs the user left: the grid, the steps per frame, the pixel ratio. */
  private applyChoice(choice: BudgetChoice | null): void {
    this.choice = choice;
    const view = this.parts.view;
    const given = this.app.simSpeed !== AUTO;
    view.flowStepsPerFrame = !choice ? view.quality.flowStepsPerFrame : given ? Infinity : choice.stepsPerFrame;
    const film = this.filmSettings(this.current);
    if (film.gridN !== view.current.gridN) {
      this.filmRate.reset();
      this.showMethod(film);
    }
    this.fit();
    this.loop.request();
  }

  /** The film's rate and grid as a text of the catalogue (`key`), or null while it is not governed or not yet measured. */
  private filmTimeText(key: 'governor.line' | 'governor.sentence'): string | null {
    const rate = this.filmRate.rate;
    const grid = this.parts.view.film.flowGrid;
    if (!this.governed || rate === null || !grid) return null;
    return message(this.cat, key, { rate: +rate.toPrecision(2), grid: grid.gridN });
  }

  /** The user changed the settings (the panel, or the pointer or keys on the bubble). */
  private change(s: ViewSettings): void {
    this.film.userChanged();
    this.set({ ...s, timeSeconds: this.current.timeSeconds });
    this.parts.onChange?.(this.current);
  }

  /** Blows on a flowing film at the probe, to the right, five view heights a second (B, or the panel's button). */
  private blowAtProbe(): void {
    const [x, y] = this.app.probe;
    this.parts.view.blow(x, y, 5 * this.parts.surface.clientHeight, 0);
  }

  /** Builds the panel anew: closed if the one it replaces was, else as the page's CSS says for its size. */
  private buildControls(): void {
    const { controls } = this.parts;
    const closed = this.gui ? this.gui._closed : controls !== undefined && startsClosed(controls, 'panel');
    this.gui?.destroy();
    this.gui = controls
      ? createControlPanel(
          this.current,
          (s) => this.change(s),
          controls,
          this.cat,
          () => this.blowAtProbe(),
          () => this.filmTimeText('governor.line') ?? '',
        )
      : null;
    if (closed) this.gui?.close();
  }

  /**
   * Sizes the view to the surface, at the pixel ratio given, else the governor's, else the
   * device's (at most 2); a frame follows only if the size changed.
   */
  private fit(): void {
    const { clientWidth, clientHeight } = this.parts.surface;
    if (clientWidth === 0 || clientHeight === 0) return; // hidden (display: none): nothing to draw
    const pixelRatio = governedValue(this.app.pixelRatio, this.choice?.pixelRatio, devicePixelRatioShown());
    const size = `${clientWidth}×${clientHeight}@${pixelRatio}`;
    if (size === this.fitted) return;
    this.fitted = size;
    this.parts.view.resize(clientWidth, clientHeight, pixelRatio);
    this.redraw();
  }

  /** The view changed under the app (resized, its context restored, its environment arrived): the plots are due, and a frame follows. */
  private redraw(): void {
    this.film.markDue();
    this.loop.request();
  }
}

/** The page's own settings and the governed knobs as asked. */
const appSettingsOf = ({ animate, probe, gridN, simSpeed, pixelRatio }: ViewSettings): AppSettings & GovernedSettings => ({
  animate,
  probe,
  gridN,
  simSpeed,
  pixelRatio,
});
