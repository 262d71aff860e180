import { XYZ_TO_LINEAR_DISPLAY_P3, XYZ_TO_LINEAR_SRGB } from '../physics/colorConversions.ts';
import { type FilmSettings } from '../settings/filmSettings.ts';
import { maxFieldThicknessNm } from '../fields/fields.ts';
import type { ProbeReading } from '../scene/probe.ts';
import { drawChromaticityPlot } from './chromaticityPlot.ts';
import { type ProbedView, downloadName } from './downloadName.ts';
import { type FilmSpectrum, filmSpectrum } from './filmSpectrum.ts';
import { type ScaleColor, interferenceScale } from './interferenceScale.ts';
import { probeColor } from './probeColor.ts';
import { PLOT_BACKGROUND, addPlotStyles } from './plotStyles.ts';
import { opaquePngUrl, saveUrl, textUrl } from './saveDownload.ts';
import { drawScaleStrip } from './scaleStrip.ts';
import { spectrumCsv } from './spectrumCsv.ts';
import { SPECTRUM_LEGEND, drawSpectrumPlot } from './spectrumPlot.ts';

/** The colour scale runs from 0 to the field's thickest film, and at least this far. */
const MIN_SCALE_NM = 1000;
const SCALE_SAMPLES = 160;

const FIELDS = ['thickness', 'angle', 'hex', 'xyz', 'linearRgb', 'deltaE00'] as const;
const LABELS: Record<(typeof FIELDS)[number], string> = {
  thickness: 'thickness',
  angle: 'θ_i',
  hex: 'colour',
  xyz: 'XYZ',
  linearRgb: 'linear RGB',
  deltaE00: 'ΔE00 rendered vs reference',
};

/**
 * The live plots under a bubble, all computed by the float64 reference (src/physics): the
 * probed point's numbers, its spectra, the xy diagram with the thickness path, and the
 * interference colour strip. Each plot can be saved (PNG; the spectrum also as CSV), named
 * after the probed view. Text goes in with textContent only.
 */
export class PlotPanel {
  readonly element: HTMLElement;
  private readonly values = new Map<string, HTMLElement>();
  private readonly swatch: HTMLElement;
  private readonly spectrum: HTMLCanvasElement;
  private readonly chromaticity: HTMLCanvasElement;
  private readonly strip: HTMLCanvasElement;
  private scaleKey = '';
  private scale: ScaleColor[] = [];
  /** What the plots show now (null: the probe is off the bubble), for the downloads. */
  private shown: { readonly view: ProbedView; readonly spectrum: FilmSpectrum } | null = null;
  private readonly saveButtons: HTMLButtonElement[];

  constructor(doc: Document = document) {
    addPlotStyles(doc);
    const el = (tag: string, className: string) => Object.assign(doc.createElement(tag), { className });
    this.element = el('section', 'tfb-plots');
    this.element.setAttribute('aria-label', 'film at the probe');
    const readout = el('dl', 'tfb-readout');
    for (const f of FIELDS) {
      const value = el('dd', '');
      value.dataset.field = f;
      readout.append(Object.assign(el('dt', ''), { textContent: LABELS[f] }), value);
      this.values.set(f, value);
    }
    this.swatch = el('span', 'tfb-swatch');
    this.spectrum = el('canvas', 'tfb-spectrum') as HTMLCanvasElement;
    this.chromaticity = el('canvas', 'tfb-chromaticity') as HTMLCanvasElement;
    this.strip = el('canvas', 'tfb-strip') as HTMLCanvasElement;
    const legend = el('div', 'tfb-legend');
    for (const [text, color] of SPECTRUM_LEGEND)
      legend.append(Object.assign(el('span', ''), { textContent: text, style: `color: ${color}` }));
    const saves = el('div', 'tfb-downloads');
    saves.append(Object.assign(el('span', ''), { textContent: 'save' }));
    const png = (canvas: HTMLCanvasElement) => () => opaquePngUrl(canvas, PLOT_BACKGROUND);
    const downloads: [string, string, string, (spectrum: FilmSpectrum) => string][] = [
      ['spectrum', 'png', 'spectrum PNG', png(this.spectrum)],
      ['spectrum', 'csv', 'spectrum CSV', (spectrum) => textUrl(spectrumCsv(spectrum), 'text/csv')],
      ['xy', 'png', 'xy PNG', png(this.chromaticity)],
      ['scale', 'png', 'scale PNG', png(this.strip)],
    ];
    this.saveButtons = downloads.map(([what, extension, text, url]) => {
      const button = Object.assign(el('button', ''), { type: 'button', textContent: text, disabled: true }) as HTMLButtonElement;
      button.dataset.download = `${what}.${extension}`;
      button.addEventListener('click', () => {
        if (this.shown) saveUrl(doc, url(this.shown.spectrum), downloadName(this.shown.view, what, extension));
      });
      return button;
    });
    saves.append(...this.saveButtons);
    this.element.append(readout, this.spectrum, legend, this.chromaticity, this.strip, saves);
  }

  /**
   * Redraws for new settings and a new reading at `probe` (fractions of the view; a null reading:
   * the probe is off the bubble).
   */
  update(s: FilmSettings, probe: readonly [number, number], reading: ProbeReading | null, displayIsP3: boolean): void {
    const show = (f: (typeof FIELDS)[number], text: string) => (this.values.get(f)!.textContent = text);
    this.element.dataset.probe = `${probe.join(',')} ${reading ? 'bubble' : 'miss'}`;
    this.shown = null;
    this.saveButtons.forEach((b) => (b.disabled = !reading));
    if (!reading) {
      for (const f of FIELDS) show(f, '—');
      show('thickness', 'off the bubble');
      return;
    }
    const stack = { nOutside: s.nOutside, nFilm: s.nFilm, nInside: s.nInside, angleDeg: reading.angleDeg };
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

    const spectrum = filmSpectrum({ ...stack, thicknessNm: reading.thicknessNm }, s.illuminant, s.polarization);
    drawSpectrumPlot(this.spectrum, spectrum);
    this.shown = { view: { thicknessNm: reading.thicknessNm, angleDeg: reading.angleDeg, illuminant: s.illuminant }, spectrum };
    const maxNm = Math.max(MIN_SCALE_NM, maxFieldThicknessNm(s));
    const key = JSON.stringify([stack, maxNm, s.illuminant, s.polarization, s.normalization, displayIsP3]);
    if (key !== this.scaleKey) {
      this.scale = interferenceScale(stack, maxNm, SCALE_SAMPLES, { ...s, xyzToLinearRgb: toRgb });
      this.scaleKey = key;
    }
    drawChromaticityPlot(this.chromaticity, this.scale, { thicknessNm: reading.thicknessNm, xyz: c.xyz, rgb8: c.rgb8 });
    drawScaleStrip(this.strip, this.scale, reading.thicknessNm);
  }
}
