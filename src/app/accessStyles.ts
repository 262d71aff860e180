/**
 * What keyboard and screen-reader users need from the page's CSS, added to a document once: a
 * visible focus ring (2 px, #ffbf47, at least 3:1 against the panel's and the page's dark
 * backgrounds) on the panel's controls, the bubble and the plots' buttons; and the live
 * description kept for screen readers only (visually hidden, still read).
 */
const CSS = `
.lil-gui :focus-visible, .tfb-focusable:focus-visible, .tfb-plots button:focus-visible, details > summary:focus-visible {
  outline: 2px solid #ffbf47; outline-offset: 1px; }
.lil-gui input[type=checkbox]:focus-visible { outline-offset: 2px; }
.tfb-focusable:focus-visible { outline-offset: -3px; }
.tfb-live { position: absolute; width: 1px; height: 1px; margin: -1px; padding: 0; overflow: hidden; clip-path: inset(50%); white-space: nowrap; border: 0; }
`;

export function addAccessStyles(doc: Document): void {
  if (doc.getElementById('tfb-access-styles')) return;
  const style = Object.assign(doc.createElement('style'), { id: 'tfb-access-styles', textContent: CSS });
  doc.head.append(style);
}
