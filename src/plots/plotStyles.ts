/** The plots' look, added to a document once (the demo page and every embedded bubble share it). */
const CSS = `
.tfb-plots { display: grid; gap: 6px; font: 11px system-ui, sans-serif; color: #ddd; }
.tfb-readout { display: grid; grid-template-columns: auto 1fr; gap: 1px 8px; margin: 0; }
.tfb-readout dt { color: #999; }
.tfb-readout dd { margin: 0; font-variant-numeric: tabular-nums; }
.tfb-swatch { display: inline-block; width: 10px; height: 10px; margin-right: 4px; vertical-align: -1px; border: 1px solid #888; }
.tfb-probe-marker { position: absolute; width: 12px; height: 12px; margin: -7px 0 0 -7px; border: 1px solid #fff;
  border-radius: 50%; box-shadow: 0 0 0 1px #000; pointer-events: none; }
.tfb-legend { display: flex; flex-wrap: wrap; gap: 0 10px; margin-top: -4px; }
.tfb-stack-note { margin: 4px 0; color: #ffd27f; }
.tfb-readout dd { overflow-wrap: anywhere; }
.tfb-spectrum { width: 100%; height: 110px; }
.tfb-chromaticity { width: 100%; aspect-ratio: 1 / 1; max-height: 240px; }
.tfb-strip { width: 100%; height: 34px; }
.tfb-downloads { display: flex; flex-wrap: wrap; align-items: center; gap: 4px; color: #999; }
.tfb-downloads button { font: inherit; padding: 1px 6px; color: #ddd; background: #2a2a30; border: 1px solid #555; border-radius: 3px; cursor: pointer; }
.tfb-downloads button:disabled { color: #666; cursor: default; }
`;

/** The background a plot is saved on (its canvas is transparent where nothing is drawn): the plots box's colour, opaque. */
export const PLOT_BACKGROUND = '#141418';

export function addPlotStyles(doc: Document): void {
  if (doc.getElementById('tfb-plot-styles')) return;
  const style = doc.createElement('style');
  style.id = 'tfb-plot-styles';
  style.textContent = CSS;
  doc.head.append(style);
}
