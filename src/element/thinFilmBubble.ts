import { addPlotStyles } from '../plots/plotStyles.ts';
import { BubbleApp } from '../app/bubbleApp.ts';
import { hasWebGL2, showCpuFallback } from '../app/cpuFallback.ts';
import { parseSettings, refusalText, settingsToQuery } from '../settings/settingsQuery.ts';
import { prefersReducedMotion } from '../app/pagePreferences.ts';
import type { Catalogue } from '../i18n/en.ts';
import { catalogueFor, catalogueLang } from '../i18n/messages.ts';
import { startsClosed } from '../app/startsClosed.ts';
import { DEFAULT_VIEW_SETTINGS, VIEW_PARAMETERS, type ViewSettings, filmSettingsOf } from '../settings/viewParameters.ts';
import { BubbleView } from '../view/bubbleView.ts';
import type { DrawnFrame } from '../view/drawnFrame.ts';
import { THICKNESS_FIELDS } from '../fields/fields.ts';
import type { ProbedFilm } from '../view/probe.ts';
import { acquireSharedRenderer, releaseSharedRenderer } from './sharedRenderer.ts';
import { FrameCanvases } from './frameCanvases.ts';

/**
 * The element's layout. It is a size container: narrower than 800 px (the plots column, 270 px,
 * beside a stage of 530 px) the plots become a drawer over the stage's bottom left that starts
 * closed; a stage narrower than 900 px or shorter than 600 px (the demo's breakpoints, index.html)
 * starts with the panel closed; so neither covers the bubble's centre (src/app/startsClosed.ts reads the
 * `--tfb-*-start` properties). A horizontal drag on the stage moves the probe, a vertical one
 * scrolls the page.
 */
/** While the film animates, the probe's film is read (and `probechange` sent) at most this often. */
const PROBE_INTERVAL_MS = 250;

const STYLE = `
thin-film-bubble { display: block; position: relative; width: 100%; height: 360px; background: #111; color: #eee; overflow: hidden;
  container: tfb / inline-size; }
thin-film-bubble .tfb-layout { position: relative; display: flex; width: 100%; height: 100%; }
thin-film-bubble .tfb-stage { position: relative; flex: 1 1 auto; min-width: 0; container: tfb-stage / size; touch-action: pan-y pinch-zoom; }
thin-film-bubble .tfb-stage > canvas { position: absolute; inset: 0; width: 100%; height: 100%; display: block; }
thin-film-bubble .tfb-controls { position: absolute; top: 0; right: 0; max-width: 100%; max-height: 100%; overflow: auto; }
thin-film-bubble .tfb-controls > .lil-gui { max-width: 100%; }
thin-film-bubble .tfb-side { flex: 0 0 270px; box-sizing: border-box; overflow: auto; padding: 4px 6px; background: #18181c; }
thin-film-bubble .tfb-side:not([open]) { flex-basis: auto; }
thin-film-bubble .tfb-side > summary { cursor: pointer; color: #bbb; padding: 2px 0; font: 12px system-ui, sans-serif; }
@container tfb (max-width: 799px) {
  thin-film-bubble .tfb-side { --tfb-plots-start: closed; position: absolute; left: 0; bottom: 0; width: min(270px, 100%); max-height: 100%;
    background: rgba(24, 24, 28, 0.9); border-top-right-radius: 6px; }
  thin-film-bubble .tfb-layout:has(> .tfb-side) .tfb-messages { bottom: 28px; }
}
@container tfb-stage (max-width: 899px) or (max-height: 599px) {
  thin-film-bubble .tfb-controls { --tfb-panel-start: closed; }
}
thin-film-bubble .cpu-fallback { margin: 0; height: 100%; display: flex; flex-direction: column; align-items: center; font: 12px system-ui, sans-serif; }
thin-film-bubble .cpu-fallback canvas { flex: 1 1 auto; min-height: 0; max-width: 100%; aspect-ratio: 1; }
thin-film-bubble .tfb-messages { position: absolute; left: 4px; bottom: 4px; right: 4px; font: 12px system-ui, sans-serif; }
thin-film-bubble .tfb-messages p { margin: 2px 0; padding: 3px 6px; background: #6b1d1d; border-radius: 3px; }
thin-film-bubble .tfb-messages p[data-state='loading'] { background: #1d3b6b; }
`;

function addElementStyles(doc: Document): void {
  if (doc.getElementById('tfb-element-styles')) return;
  const style = Object.assign(doc.createElement('style'), { id: 'tfb-element-styles', textContent: STYLE });
  doc.head.prepend(style); // first, so the page's own rules win
}

/**
 * `<thin-film-bubble>`: an embeddable bubble. Its attributes are the demo's URL parameters
 * (thickness, field, nFilm, illuminant, …, probe), plus `controls` (show the panel) and
 * `plots` (show the plots). It sizes to its CSS box, draws nothing while off screen or in a
 * hidden page, and frees its GPU resources when removed. A bad attribute is named, with its
 * range, in a message inside the element, and its default (or last good) value is kept.
 * Events: `change` (detail: { settings, query }) when its panel or a press on the bubble changes the view;
 * `probechange` (detail: { thicknessNm, angleDeg }) when the film at the probe changes (after a
 * complete frame; while the film animates, at most every PROBE_INTERVAL_MS), also read as `probeReading`.
 * With `space` display-p3 or wide-gamut, where the browser offers it, the bubble is shown in Display P3 (FrameCanvases).
 */
export class ThinFilmBubble extends HTMLElement {
  static readonly observedAttributes = [...VIEW_PARAMETERS.map((row) => row.attribute), 'controls', 'plots', 'lang'];
  private app: BubbleApp | null = null;
  private canvas: HTMLCanvasElement | null = null;
  private messages: HTMLElement | null = null;
  /** Whether the element is built (live, or as the CPU image without WebGL2). */
  private built = false;
  private probed: ProbedFilm | null = null;
  /** What the last probe reading was taken of (the view's film settings and the probe), and when. */
  private probedOf: readonly [unknown, unknown, number] = [null, null, -Infinity];

  /** The film at the probe as last drawn: its thickness and θ_i (null before a frame, off the bubble, or without WebGL2). */
  get probeReading(): ProbedFilm | null {
    return this.probed;
  }

  /**
   * The shared renderer's live GPU objects (three's renderer.info), for pages that watch memory;
   * null without a live view.
   */
  get gpuResources(): { geometries: number; textures: number; programs: number } | null {
    if (!this.app) return null;
    const { memory, programs } = this.app.renderer.info;
    return { geometries: memory.geometries, textures: memory.textures, programs: programs?.length ?? 0 };
  }

  /** The settings shown now (null before the element is on a page). */
  get settings(): ViewSettings | null {
    return this.app?.current ?? null;
  }

  /** The language asked for: the element's own `lang`, an ancestor's, or the page's. */
  private get catalogue(): Catalogue {
    return catalogueFor(this.closest('[lang]')?.getAttribute('lang') ?? this.ownerDocument.documentElement.lang);
  }

  connectedCallback(): void {
    if (this.built) return;
    const cat = this.catalogue;
    this.built = true;
    addElementStyles(this.ownerDocument);
    addPlotStyles(this.ownerDocument);
    const el = (tag: string, className: string) => Object.assign(this.ownerDocument.createElement(tag), { className });
    const layout = el('div', 'tfb-layout');
    const stage = el('div', 'tfb-stage');
    this.canvas = el('canvas', '') as HTMLCanvasElement;
    this.messages = el('div', 'tfb-messages');
    this.messages.setAttribute('role', 'status');
    this.messages.setAttribute('aria-label', cat['app.messages']);
    layout.lang = catalogueLang(this.closest('[lang]')?.getAttribute('lang') ?? this.ownerDocument.documentElement.lang);
    stage.append(this.canvas, this.messages);
    layout.append(stage);
    const controls = this.hasAttribute('controls') ? el('div', 'tfb-controls') : undefined;
    if (controls) stage.append(controls);
    const plots = this.hasAttribute('plots') ? (el('details', 'tfb-side') as HTMLDetailsElement) : undefined;
    if (plots) {
      plots.append(Object.assign(el('summary', ''), { textContent: cat['bubble.plotsSummary'] }));
      layout.append(plots);
    }
    this.replaceChildren(layout);
    if (plots) plots.open = !startsClosed(plots, 'plots'); // a narrow element starts with the drawer closed (STYLE)

    const read = this.readAttributes(DEFAULT_VIEW_SETTINGS);
    // Less motion asked for: the swirl stands still unless the element says animate="1".
    const settings =
      prefersReducedMotion(this.ownerDocument.defaultView ?? window) && !this.hasAttribute('animate') ? { ...read, animate: false } : read;
    if (!hasWebGL2()) {
      // The page still teaches: a message and a still image computed on the CPU.
      showCpuFallback(this.canvas, filmSettingsOf(settings), () => (this.dataset.frames = 'fallback'), cat);
      return;
    }
    const renderer = acquireSharedRenderer();
    const view = new BubbleView(renderer);
    const frames = new FrameCanvases(this.canvas);
    this.app = new BubbleApp(
      {
        view,
        surface: stage,
        focusable: this.canvas,
        catalogue: cat,
        controls,
        plots,
        messages: this.messages ?? undefined,
        present: () => frames.show(renderer.domElement, view.displayIsP3),
        // Frames that show the settings in full (not from a coarse table) are counted.
        onFrame: (complete) => {
          if (!complete) return;
          this.dataset.frames = String(Number(this.dataset.frames ?? 0) + 1);
          this.readProbe(view, this.app!.drawn);
        },
        onChange: (s) => {
          this.dispatchEvent(new CustomEvent('change', { detail: { settings: s, query: settingsToQuery(s) } }));
        },
      },
      settings,
    );
  }

  /** Reads the film at the probe when the film or the probe changed since the last reading, and says so (`probechange`). */
  private readProbe(view: BubbleView, frame: DrawnFrame): void {
    const { probe, animate, field } = frame.asked;
    const [film, at, ms] = this.probedOf;
    const now = performance.now();
    if (at === probe && (film === frame.film || (animate && THICKNESS_FIELDS[field].animates && now - ms < PROBE_INTERVAL_MS))) return;
    const of = (this.probedOf = [frame.film, probe, now]);
    // The pixel comes back from the GPU a frame or two later; a reading asked for since (or the element removed) counts instead.
    view.probe(probe[0], probe[1]).then(
      (reading) => {
        if (this.probedOf !== of) return;
        this.probed = reading && { thicknessNm: reading.thicknessNm, angleDeg: reading.angleDeg };
        if (this.probed) this.dispatchEvent(new CustomEvent('probechange', { detail: this.probed }));
      },
      // The context was lost before the pixel came back: the next complete frame reads it again.
      () => {
        if (this.probedOf === of) this.probedOf = [null, null, -Infinity];
      },
    );
  }

  disconnectedCallback(): void {
    if (!this.built) return;
    this.built = false;
    this.replaceChildren();
    this.probed = null;
    this.probedOf = [null, null, -Infinity];
    if (!this.app) return;
    this.app.dispose();
    this.app = null;
    releaseSharedRenderer();
  }

  attributeChangedCallback(name: string, _old: string | null, value: string | null): void {
    if (!this.built) return;
    if (name === 'controls' || name === 'plots' || name === 'lang' || !this.app) {
      // The layout changes (or the still image must be recomputed): build the element anew.
      this.disconnectedCallback();
      this.connectedCallback();
      return;
    }
    // A removed attribute goes back to its default; otherwise the panel's changes are kept.
    this.app.set(this.readAttributes(value === null ? DEFAULT_VIEW_SETTINGS : this.app.current), true);
  }

  /** The settings the attributes ask for; a bad one is reported and `base`'s value kept. */
  private readAttributes(base: ViewSettings): ViewSettings {
    const query = new URLSearchParams();
    for (const row of VIEW_PARAMETERS) {
      const value = this.getAttribute(row.attribute);
      if (value !== null) query.set(row.url, value);
    }
    const { settings, refusals } = parseSettings(query.toString(), base);
    const cat = this.catalogue;
    this.messages?.replaceChildren(
      ...refusals.map((r) => Object.assign(this.ownerDocument.createElement('p'), { textContent: refusalText(r, cat) })), // never innerHTML
    );
    return settings;
  }
}

/** Registers the element (once per page, whichever bundle gets there first). */
export function defineThinFilmBubble(name = 'thin-film-bubble'): void {
  if (!customElements.get(name)) customElements.define(name, ThinFilmBubble);
}
