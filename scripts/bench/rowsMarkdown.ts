/** The benchmark's main table, as Markdown. */
import type { DeltaStats } from '../../src/physics/deltaStats.ts';
import type { BenchRowResult } from './benchRow.ts';

export interface MeasuredRow extends Omit<BenchRowResult, 'xyz'> {
  readonly name: string;
  readonly errors: readonly DeltaStats[] | null;
}

const ms = (v: number) => (v >= 100 ? v.toFixed(0) : v.toFixed(1));
const stats = (s: DeltaStats | undefined) => (s ? `${s.max.toFixed(2)} / ${s.p99.toFixed(2)} / ${s.mean.toFixed(3)}` : '—');

export function rowsMarkdown(
  rows: readonly MeasuredRow[],
  how: { sizes: readonly (readonly [number, number])[]; frames: number; frameBudgetMs: number },
): string {
  const floor = rows[0]!; // the plain textured sphere
  const sizeHeads = how.sizes.map(([w, h]) => `${w}×${h} ms (× floor)`);
  const head = [
    'method',
    ...sizeHeads,
    'first table build ms (with compile)',
    'change → next frame ms: n film / light / polarisation / range (max × own frame)',
    'rebuilds while animating',
    'first frame ms',
    'fixed grid ΔE00 max / p99 / mean',
    'stress grid ΔE00 max / p99 / mean',
  ];
  const lines = rows.map((r) => {
    const frames = r.frames.map((f, i) => {
      const ratio = f.medianMs / floor.frames[i]!.medianMs;
      return `${ms(f.medianMs)} (${ratio.toFixed(2)}×)${f.count < how.frames ? ` [${f.count}]` : ''}`;
    });
    const table = r.tableBuildMs === null ? '—' : ms(r.tableBuildMs);
    const change =
      r === floor
        ? '—'
        : `${r.changeToFrameMs.map(ms).join(' / ')} (${(Math.max(...r.changeToFrameMs) / r.frames[0]!.medianMs).toFixed(1)}×)`;
    return [
      r.name,
      ...frames,
      table,
      change,
      String(r.rebuildsWhileAnimating),
      ms(r.firstFrameMs),
      stats(r.errors?.[0]),
      stats(r.errors?.[1]),
    ];
  });
  return [
    `| ${head.join(' | ')} |`,
    `|${head.map(() => '---').join('|')}|`,
    ...lines.map((l) => `| ${l.join(' | ')} |`),
    '',
    `Frame times: median of ${how.frames} frames after 3 warm-up frames, each synced by a 1-pixel readPixels; [n]: a slow row's median of n frames (stopped at ${how.frameBudgetMs / 1000} s per size; [1]: one frame, when a single frame takes longer than that — the \`exact\` rows on SwiftShader, where 30 frames at 1920×1080 would take minutes per row). × floor: the ratio to the plain textured sphere at the same size, measured in the same run. Change → next frame: at 1280×720 the view takes the changed settings, draws and reads a pixel back — table rebuild (if any) and frame — median of 3 changes and 3 changes back; the × is the largest of the four against this row's own frame time. First frame: navigation start of a fresh page (Vite dev server, unbundled) to that row's first frame read back. ΔE00: film XYZ rendered by the row's shader (shaders/film/filmColor.glsl's filmXyz; three.js's Rec.709 output taken back to XYZ with its own matrix) into a float target, against the float64 reference, soap film n 1.33 in air, D65, unpolarised; fixed grid 0–2000 nm × 0–85° (3618 films), stress grid 0–20 µm × 0–89.9° (4025 films).`,
  ].join('\n');
}
