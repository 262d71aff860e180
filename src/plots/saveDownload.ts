/**
 * Saving what the plots show as files, within the click that asks for it (a download started
 * later, after an await, may be blocked as one the user did not ask for): a canvas as a PNG on an
 * opaque background (plot canvases are transparent where nothing is drawn), a text as a file.
 */

/** The canvas's pixels drawn over `background` (a CSS colour), as a PNG data URL. */
export function opaquePngUrl(canvas: HTMLCanvasElement, background: string): string {
  const copy = canvas.ownerDocument.createElement('canvas');
  copy.width = canvas.width;
  copy.height = canvas.height;
  const ctx = copy.getContext('2d');
  if (!ctx) throw new Error('a 2D canvas context is needed to save a plot');
  ctx.fillStyle = background;
  ctx.fillRect(0, 0, copy.width, copy.height);
  ctx.drawImage(canvas, 0, 0);
  return copy.toDataURL('image/png');
}

/** A text file as a data URL. */
export const textUrl = (text: string, type: string): string => `data:${type};charset=utf-8,${encodeURIComponent(text)}`;

/** Offers the file at `url` to the user as a download named `name`. */
export function saveUrl(doc: Document, url: string, name: string): void {
  Object.assign(doc.createElement('a'), { href: url, download: name }).click();
}
