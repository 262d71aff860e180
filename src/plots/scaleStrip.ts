import type { ScaleColor } from './interferenceScale.ts';
import { prepareCanvas, scale } from './plotCanvas.ts';

/** The interference colour scale as a strip (thickness 0 → max), with a marker at the probed thickness. */
export function drawScaleStrip(canvas: HTMLCanvasElement, colors: readonly ScaleColor[], probedThicknessNm: number): void {
  const { ctx, width, height } = prepareCanvas(canvas);
  const maxNm = colors[colors.length - 1]!.thicknessNm;
  const px = scale(0, maxNm, 0, width);
  const stripHeight = height - 12;
  colors.forEach((c, i) => {
    const x0 = i === 0 ? 0 : (px(colors[i - 1]!.thicknessNm) + px(c.thicknessNm)) / 2;
    const x1 = i === colors.length - 1 ? width : (px(c.thicknessNm) + px(colors[i + 1]!.thicknessNm)) / 2;
    ctx.fillStyle = `rgb(${c.rgb8.join(',')})`;
    ctx.fillRect(Math.floor(x0), 0, Math.ceil(x1 - x0) + 1, stripHeight);
  });
  const x = px(Math.min(probedThicknessNm, maxNm));
  ctx.fillStyle = '#fff';
  ctx.beginPath();
  ctx.moveTo(x, stripHeight - 6);
  ctx.lineTo(x - 5, stripHeight + 2);
  ctx.lineTo(x + 5, stripHeight + 2);
  ctx.fill();
  ctx.fillStyle = '#aaa';
  ctx.textAlign = 'left';
  ctx.fillText('0 nm', 2, height - 1);
  ctx.textAlign = 'right';
  ctx.fillText(`${Math.round(maxNm)} nm`, width - 2, height - 1);
}
