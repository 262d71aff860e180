import { XYZ_TO_LINEAR_SRGB, XYZ_TO_LINEAR_WIDE_GAMUT, xyzToXy } from '../physics/colorConversions.ts';
import { type Xy, gamutTriangle, spectralLocus } from './chromaticity.ts';
import type { ScaleColor } from './interferenceScale.ts';
import { drawAxes, drawLine, prepareCanvas } from './plotCanvas.ts';

const LOCUS = spectralLocus();
const MIN_PATH_Y = 1e-4;
const SRGB = gamutTriangle(XYZ_TO_LINEAR_SRGB);
const WIDE_GAMUT = gamutTriangle(XYZ_TO_LINEAR_WIDE_GAMUT);

/**
 * The CIE 1931 xy diagram as in the paper's Figure 2 (spectral locus, the sRGB and Wide Gamut
 * triangles), with the path of the film's colour over the thickness scale and the probed colour.
 */
export function drawChromaticityPlot(canvas: HTMLCanvasElement, path: readonly ScaleColor[], current: ScaleColor): void {
  const { ctx, width, height } = prepareCanvas(canvas);
  const side = Math.min(width, height + 16);
  const { px, py } = drawAxes(
    ctx,
    { width: side, height },
    { min: 0, max: 0.8, ticks: [0, 0.2, 0.4, 0.6, 0.8], label: 'x' },
    { min: 0, max: 0.9, ticks: [0, 0.3, 0.6, 0.9], label: 'y' },
  );
  const at = ([x, y]: Xy) => [px(x), py(y)] as const;
  drawLine(ctx, LOCUS.map(at), '#ddd', 1.2, true);
  drawLine(ctx, SRGB.map(at), '#aaa', 1, true);
  ctx.setLineDash([3, 3]);
  drawLine(ctx, WIDE_GAMUT.map(at), '#aaa', 1, true);
  ctx.setLineDash([]);
  // A film too thin to reflect (Y → 0) has no chromaticity: the path starts where there is light.
  const lit = path.filter((c) => c.xyz[1] > MIN_PATH_Y);
  for (let i = 1; i < lit.length; i++) {
    const [r, g, b] = lit[i]!.rgb8;
    drawLine(ctx, [at(xyzToXy(lit[i - 1]!.xyz)), at(xyzToXy(lit[i]!.xyz))], `rgb(${r},${g},${b})`, 2);
  }
  const [x, y] = at(xyzToXy(current.xyz));
  ctx.beginPath();
  ctx.arc(x, y, 4, 0, 2 * Math.PI);
  ctx.fillStyle = `rgb(${current.rgb8.join(',')})`;
  ctx.fill();
  ctx.strokeStyle = '#fff';
  ctx.lineWidth = 1.5;
  ctx.stroke();
  ctx.fillStyle = '#aaa';
  ctx.textAlign = 'left';
  ctx.fillText('sRGB ─  Wide Gamut ┄', px(0.42), py(0.86));
}
