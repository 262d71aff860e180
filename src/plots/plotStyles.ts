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
.tfb-readout dd { overflow-wrap: anywhere; }
.tfb-spectrum { width: 100%; height: 110px; }
.tfb-chromaticity { width: 100%; aspect-ratio: 1 / 1; max-height: 240px; }
.tfb-strip { width: 100%; height: 34px; }
`;

export function addPlotStyles(doc: Document): void {
  if (doc.getElementById('tfb-plot-styles')) return;
  const style = doc.createElement('style');
  style.id = 'tfb-plot-styles';
  style.textContent = CSS;
  doc.head.append(style);
}
