import type GUI from 'lil-gui';
import type { WebGLRenderer } from 'three';
import { THICKNESS_FIELDS } from '../fields/fields.ts';
import { type Catalogue, EN } from '../i18n/en.ts';
import { message } from '../i18n/messages.ts';
import { type DrawnFrame, resolveFrame, retimed, sameFrame } from '../view/drawnFrame.ts';
import type { FrameReport } from '../view/frameReport.ts';
import type { ViewSettings } from '../settings/viewParameters.ts';
import { addAccessStyles } from './accessStyles.ts';
import type { BubbleAppParts } from './bubbleAppParts.ts';
import { createControlPanel } from './controlPanel.ts';
import { FilmAtProbe } from './filmAtProbe.ts';
import { FrameLoop } from './frameLoop.ts';
import { GovernorSeat } from './governorSeat.ts';
import { onPixelRatioChange } from './pixelRatioChange.ts';
import { listenToProbeInput } from './probeInput.ts';
import { startsClosed } from './startsClosed.ts';
import { StatusLines } from './statusLines.ts';

export type { BubbleAppParts } from './bubbleAppParts.ts';

/**
 * A bubble on a page: the settings asked for, the view that draws them, its controls and plots,
 * and when to draw. The app owns the settings; it resolves them with what the machine and the page
 * offer into the frame the view draws (resolveFrame, src/view/drawnFrame.ts) when either changes,
 * and between changes only retimes that frame while the film animates. Its
 * rooms: FrameLoop (when frames are drawn), GovernorSeat (its place in the page's frame governor),
 * probeInput (the pointer and keys on the bubble), FilmAtProbe (the plots, the probe's ring and
 * the live description), StatusLines (the notices in the page's messages).
 */
export class BubbleApp {
  private gui: GUI | null = null;
  private readonly cat: Catalogue;
  private readonly loop: FrameLoop;
  private readonly film: FilmAtProbe;
  private readonly status: StatusLines;
  private readonly seat: GovernorSeat;
  /** What removes the app's listeners and observers (the rooms' own go with them). */
  private readonly stopListening: () => void;
  /** The surface's size the view was last fitted to. */
  private fitted = '';
  /** The settings asked for, and the frame drawn for them. */
  private asked: ViewSettings;
  private frame!: DrawnFrame; // set by the constructor's resolve

  constructor(
    private readonly parts: BubbleAppParts,
    initial: ViewSettings,
  ) {
    const { view, surface } = parts;
    this.asked = initial;
    this.cat = parts.catalogue ?? EN;
    this.seat = new GovernorSeat(surface.ownerDocument, () => this.choiceChanged());
    addAccessStyles(surface.ownerDocument);
    this.film = new FilmAtProbe({
      view,
      surface,
      plots: parts.plots,
      cat: this.cat,
      frame: () => this.frame,
      looping: () => this.loop.looping,
      filmTime: () => this.seat.filmTimeText(this.cat, 'governor.sentence'),
    });
    this.status = new StatusLines(surface.ownerDocument, parts.messages, this.cat);
    this.resolve();
    this.loop = new FrameLoop(
      view,
      surface,
      () => this.animating,
      { timeSeconds: () => this.asked.timeSeconds, setTimeSeconds: (timeSeconds) => (this.asked = { ...this.asked, timeSeconds }) },
      (now, follows) => this.draw(now, follows),
    );
    view.onEnvironmentChange = () => {
      this.resolve();
      this.redraw();
    };
    this.seat.follow(this.asked, this.animating, view.offers.baseStepsPerFrame);
    this.fit();
    // The GPU compiles the first frame's programs while the panel is built.
    this.loop.start();
    this.buildControls();
    this.stopListening = this.listen();
  }

  /** The settings asked for (the frame may draw others in their place: `drawn`). */
  get current(): ViewSettings {
    return this.asked;
  }

  /** The frame drawn for them: what the view draws, and each substitution with why. */
  get drawn(): DrawnFrame {
    return this.frame;
  }

  get renderer(): WebGLRenderer {
    return this.parts.view.renderer;
  }

  /** Shows new (validated) settings; the panel follows when `rebuildControls`. */
  set(s: ViewSettings, rebuildControls = false): void {
    this.asked = s;
    this.seat.restartRate();
    this.seat.follow(s, this.animating, this.parts.view.offers.baseStepsPerFrame);
    this.resolve();
    this.fit();
    this.film.settingsChanged();
    if (rebuildControls) this.buildControls();
    this.loop.request();
  }

  dispose(): void {
    this.seat.leave();
    this.loop.dispose();
    this.film.dispose();
    this.stopListening();
    this.gui?.destroy();
    this.status.remove();
    this.parts.view.dispose();
  }

  /** Resolves the settings asked for with what the view, the governor and the device offer, and shows the frame (with its notices). */
  private resolve(): DrawnFrame {
    const { view } = this.parts;
    const frame = resolveFrame(this.asked, { ...view.offers, choice: this.seat.choice, devicePixelRatio: globalThis.devicePixelRatio });
    const shown: DrawnFrame | undefined = this.frame;
    if (shown && sameFrame(frame, shown)) return shown;
    this.frame = frame;
    view.show(frame);
    this.status.showNotices(this.frame.notices.flatMap(({ message: m }) => (m ? [message(this.cat, m.key, m.values)] : [])));
    this.status.showEnvironment(this.frame.environment);
    return this.frame;
  }

  /**
   * The frame for an animation frame. The settings and the offers change by events, each of which
   * resolves the frame again (set, the governor's choice, an environment arriving, the device's
   * pixel ratio); between them, a light's transform arriving is the one offer a frame waits for,
   * and the film's time the one setting that moves: the frame shown is kept, retimed.
   */
  private frameNow(): DrawnFrame {
    const { view } = this.parts;
    const pending = this.frame.lightPending;
    if (pending && view.offers.lightReady(pending)) return this.resolve();
    if (this.frame.asked.timeSeconds !== this.asked.timeSeconds) {
      this.frame = retimed(this.frame, this.asked.timeSeconds);
      view.showTime(this.frame);
    }
    return this.frame;
  }

  /** Listens to the user's input on the bubble, to the surface's size and to a restored context; returns what stops it. */
  private listen(): () => void {
    const { view, surface } = this.parts;
    const stopInput = listenToProbeInput({
      surface,
      focusable: this.parts.focusable ?? surface,
      label: this.cat['bubble.label'],
      controls: this.parts.controls ?? null,
      probe: () => this.asked.probe,
      moveProbe: (probe) => this.change({ ...this.asked, probe }),
      blow: (fx, fy, vxPx, vyPx) => view.blow(fx, fy, vxPx, vyPx),
      blowAtProbe: () => this.blowAtProbe(),
      burst: (fx, fy) => view.burst(fx, fy),
      burstAtProbe: () => this.burstAtProbe(),
    });
    const onRestored = () => this.redraw();
    const glCanvas = view.renderer.domElement;
    glCanvas.addEventListener('webglcontextrestored', onRestored);
    const resize = new ResizeObserver(() => this.fit());
    resize.observe(surface);
    const stopPixelRatio = onPixelRatioChange(() => {
      this.resolve();
      this.fit();
    });
    return () => {
      stopInput();
      stopPixelRatio();
      glCanvas.removeEventListener('webglcontextrestored', onRestored);
      resize.disconnect();
    };
  }

  /**
   * One frame of the settings as they are now (the offers may have changed: a light's transform
   * arrived). A frame drawn from a coarse table (FilmTable: the frames after a change complete it),
   * while the HDR environment is on its way, or with a flowing film short of its frozen time is not
   * complete; while the film animates, every frame shows its film time and is. The plots follow a complete frame.
   */
  private draw(now: number, follows: boolean): FrameReport {
    const frame = this.frameNow();
    const report = this.parts.view.render('paced');
    // A shared renderer's canvas holds another view's frame when this one did not draw.
    if (report.drawn) this.parts.present?.();
    if (this.loop.looping) this.seat.drawn(now, report, frame.film.simSpeed, follows);
    const complete = !report.coarse && (!report.film?.behind || this.loop.looping) && frame.environment.state !== 'loading';
    this.film.frameShown(complete);
    this.parts.onFrame?.(complete);
    return report;
  }

  private get animating(): boolean {
    return this.asked.animate && THICKNESS_FIELDS[this.asked.field].animates;
  }

  /** The governor's choice changed: the frame follows it. */
  private choiceChanged(): void {
    this.resolve();
    this.fit();
    this.loop.request();
  }

  /** The user changed the settings (the panel, or the pointer or keys on the bubble). */
  private change(s: ViewSettings): void {
    this.film.userChanged();
    this.set({ ...s, timeSeconds: this.asked.timeSeconds });
    this.parts.onChange?.(this.asked);
  }

  /** Blows on a flowing film at the probe, to the right, five view heights a second (B, or the panel's button). */
  private blowAtProbe(): void {
    const [x, y] = this.asked.probe;
    this.parts.view.blow(x, y, 5 * this.parts.surface.clientHeight, 0);
  }

  /** Bursts a flowing film at the probe (P, or the panel's button). */
  private burstAtProbe(): void {
    this.parts.view.burst(...this.asked.probe);
  }

  /** Builds the panel anew: closed if the one it replaces was, else as the page's CSS says for its size. */
  private buildControls(): void {
    const { controls } = this.parts;
    const closed = this.gui ? this.gui._closed : controls !== undefined && startsClosed(controls, 'panel');
    this.gui?.destroy();
    this.gui = controls
      ? createControlPanel(
          this.asked,
          (s) => this.change(s),
          controls,
          this.cat,
          { blow: () => this.blowAtProbe(), burst: () => this.burstAtProbe() },
          () => this.seat.filmTimeText(this.cat, 'governor.line') ?? '',
        )
      : null;
    if (closed) this.gui?.close();
  }

  /** Sizes the view to the surface at the frame's pixel ratio; a frame follows only if the size changed. */
  private fit(): void {
    const { clientWidth, clientHeight } = this.parts.surface;
    if (clientWidth === 0 || clientHeight === 0) return; // hidden (display: none): nothing to draw
    const { pixelRatio } = this.frame;
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
