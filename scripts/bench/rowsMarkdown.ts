/** The benchmark's main table, as Markdown. */
import type { DeltaStats } from '../harness/deltaStats.ts';
import { THICKNESS_FIELDS } from '../../src/fields/fields.ts';
import type { FilmQuality } from '../../src/settings/filmQuality.ts';
import type { FilmSettings } from '../../src/settings/filmSettings.ts';
import type { BenchPlan } from './benchPlan.ts';
import { type BenchRowResult, EARLIER_MODELS, FIRST_FRAME_SIZE, FIT_OVER_BUDGET } from './benchRow.ts';

export interface MeasuredRow extends Omit<BenchRowResult, 'xyz'> {
  readonly name: string;
  readonly settings: FilmSettings;
  readonly quality: FilmQuality;
  /** per error grid (fixed, stress); null where the row measures no error */
  readonly errors: readonly DeltaStats[] | null;
  /** the row's own time in the run, s */
  readonly seconds: number;
}

const ms = (v: number) => (v >= 100 ? v.toFixed(0) : v.toFixed(1));
const stats = (s: DeltaStats | undefined) => (s ? `${s.max.toFixed(2)} / ${s.p99.toFixed(2)} / ${s.mean.toFixed(3)}` : '—');

/** `a` as a multiple of `b`; — where either is missing. */
const ratio = (a: number | null | undefined, b: number | null | undefined) => (a != null && b ? `${(a / b).toFixed(2)}×` : '—');

/** A row's cells; `turn`: the line of the view taking turns with it, which has only frames. */
function rowCells(r: MeasuredRow, floor: MeasuredRow, plan: BenchPlan, turn = false): string[] {
  const frames = r.frames.map((f, i) => {
    if (f === null) return 'not timed';
    const floorMs = floor.frames[i]?.medianMs;
    const vsFloor = floorMs === undefined ? '' : ` (${ratio(f.medianMs, floorMs)})`;
    if ('fittedFrom' in f) return `≈${ms(f.medianMs)}${vsFloor} [fitted]`;
    return `${ms(f.medianMs)}${vsFloor}${f.count < plan.frames ? ` [${f.count}]` : ''}`;
  });
  const table = r.tableBuildMs === null ? '—' : ms(r.tableBuildMs);
  const timed = r.changeToFrameMs.filter((c): c is number => c !== null);
  const change =
    r === floor || turn
      ? '—'
      : timed.length === 0
        ? 'not timed'
        : `${r.changeToFrameMs.map((c) => (c === null ? '—' : ms(c))).join(' / ')} (${(Math.max(...timed) / r.frames[0]!.medianMs).toFixed(1)}×)`;
  return [
    r.name,
    ...frames,
    table,
    change,
    turn ? '—' : String(r.rebuildsWhileAnimating),
    turn ? '—' : ms(r.firstFrameMs),
    stats(r.errors?.[0]),
    stats(r.errors?.[1]),
    turn ? '—' : r.seconds.toFixed(0),
  ];
}

/** A row taking turns with an earlier model: that model's view, its frames alone, on the line below it. */
const turnCells = (r: MeasuredRow, t: NonNullable<MeasuredRow['turns']>, floor: MeasuredRow, plan: BenchPlan) =>
  rowCells(
    {
      ...r,
      name: `↳ frames taking turns with the row above: ${EARLIER_MODELS[t.model]}`,
      frames: t.frames,
      tableBuildMs: null,
      errors: null,
    },
    floor,
    plan,
    true,
  );

/** Per row taking turns: its frame against the earlier model's at each size. */
const turnsNotes = (rows: readonly MeasuredRow[], plan: BenchPlan): string[] =>
  rows.flatMap((r) =>
    r.turns
      ? [
          `${r.name}, against ${EARLIER_MODELS[r.turns.model]}, frames taking turns: ${plan.sizes.map(([w, h], i) => `${ratio(r.frames[i]?.medianMs, r.turns!.frames[i]?.medianMs)} at ${w}×${h}`).join(', ')} (the earlier model's view drawn with each of the row's frames, before and after it in turn, in the same page, each timed apart).`,
        ]
      : [],
  );

export function rowsMarkdown(rows: readonly MeasuredRow[], plan: BenchPlan): string {
  const floor = rows[0]!; // the plain textured sphere
  const sizeHeads = plan.sizes.map(([w, h]) => `${w}×${h} ms (× floor)`);
  const head = [
    'method',
    ...sizeHeads,
    'first table build ms (with compile)',
    'change → next frame ms: n film / light / polarisation / range (max × own frame)',
    'rebuilds while animating',
    'first frame ms',
    'fixed grid ΔE00 max / p99 / mean',
    'stress grid ΔE00 max / p99 / mean',
    'row s',
  ];
  const lines = rows.flatMap((r) => [rowCells(r, floor, plan), ...(r.turns ? [turnCells(r, r.turns, floor, plan)] : [])]);
  const budgetS = plan.frameBudgetMs / 1000;
  return [
    `| ${head.join(' | ')} |`,
    `|${head.map(() => '---').join('|')}|`,
    ...lines.map((l) => `| ${l.join(' | ')} |`),
    '',
    ...turnsNotes(rows, plan).flatMap((n) => [n, '']),
    `Frame times: median of up to ${plan.frames} frames after ${Math.min(3, plan.frames)} warm-up frames, each synced by a 1-pixel readPixels; [n]: a slow row's median of n frames, stopped at ${budgetS} s per size. [1]: a single frame, where one frame takes longer than ${budgetS} s; ≈ [fitted]: where a frame at a 16th of the pixels, times 16, would take longer than ${FIT_OVER_BUDGET * budgetS} s (the per-fragment \`exact\` rows and the dispersive films' per-fragment bins on SwiftShader), one frame at a 16th and one at a quarter of the pixels, the line through them (a fixed cost plus a cost per pixel) taken to the size's pixels, with no frame drawn at that size; a row over the budget is **trimmed**: its larger sizes are not timed (each frame would take longer still) and neither are its changes (“not timed”). × floor: the ratio to the plain textured sphere at the same size, measured in the same run. Change → next frame: at ${plan.sizes[0]![0]}×${plan.sizes[0]![1]} the view takes the changed settings, draws and reads a pixel back — table rebuild (if any) and frame — the upper median of ${plan.changesBack ? `each change and its way back (the way back only while that change has taken under ${budgetS} s)` : 'each change (its way back not timed)'}, repeated up to ${plan.changeRepeats} times while that change has taken under ${budgetS} s; not timed for the textured sphere, which shows no film, nor for the rows that change only the scene around the default table, whose changes that row times; the × is the largest of the four against this row's own frame time. First frame: navigation start of a fresh page (Vite dev server, unbundled) to that row's first frame read back, drawn at ${FIRST_FRAME_SIZE.join('×')} (the program's compile and the table's build, with few fragments)${plan.pagePerLane ? "; here each lane's rows share a page, and a later row's first frame is timed from its start in that warm page" : ''}. ΔE00: film XYZ rendered by the row's shader (shaders/film/filmColor.glsl's filmXyz; three.js's Rec.709 output taken back to XYZ with its own matrix) into a float target, against the float64 reference, the row's film in air, D65, unpolarised; fixed grid 0–2000 nm × 0–85° (3618 films), stress grid 0–20 µm × 0–89.9° (4025 films)${plan.gridStride > 1 ? `, every ${plan.gridStride}th film of each` : ''}. Row s: the row's own time in this run (page load${plan.pagePerLane ? ", for a lane's first row" : ''}, frames, changes, the grids drawn and compared).${rows.some((r) => THICKNESS_FIELDS[r.settings.field].evolves) ? " Flow field rows: each frame advances the film time by 1/60 s, as the app's frames at 60 Hz with simSpeed 1, and takes the whole steps that time asks (the number in the row's name is their mean; a frame takes the whole number below or above it, so a single frame [1] may hold one step more or less), each step the simulation's draws (the flow simulation's table below), then the halo of the film the bubble samples and the bubble's frame; the film starts at time 0, so the frames timed show its first second of drainage." : ''}`,
  ].join('\n');
}
