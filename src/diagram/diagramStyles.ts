/**
 * The diagram's look: one column that reflows from a phone's 390 px up, light colours with text
 * contrast above 7:1, a visible focus ring on every control. Added once per document, first in
 * its head so the page's own rules win.
 */
const STYLE = `
thin-film-diagram { display: block; container: tfd / inline-size; font: 14px/1.4 system-ui, sans-serif; color: #1b1b1b; background: #fff; }
thin-film-diagram .tfd-controls { display: grid; grid-template-columns: repeat(auto-fit, minmax(170px, 1fr)); gap: 6px 14px; margin: 0 0 8px; padding: 0; border: 0; }
thin-film-diagram .tfd-controls label { display: flex; flex-direction: column; gap: 2px; }
thin-film-diagram .tfd-controls label.tfd-check { flex-direction: row; align-items: center; gap: 6px; }
thin-film-diagram input, thin-film-diagram select { font: inherit; color: inherit; }
thin-film-diagram input[type='range'] { width: 100%; }
thin-film-diagram :focus-visible { outline: 3px solid #1f4fbf; outline-offset: 2px; }
thin-film-diagram svg { display: block; width: 100%; max-width: 640px; height: auto; user-select: text; }
thin-film-diagram figure { margin: 6px 0; }
thin-film-diagram .tfd-phasors { display: flex; flex-wrap: wrap; gap: 8px; }
thin-film-diagram .tfd-phasors svg { flex: 1 1 170px; max-width: 300px; border: 1px solid #ddd; }
thin-film-diagram .tfd-table { overflow-x: auto; }
thin-film-diagram .tfd-stack-note { margin: 4px 0; padding: 4px 8px; border-left: 3px solid #8a5a00; background: #fff6e0; }
thin-film-diagram table { border-collapse: collapse; font-size: 13px; }
thin-film-diagram caption { text-align: left; font-weight: 600; padding: 2px 0; }
thin-film-diagram th, thin-film-diagram td { padding: 2px 8px 2px 0; border-bottom: 1px solid #ddd; text-align: left; }
thin-film-diagram .tfd-errors p { background: #fde8e8; color: #6b0b0b; padding: 4px 8px; margin: 4px 0; border-radius: 3px; }
thin-film-diagram .tfd-summary { font-weight: 600; margin: 4px 0; }
`;

export function addDiagramStyles(doc: Document): void {
  if (doc.getElementById('tfd-element-styles')) return;
  doc.head.prepend(Object.assign(doc.createElement('style'), { id: 'tfd-element-styles', textContent: STYLE }));
}
