import { type Matrix3, XYZ_TO_LINEAR_DISPLAY_P3, XYZ_TO_LINEAR_SRGB, xyzToXy } from '../physics/colorConversions.ts';
import { type Catalogue, EN, type MessageKey } from '../i18n/en.ts';
import { message } from '../i18n/messages.ts';
import { type FilmSettings } from '../settings/filmSettings.ts';
import type { ProbeReading } from '../view/probe.ts';
import { drawChromaticityPlot } from './chromaticityPlot.ts';
import { type ProbedView, downloadName } from './downloadName.ts';
import { type FilmSpectrum, filmSpectrum } from './filmSpectrum.ts';
import type { ScaleColor, ScaleRequest } from './interferenceScale.ts';
import { interferenceScaleFor } from './interferenceScaleStore.ts';
import { probeColor } from './probeColor.ts';
import { PLOT_BACKGROUND, addPlotStyles } from './plotStyles.ts';
import { opaquePngUrl, saveUrl, textUrl } from './saveDownload.ts';
import { drawScaleStrip } from './scaleStrip.ts';
import { spectrumCsv } from './spectrumCsv.ts';
import { SPECTRUM_LEGEND, drawSpectrumPlot } from './spectrumPlot.ts';
import { filmOptionAt } from '../methods/filmStacks.ts';

/** The colour scale runs from 0 to the field's thickest film, and at least this far. */
const MIN_SCALE_NM = 1000;
const SCALE_SAMPLES = 160;

const FIELDS = ['thickness', 'angle', 'hex', 'xyz', 'linearRgb', 'deltaE00'] as const;
/** The spectrum's table (on demand) lists every this many nanometres of the plot's 1 nm samples. */
const TABLE_STEP_NM = 10;

/** An element of the panel, of class `className`. */
const panelElement = (doc: Document, tag: string, className: string): HTMLElement => Object.assign(doc.createElement(tag), { className });

/** The probed point's numbers: a term and its value per field of FIELDS, each value kept in `values` by its field. */
function readoutList(doc: Document, cat: Catalogue, values: Map<string, HTMLElement>): HTMLElement {
  const readout = panelElement(doc, 'dl', 'tfb-readout');
  for (const f of FIELDS) {
    const value = panelElement(doc, 'dd', '');
    value.dataset.field = f;
    readout.append(Object.assign(panelElement(doc, 'dt', ''), { textContent: cat[`plots.${f}`] }), value);
    values.set(f, value);
  }
  return readout;
}

/** A plot's canvas: an image whose text alternative says what it shows (no reading yet). */
function plotImage(doc: Document, cat: Catalogue, className: string): HTMLCanvasElement {
  const canvas = panelElement(doc, 'canvas', className) as HTMLCanvasElement;
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', cat['plots.noReading']);
  return canvas;
}

/** The spectrum's curves named in their colours; hidden from assistive technology, as the spectrum's text alternative names its curves. */
function spectrumLegend(doc: Document, cat: Catalogue): HTMLElement {
  const legend = panelElement(doc, 'div', 'tfb-legend');
  legend.setAttribute('aria-hidden', 'true');
  for (const [key, color] of SPECTRUM_LEGEND)
    legend.append(Object.assign(panelElement(doc, 'span', ''), { textContent: cat[key], style: `color: ${color}` }));
  return legend;
}

/**
 * The live plots under a bubble, all computed by the float64 reference (src/physics): the
 * probed point's numbers, its spectra, the xy diagram with the thickness path, and the
 * interference colour strip. Each plot can be saved (PNG; the spectrum also as CSV), named
 * after the probed view. Each plot is an image with a text alternative that says what it shows
 * and its values now; the spectrum is also a table, shown on demand. Texts come from a catalogue
 * and go in with textContent only.
 */
export class PlotPanel {
  readonly element: HTMLElement;
  private readonly values = new Map<string, HTMLElement>();
  private readonly swatch: HTMLElement;
  /** Says when the plots show a stack of films rather than one film (hidden for the single film). */
  private readonly stackNote: HTMLElement;
  private readonly spectrum: HTMLCanvasElement;
  private readonly chromaticity: HTMLCanvasElement;
  private readonly strip: HTMLCanvasElement;
  /** The scale wanted (its settings), and the one drawn: the last to arrive, until the wanted one does. */
  private scaleKey = '';
  private scale: { readonly key: string; readonly colors: ScaleColor[] } | null = null;
  /** The probed colour on the scale's plots, and their labels' numbers. */
  private scalePoint: (ScaleColor & { readonly maxNm: number }) | null = null;
  /** What the plots show now (null: the probe is off the bubble), for the downloads. */
  private shown: { readonly view: ProbedView; readonly spectrum: FilmSpectrum } | null = null;
  private readonly saveButtons: HTMLButtonElement[];
  private readonly tableButton: HTMLButtonElement;
  private readonly table: HTMLTableElement;

  constructor(
    doc: Document = document,
    private readonly cat: Catalogue = EN,
  ) {
    addPlotStyles(doc);
    this.element = panelElement(doc, 'section', 'tfb-plots');
    this.element.setAttribute('aria-label', cat['plots.label']);
    const readout = readoutList(doc, cat, this.values);
    this.swatch = panelElement(doc, 'span', 'tfb-swatch');
    this.stackNote = panelElement(doc, 'p', 'tfb-stack-note');
    this.stackNote.hidden = true;
    this.spectrum = plotImage(doc, cat, 'tfb-spectrum');
    this.chromaticity = plotImage(doc, cat, 'tfb-chromaticity');
    this.strip = plotImage(doc, cat, 'tfb-strip');
    this.table = panelElement(doc, 'table', 'tfb-spectrum-table') as HTMLTableElement;
    this.table.id = `tfb-spectrum-table-${++tableCount}`;
    this.table.hidden = true;
    this.tableButton = Object.assign(panelElement(doc, 'button', 'tfb-table-toggle'), {
      type: 'button',
      textContent: cat['plots.showTable'],
    }) as HTMLButtonElement;
    this.tableButton.setAttribute('aria-expanded', 'false');
    this.tableButton.setAttribute('aria-controls', this.table.id);
    this.tableButton.addEventListener('click', () => this.showTable(this.table.hidden));
    const saves = panelElement(doc, 'div', 'tfb-downloads');
    saves.append(Object.assign(panelElement(doc, 'span', ''), { textContent: cat['plots.save'] }));
    this.saveButtons = this.downloadButtons(doc);
    saves.append(...this.saveButtons);
    const legend = spectrumLegend(doc, cat);
    this.element.append(readout, this.stackNote, this.spectrum, legend, this.tableButton, this.table, this.chromaticity, this.strip, saves);
  }

  /** A button per download (disabled until the plots show a reading), each saving what the plots show then. */
  private downloadButtons(doc: Document): HTMLButtonElement[] {
    const png = (canvas: HTMLCanvasElement) => () => opaquePngUrl(canvas, PLOT_BACKGROUND);
    const downloads: [string, string, MessageKey, (spectrum: FilmSpectrum) => string][] = [
      ['spectrum', 'png', 'plots.save.spectrumPng', png(this.spectrum)],
      ['spectrum', 'csv', 'plots.save.spectrumCsv', (spectrum) => textUrl(spectrumCsv(spectrum), 'text/csv')],
      ['xy', 'png', 'plots.save.xyPng', png(this.chromaticity)],
      ['scale', 'png', 'plots.save.scalePng', png(this.strip)],
    ];
    return downloads.map(([what, extension, text, url]) => {
      const button = Object.assign(panelElement(doc, 'button', ''), {
        type: 'button',
        textContent: this.cat[text],
        disabled: true,
      }) as HTMLButtonElement;
      button.dataset.download = `${what}.${extension}`;
      button.addEventListener('click', () => {
        if (this.shown) saveUrl(doc, url(this.shown.spectrum), downloadName(this.shown.view, what, extension));
      });
      return button;
    });
  }

  /** Shows or hides the spectrum's table (built anew from the spectrum shown). */
  private showTable(show: boolean): void {
    this.table.hidden = !show;
    this.tableButton.textContent = this.cat[show ? 'plots.hideTable' : 'plots.showTable'];
    this.tableButton.setAttribute('aria-expanded', String(show));
    this.fillTable();
  }

  /** The spectrum shown as rows of λ, R, I_in and I_out every TABLE_STEP_NM, while the table is shown (textContent only). */
  private fillTable(): void {
    if (this.table.hidden) return;
    const doc = this.table.ownerDocument;
    const row = (tag: 'th' | 'td', texts: readonly string[]) => {
      const tr = doc.createElement('tr');
      tr.append(...texts.map((text, i) => Object.assign(doc.createElement(i === 0 && tag === 'td' ? 'th' : tag), { textContent: text })));
      if (tag === 'td') tr.firstElementChild!.setAttribute('scope', 'row');
      else for (const th of tr.children) th.setAttribute('scope', 'col');
      return tr;
    };
    const c = this.cat;
    const caption = Object.assign(doc.createElement('caption'), {
      textContent: message(c, 'plots.tableCaption', { stepNm: TABLE_STEP_NM }),
    });
    const head = doc.createElement('thead');
    head.append(row('th', [c['plots.tableWavelength'], c['plots.tableReflectance'], c['plots.tableIncident'], c['plots.tableReflected']]));
    const body = doc.createElement('tbody');
    const s = this.shown?.spectrum;
    if (s)
      s.lambdasNm.forEach((l, i) => {
        if (i % TABLE_STEP_NM !== 0) return;
        body.append(row('td', [String(l), s.reflectance[i]!.toFixed(4), s.incident[i]!.toFixed(4), s.reflected[i]!.toFixed(4)]));
      });
    else body.append(row('td', [c['plots.noReading']]));
    this.table.replaceChildren(caption, head, body);
  }

  /**
   * Redraws for new settings, their field's largest thickness (the frame's: the film table's range,
   * which the scale spans) and a new reading at `probe` (fractions of the view; a null reading: the
   * probe is off the bubble).
   */
  update(s: FilmSettings, fieldMaxNm: number, probe: readonly [number, number], reading: ProbeReading | null, displayIsP3: boolean): void {
    const show = (f: (typeof FIELDS)[number], text: string) => (this.values.get(f)!.textContent = text);
    this.element.dataset.probe = `${probe.join(',')} ${reading ? 'bubble' : 'miss'}`;
    this.shown = null;
    this.saveButtons.forEach((b) => (b.disabled = !reading));
    if (!reading) {
      this.stackNote.hidden = true;
      for (const f of FIELDS) show(f, '—');
      show('thickness', this.cat['plots.offBubble']);
      for (const canvas of [this.spectrum, this.chromaticity, this.strip]) canvas.setAttribute('aria-label', this.cat['plots.noReading']);
      this.fillTable();
      return;
    }
    const stack = filmOptionAt(s, reading.angleDeg);
    const toRgb = displayIsP3 ? XYZ_TO_LINEAR_DISPLAY_P3 : XYZ_TO_LINEAR_SRGB;
    const c = probeColor({ ...stack, thicknessNm: reading.thicknessNm }, s, toRgb, reading.renderedXyz);
    const fmt = (xs: readonly number[]) => xs.map((v) => v.toFixed(4)).join(' ');
    show('thickness', `${reading.thicknessNm.toFixed(1)} nm`);
    show('angle', `${reading.angleDeg.toFixed(2)}°`);
    show('hex', c.hex);
    this.values.get('hex')!.prepend(this.swatch);
    show('xyz', fmt(c.xyz));
    show('linearRgb', fmt(c.linearRgb));
    show('deltaE00', c.deltaE00.toFixed(3));
    this.swatch.style.background = c.hex;

    const spectrum = filmSpectrum({ ...stack, thicknessNm: reading.thicknessNm }, s.illuminant, s.polarization, 1, s.lightTint);
    drawSpectrumPlot(this.spectrum, spectrum, this.cat['common.wavelength']);
    this.shown = {
      view: { thicknessNm: reading.thicknessNm, angleDeg: reading.angleDeg, illuminant: s.illuminant, lightTint: s.lightTint },
      spectrum,
    };
    const stackText = spectrum.layerCount ? message(this.cat, 'plots.stackNote', { count: spectrum.layerCount }) : '';
    this.stackNote.hidden = !stackText;
    this.stackNote.textContent = stackText;
    this.spectrum.setAttribute('aria-label', [stackText, spectrumLabel(spectrum, this.cat)].filter(Boolean).join(' '));
    this.fillTable();
    const maxNm = Math.max(MIN_SCALE_NM, fieldMaxNm);
    this.scalePoint = { thicknessNm: reading.thicknessNm, xyz: c.xyz, rgb8: c.rgb8, maxNm };
    this.askScale(stack, maxNm, s, toRgb);
    this.drawScale();
  }

  /** Asks for the colour scale of the film in the light of `s` where it is not the one asked last (computed in a worker, drawn when it arrives). */
  private askScale(stack: ScaleRequest['stack'], maxThicknessNm: number, s: FilmSettings, xyzToLinearRgb: Matrix3): void {
    const { illuminant, lightTint, polarization, normalization } = s;
    const request = {
      stack,
      maxThicknessNm,
      count: SCALE_SAMPLES,
      options: { illuminant, lightTint, polarization, normalization, xyzToLinearRgb },
    };
    const key = JSON.stringify(request);
    if (key === this.scaleKey) return;
    this.scaleKey = key;
    const colors = interferenceScaleFor(request, (arrived) => {
      this.scale = { key, colors: arrived };
      if (this.scaleKey === key && this.shown) this.drawScale();
    });
    if (colors) this.scale = { key, colors };
  }

  /**
   * The xy diagram and the strip: the scale wanted, or until it arrives the last one (marked
   * `data-scale="pending"` on the plots, `ready` once the wanted one is drawn).
   */
  private drawScale(): void {
    const p = this.scalePoint!;
    this.element.dataset.scale = this.scale?.key === this.scaleKey ? 'ready' : 'pending';
    if (this.scale) {
      drawChromaticityPlot(this.chromaticity, this.scale.colors, p);
      drawScaleStrip(this.strip, this.scale.colors, p.thicknessNm);
    }
    const [x, y] = xyzToXy(p.xyz).map((v) => v.toFixed(4));
    this.chromaticity.setAttribute('aria-label', message(this.cat, 'plots.xyLabel', { x: x!, y: y!, maxNm: p.maxNm }));
    const thickness = p.thicknessNm.toFixed(0);
    this.strip.setAttribute('aria-label', message(this.cat, 'plots.scaleLabel', { maxNm: p.maxNm, thickness }));
  }
}

/** Instances so far, for each spectrum table's own id. */
let tableCount = 0;

/** What the spectrum plot shows, in words: R's range and where it peaks and dips. */
function spectrumLabel(s: FilmSpectrum, cat: Catalogue): string {
  let lo = 0;
  let hi = 0;
  s.reflectance.forEach((r, i) => {
    if (r < s.reflectance[lo]!) lo = i;
    if (r > s.reflectance[hi]!) hi = i;
  });
  const at = (i: number) => ({ r: s.reflectance[i]!.toFixed(4), nm: s.lambdasNm[i]! });
  const [min, max] = [at(lo), at(hi)];
  return message(cat, 'plots.spectrumLabel', { min: min.r, minNm: min.nm, max: max.r, maxNm: max.nm });
}
