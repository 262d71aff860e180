import { shownPixelRatio } from '../settings/pixelRatio.ts';

/** A 2D canvas drawn at the device's pixel ratio, in CSS-pixel coordinates. */
export function prepareCanvas(canvas: HTMLCanvasElement): { ctx: CanvasRenderingContext2D; width: number; height: number } {
  const ratio = shownPixelRatio();
  const width = Math.max(1, canvas.clientWidth);
  const height = Math.max(1, canvas.clientHeight);
  if (canvas.width !== Math.round(width * ratio) || canvas.height !== Math.round(height * ratio)) {
    canvas.width = Math.round(width * ratio);
    canvas.height = Math.round(height * ratio);
  }
  const ctx = canvas.getContext('2d');
  if (!ctx) throw new Error('a 2D canvas context is needed for the plots');
  ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
  ctx.clearRect(0, 0, width, height);
  ctx.font = '10px system-ui, sans-serif';
  return { ctx, width, height };
}

/** A linear map from a data range to a pixel range. */
export const scale = (d0: number, d1: number, p0: number, p1: number) => (v: number) => p0 + ((v - d0) / (d1 - d0)) * (p1 - p0);

/** Axes with ticks and labels; returns the data → pixel maps of the plot area. */
export function drawAxes(
  ctx: CanvasRenderingContext2D,
  box: { width: number; height: number },
  x: { min: number; max: number; ticks: number[]; label: string },
  y: { min: number; max: number; ticks: number[]; label: string },
): { px: (v: number) => number; py: (v: number) => number } {
  const left = 38,
    right = box.width - 6,
    top = 6,
    bottom = box.height - 22;
  const px = scale(x.min, x.max, left, right);
  const py = scale(y.min, y.max, bottom, top);
  ctx.strokeStyle = '#666';
  ctx.fillStyle = '#aaa';
  ctx.lineWidth = 1;
  ctx.strokeRect(left, top, right - left, bottom - top);
  ctx.textAlign = 'center';
  for (const t of x.ticks) ctx.fillText(String(t), px(t), bottom + 11);
  if (x.label) ctx.fillText(x.label, (left + right) / 2, box.height - 1);
  ctx.textAlign = 'right';
  for (const t of y.ticks) ctx.fillText(String(+t.toPrecision(3)), left - 3, py(t) + 3);
  ctx.save();
  ctx.translate(7, (top + bottom) / 2);
  ctx.rotate(-Math.PI / 2);
  ctx.textAlign = 'center';
  ctx.fillText(y.label, 0, 0);
  ctx.restore();
  return { px, py };
}

/** A polyline through (xs[i], ys[i]). */
export function drawLine(
  ctx: CanvasRenderingContext2D,
  points: Iterable<readonly [number, number]>,
  style: string,
  width = 1.5,
  close = false,
): void {
  ctx.beginPath();
  let first = true;
  for (const [x, y] of points) {
    if (first) ctx.moveTo(x, y);
    else ctx.lineTo(x, y);
    first = false;
  }
  if (close) ctx.closePath();
  ctx.strokeStyle = style;
  ctx.lineWidth = width;
  ctx.stroke();
}
