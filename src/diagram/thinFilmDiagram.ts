import type { Catalogue } from '../i18n/en.ts';
import { catalogueFor, catalogueLang, message } from '../i18n/messages.ts';
import { FILM_STACK_DOMAIN } from '../physics/filmReflectance.ts';
import { BEAM_TAIL_FRACTION, type FilmBeams, filmBeams } from '../physics/reflectedBeams.ts';
import { isInDomain, quoted } from '../input/validate.ts';
import { type FilmMediaOption, optionFilmsOf } from '../methods/filmStacks.ts';
import type { ProbedFilm } from '../view/probe.ts';
import { drawBeamFigure } from './beamFigure.ts';
import { fillBeamTable } from './beamTable.ts';
import { type DiagramControls, buildDiagramControls, polarizationName } from './diagramControls.ts';
import {
  DEFAULT_DIAGRAM_SETTINGS,
  DIAGRAM_ATTRIBUTES,
  DIAGRAM_ROWS,
  type DiagramSettings,
  readDiagramAttributes,
} from './diagramParameters.ts';
import { addDiagramStyles } from './diagramStyles.ts';
import { fourFigures, settingText } from './numberText.ts';
import { drawPhasorFigure } from './phasorFigure.ts';
import { diagramFilmAt, drawSpectrumFigure } from './spectrumFigure.ts';
import { SVG_NS } from './svgNodes.ts';

let instances = 0;

/** The summary's second sentence: how many beams were drawn and what the rest of the series adds. */
function beamSentence(beams: FilmBeams, cat: Catalogue): string {
  const count = Math.max(...beams.channels.map((c) => c.beams.beams.length));
  const bound = Math.max(...beams.channels.map((c) => c.beams.tailBound));
  if (count === 1) return cat['diagram.summaryNoEntry'];
  if (!Number.isFinite(bound)) return message(cat, 'diagram.summaryDiverges', { count });
  if (bound > BEAM_TAIL_FRACTION) return message(cat, 'diagram.summaryTail', { count, bound: fourFigures(bound) });
  return message(cat, 'diagram.summaryBeams', { count, bound: `${BEAM_TAIL_FRACTION * 100} %` });
}

/**
 * `<thin-film-diagram>`: the paper's Figure 1, live. The film (attributes `thickness`, `angle`,
 * `wavelength`, `nfilm`, `noutside`, `ninside`, `polarization`, read and checked as the bubble's are),
 * or the probe of the `<thin-film-bubble>` named by `for` (its thickness and θ_i); its own controls
 * set the same. It shows the media and rays with the reflected beams E_0 … E_N, a phasor diagram per
 * polarisation channel, R(λ) with λ marked, a table of the beams and a summary of R; `lang`
 * (or the page's) chooses the language. `reflectance` holds R; `diagramchange` (detail:
 * { reflectance, beamCount }) follows every change. A bad attribute is named with its range in a
 * message (text only) and its earlier value kept. It draws one film only: when the bubble it
 * follows shows a stack of films, a note says so and points to the bubble's
 * plots, which show the stack's R(λ) (docs/diagram.md#one-film-only).
 */
export class ThinFilmDiagram extends HTMLElement {
  static readonly observedAttributes = [...DIAGRAM_ATTRIBUTES, 'for', 'lang'];
  private state: DiagramSettings = DEFAULT_DIAGRAM_SETTINGS;
  private flipTop = false;
  private errors: readonly string[] = [];
  private linkError: string | null = null;
  /** The films of the stack the linked bubble shows (0: one film, or no bubble). */
  private bubbleFilms = 0;
  private unlink: () => void = () => {};
  private parts: {
    readonly controls: DiagramControls;
    readonly errors: HTMLElement;
    readonly summary: HTMLElement;
    readonly stackNote: HTMLElement;
    readonly figure: SVGSVGElement;
    readonly phasors: HTMLElement;
    readonly spectrum: SVGSVGElement;
    readonly table: HTMLTableElement;
  } | null = null;
  private readonly uid = `tfd${++instances}`;
  private r = Number.NaN;
  private beamCount = 0;

  /** R at the diagram's settings (eq 14; with the top surface's phase flip removed when the toggle is on); NaN before it is on a page. */
  get reflectance(): number {
    return this.r;
  }

  /** The settings shown now. */
  get settings(): DiagramSettings & { readonly flipTop: boolean } {
    return { ...this.state, flipTop: this.flipTop };
  }

  connectedCallback(): void {
    addDiagramStyles(this.ownerDocument);
    this.state = readDiagramAttributes((a) => this.getAttribute(a), DEFAULT_DIAGRAM_SETTINGS, this.catalogue).settings;
    this.build();
    this.link();
  }

  disconnectedCallback(): void {
    this.unlink();
    this.parts = null;
    this.replaceChildren();
  }

  attributeChangedCallback(name: string, _old: string | null, value: string | null): void {
    if (!this.isConnected || !this.parts) return;
    if (name === 'lang') return this.build();
    if (name === 'for') return this.link();
    const row = DIAGRAM_ROWS.find((r) => r.row.attribute === name)!.row;
    this.state =
      value === null
        ? { ...this.state, [row.key]: row.defaultValue }
        : readDiagramAttributes((a) => (a === name ? value : null), this.state, this.catalogue).settings;
    this.errors = readDiagramAttributes((a) => this.getAttribute(a), DEFAULT_DIAGRAM_SETTINGS, this.catalogue).errors;
    this.render();
  }

  /** The language asked for: the element's own `lang`, an ancestor's, or the page's. */
  private get language(): string {
    return this.closest('[lang]')?.getAttribute('lang') ?? this.ownerDocument.documentElement.lang;
  }

  private get catalogue(): Catalogue {
    return catalogueFor(this.language);
  }

  /** Builds the element's parts in its language, then shows the settings. */
  private build(): void {
    const doc = this.ownerDocument;
    const cat = this.catalogue;
    const el = <K extends keyof HTMLElementTagNameMap>(tag: K, className: string) => Object.assign(doc.createElement(tag), { className });
    const svgFigure = (label: string) => {
      const s = doc.createElementNS(SVG_NS, 'svg');
      s.setAttribute('role', 'img');
      s.setAttribute('aria-labelledby', `${this.uid}-${label}-title`);
      s.setAttribute('aria-describedby', `${this.uid}-${label}-desc`);
      return s;
    };
    const controls = buildDiagramControls(
      doc,
      cat,
      this.id,
      (attribute, raw) => this.setFromControl(attribute, raw),
      (on) => {
        this.flipTop = on;
        this.render();
      },
    );
    const root = el('section', 'tfd');
    root.lang = catalogueLang(this.language);
    root.setAttribute('aria-label', cat['diagram.label']);
    const errors = el('div', 'tfd-errors');
    errors.setAttribute('role', 'alert');
    const summary = el('p', 'tfd-summary');
    summary.setAttribute('aria-live', 'polite');
    const stackNote = el('p', 'tfd-stack-note');
    const figure = svgFigure('figure');
    const phasors = el('div', 'tfd-phasors');
    const spectrum = svgFigure('spectrum');
    const tableBox = el('div', 'tfd-table');
    const table = doc.createElement('table');
    tableBox.append(table);
    root.append(controls.element, errors, stackNote, summary, figure, phasors, spectrum, tableBox);
    this.replaceChildren(root);
    this.parts = { controls, errors, summary, stackNote, figure, phasors, spectrum, table };
    this.errors = readDiagramAttributes((a) => this.getAttribute(a), DEFAULT_DIAGRAM_SETTINGS, cat).errors;
    this.render();
  }

  private setFromControl(attribute: string, raw: string): void {
    const read = readDiagramAttributes((a) => (a === attribute ? raw : null), this.state, this.catalogue);
    if (read.errors.length) return; // a field still being typed in; the input shows its own range
    this.state = read.settings;
    this.render();
  }

  /** Follows the probe of the bubble named by `for`: its thickness and θ_i. */
  private link(): void {
    this.unlink();
    this.unlink = () => {};
    this.linkError = null;
    this.bubbleFilms = 0;
    const id = this.getAttribute('for');
    if (id === null) return this.render();
    const bubble = this.ownerDocument.getElementById(id);
    if (!bubble || bubble.localName !== 'thin-film-bubble') {
      if (this.ownerDocument.readyState === 'loading') {
        this.ownerDocument.addEventListener('DOMContentLoaded', () => this.link(), { once: true });
      } else {
        this.linkError = message(this.catalogue, 'diagram.error.for', { attribute: 'for', value: quoted(id), tag: '<thin-film-bubble>' });
      }
      return this.render();
    }
    const follow = (probe: ProbedFilm | null | undefined) => {
      // Read through the bubble's public `settings` (the element layer sits above this one).
      this.bubbleFilms = optionFilmsOf((bubble as HTMLElement & { settings?: FilmMediaOption | null }).settings ?? {}).length;
      if (
        !probe ||
        !isInDomain(probe.thicknessNm, FILM_STACK_DOMAIN.thicknessNm) ||
        !isInDomain(probe.angleDeg, FILM_STACK_DOMAIN.angleDeg)
      )
        return;
      this.state = { ...this.state, thicknessNm: probe.thicknessNm, angleDeg: probe.angleDeg };
      this.render();
    };
    const listener = (e: Event) => follow((e as CustomEvent<ProbedFilm>).detail);
    bubble.addEventListener('probechange', listener);
    this.unlink = () => bubble.removeEventListener('probechange', listener);
    follow((bubble as HTMLElement & { probeReading?: ProbedFilm | null }).probeReading);
    this.render();
  }

  private render(): void {
    const parts = this.parts;
    if (!parts) return;
    const cat = this.catalogue;
    const s = this.state;
    const stack = diagramFilmAt(s, s.wavelengthNm);
    const beams = filmBeams(stack, s.polarization, s.wavelengthNm, { flipTop: this.flipTop });
    this.r = beams.reflectance;
    this.beamCount = Math.max(...beams.channels.map((c) => c.beams.beams.length));
    parts.controls.sync(s, this.flipTop);
    const messages = this.linkError ? [...this.errors, this.linkError] : this.errors;
    parts.stackNote.hidden = this.bubbleFilms === 0;
    parts.stackNote.textContent = this.bubbleFilms ? message(cat, 'diagram.oneFilm', { count: this.bubbleFilms }) : '';
    parts.errors.replaceChildren(...messages.map((e) => Object.assign(this.ownerDocument.createElement('p'), { textContent: e })));
    parts.summary.textContent = `${message(cat, 'diagram.summary', {
      reflectance: fourFigures(this.r),
      wavelength: settingText(s.wavelengthNm),
      polarization: polarizationName(s.polarization, cat),
    })} ${beamSentence(beams, cat)}`;
    const ids = (label: string) => ({ title: `${this.uid}-${label}-title`, desc: `${this.uid}-${label}-desc` });
    drawBeamFigure(parts.figure, { stack, beams, flipTop: this.flipTop, catalogue: cat }, ids('figure'));
    const names = beams.channels.map((c) => polarizationName(c.channel, cat));
    while (parts.phasors.children.length > beams.channels.length) parts.phasors.lastElementChild!.remove();
    beams.channels.forEach((c, i) => {
      let phasor = parts.phasors.children[i] as SVGSVGElement | undefined;
      if (!phasor) {
        phasor = this.ownerDocument.createElementNS(SVG_NS, 'svg');
        phasor.setAttribute('role', 'img');
        parts.phasors.append(phasor);
      }
      const label = `phasor${i}`;
      phasor.setAttribute('aria-labelledby', ids(label).title);
      phasor.setAttribute('aria-describedby', ids(label).desc);
      drawPhasorFigure(phasor, c, names[i]!, cat, { ...ids(label), marker: `${this.uid}-${label}-arrow` });
    });
    drawSpectrumFigure(
      parts.spectrum,
      { stack: s, polarization: s.polarization, flipTop: this.flipTop, wavelengthNm: s.wavelengthNm },
      cat,
      ids('spectrum'),
    );
    fillBeamTable(parts.table, beams, names, this.flipTop, cat);
    this.dataset.reflectance = String(this.r);
    this.dataset.beams = String(this.beamCount);
    this.dispatchEvent(new CustomEvent('diagramchange', { detail: { reflectance: this.r, beamCount: this.beamCount } }));
  }
}

/** Registers the element (once per page). */
export function defineThinFilmDiagram(name = 'thin-film-diagram'): void {
  if (!customElements.get(name)) customElements.define(name, ThinFilmDiagram);
}
