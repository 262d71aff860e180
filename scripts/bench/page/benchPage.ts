/**
 * The benchmark page: `benchRow` runs one row, once in a fresh page or (the smoke's
 * `pagePerLane`) once per row of a lane in the same page; `benchFlowSpeed` times the flowing
 * film's GPU simulation (gpuFlowSpeed.ts). It builds the demo's BubbleView with the
 * row's settings and quality, times frames synced with a 1-pixel readPixels, and renders the error
 * grids through the same film shader (FilmXyzProbe) on a renderer of their own. A row disposes all
 * it made on the page's renderer and checks that nothing is left there, so that a later row finds
 * the renderer as the first found it.
 */
import { WebGLRenderer } from 'three';
import { createBubbleRenderer } from '../../../src/view/bubbleRenderer.ts';
import { FilmXyzProbe } from '../../harness/filmXyzProbe.ts';
import { loadEnvironmentPixels } from '../../../src/bubbleMaterials/environmentMaps.ts';
import { type FilmSettings, isHdrEnvironment } from '../../../src/settings/filmSettings.ts';
import {
  type BenchRowResult,
  type BenchRowSpec,
  CHANGES,
  FIRST_FRAME_SIZE,
  FIT_OVER_BUDGET,
  type FrameTime,
  fitSizes,
  fittedFrameMs,
} from '../benchRow.ts';
import type { FlowSpeedPlan } from '../flowSpeed.ts';
import { gpuFlowSpeed } from './gpuFlowSpeed.ts';
import { type RowScene, rowScene } from './rowScene.ts';
import { RowViews, drawAndWait } from './rowViews.ts';
import { TableWatch } from './tableWatch.ts';
import { median } from '../median.ts';
import { methodReads } from '../../../src/methods/methods.ts';

const canvas = document.querySelector<HTMLCanvasElement>('#bubble');
if (!canvas) throw new Error('bench.html must hold #bubble');
/** The renderer of every row's view: one per canvas, as a second WebGLRenderer would share the canvas's context without knowing its state. */
const renderer = createBubbleRenderer(canvas);
/**
 * The error grids' probe on its own canvas, made at the page's first row that measures error and
 * kept for its later rows: its programs compile once per film mode and quality, and its tables
 * are drawn anew around each grid (the table pass in only the columns the grid's films read).
 */
let gridProbe: FilmXyzProbe | null = null;
/** Rows run in this page so far. */
let rowsRun = 0;

/** A frame four times the pixels taking at least this many times as long is mostly a cost per pixel. */
const PIXEL_BOUND = 2;

/**
 * The textures a row may leave on the page's renderer once the grids' probe is made: a light's bin
 * weights and spectral transform, for the film material and for its table. SharedTextures shares
 * them with the probe's materials and tables, which hold them for the page, so the next row with
 * the same light finds them with the same texels. Before the probe is made (every row of a fresh
 * page) a row leaves none.
 */
const TEXTURES_SHARED_WITH_PROBE = 4;

/** What a row left on the page's renderer after disposing all it made, beyond what the probe shares; null: nothing. */
function leftOnRenderer(): string | null {
  const { memory, programs } = renderer.info;
  const left = { programs: programs?.length ?? 0, geometries: memory.geometries, textures: memory.textures };
  const sharedTextures = gridProbe ? TEXTURES_SHARED_WITH_PROBE : 0;
  return left.programs > 0 || left.geometries > 0 || left.textures > sharedTextures ? JSON.stringify(left) : null;
}

/** Draws the views' next frame and returns the row's time (ms). */
type TimedFrame = () => number;

/** The row's film as last shown: the frames move its time on, the changes change it. */
interface ShownFilm {
  film: FilmSettings;
}

/** The views' frames from the film's time on, the animated field moving 1/60 s a frame as in the demo's loop. */
function animatedFrames(views: RowViews, shown: ShownFilm): TimedFrame {
  return () => {
    shown.film = { ...shown.film, timeSeconds: shown.film.timeSeconds + 1 / 60 };
    return views.frame(shown.film);
  };
}

const pixels = ([w, h]: readonly [number, number]) => w * h;

/**
 * A slow row's frame at `size`, fitted rather than drawn, or null where it is to be drawn. Where a
 * frame at a 16th of the pixels, times 16, would outlast FIT_OVER_BUDGET budgets, the frame time is
 * fitted from that frame and one at a quarter of the pixels (fittedFrameMs): a slow row's full frame
 * (tens of seconds of per-fragment bins on a CPU rasteriser) is not drawn.
 */
function fittedFrame(views: RowViews, spec: BenchRowSpec, size: readonly [number, number], frame: TimedFrame): FrameTime | null {
  const [small, larger] = fitSizes(size);
  views.resize(small);
  // Over the threshold, a second frame confirms it (the faster of the two): on a busy machine one
  // frame of a fast row can come late.
  const overThreshold = (ms: number) => (ms * pixels(size)) / pixels(small) > FIT_OVER_BUDGET * spec.frameBudgetMs;
  let smallMs = frame();
  if (overThreshold(smallMs)) smallMs = Math.min(smallMs, frame());
  if (!overThreshold(smallMs)) return null;
  views.resize(larger);
  const largerMs = frame();
  const fittedMs = fittedFrameMs(
    [
      [pixels(small), smallMs],
      [pixels(larger), largerMs],
    ],
    pixels(size),
  );
  // Fitted only where the frame is mostly a cost per pixel (4× the pixels took ≥ PIXEL_BOUND× the
  // time): a fixed cost's noise, taken 4× along the line, would say nothing.
  return largerMs >= PIXEL_BOUND * smallMs && fittedMs > FIT_OVER_BUDGET * spec.frameBudgetMs
    ? { medianMs: fittedMs, fittedFrom: [small, larger] }
    : null;
}

/** After a first frame at the size within the budget (`firstMs`): up to 3 warm-up frames, then up to `frames` timed ones within the budget. */
function drawnFrame(spec: BenchRowSpec, firstMs: number, frame: TimedFrame): { medianMs: number; count: number } {
  const warm = [firstMs];
  while (warm.length < Math.min(3, spec.frames)) warm.push(frame());
  const count = Math.max(Math.min(3, spec.frames), Math.min(spec.frames, Math.floor(spec.frameBudgetMs / Math.min(...warm))));
  const times = Array.from({ length: count }, frame);
  return { medianMs: median(times), count };
}

/** Per size, the row's frame time and the turns' (null without turns, or where the row's is not drawn in full). */
interface FrameTimes {
  readonly frames: (FrameTime | null)[];
  readonly turns: (FrameTime | null)[];
}

/**
 * The frame time per size, fitted (fittedFrame) or drawn (drawnFrame). A frame over the budget,
 * timed or fitted, is its own measurement, and the larger sizes are not timed (null): each would
 * cost more than it.
 */
function frameTimes(views: RowViews, spec: BenchRowSpec, frame: TimedFrame): FrameTimes {
  const out: FrameTimes = { frames: [], turns: [] };
  let slow = false;
  for (const size of spec.sizes) {
    const fitted = slow ? null : fittedFrame(views, spec, size, frame);
    if (slow || fitted) {
      slow = true;
      out.frames.push(fitted);
      out.turns.push(null);
      continue;
    }
    views.resize(size);
    const firstMs = frame();
    slow = firstMs > spec.frameBudgetMs;
    const drawn = slow ? { medianMs: firstMs, count: 1 } : drawnFrame(spec, firstMs, frame);
    out.frames.push(drawn);
    out.turns.push(slow ? null : views.turnFrame(drawn.count));
  }
  return out;
}

/**
 * Each change and its way back (timed too where `changesBack`, while that change has taken less
 * than the budget; else drawn with the next change), up to `changeRepeats` times while that
 * change has taken less than the budget: the change applied → its frame drawn and read back, ms
 * (the median). None (null) for the textured sphere, which shows no film, for a row that does not
 * time them, and for a row whose frame alone outlasts the budget.
 */
function changeTimes(scene: RowScene, spec: BenchRowSpec, firstSizeMs: number, shown: ShownFilm): (number | null)[] {
  scene.view.resize(...spec.sizes[0]!);
  const changesTimed = spec.kind === 'bubble' && spec.timesChanges && firstSizeMs <= spec.frameBudgetMs;
  return CHANGES.map(({ values }) => {
    if (!changesTimed) return null;
    const times: number[] = [];
    let spentMs = 0;
    for (let repeat = 0; repeat < spec.changeRepeats && (repeat === 0 || spentMs < spec.frameBudgetMs); repeat++)
      for (const [i, v] of values(spec.settings).entries()) {
        const started = performance.now();
        shown.film = { ...shown.film, ...v };
        scene.show(shown.film);
        if (i > 0 && !(spec.changesBack && spentMs < spec.frameBudgetMs)) continue; // drawn with the next change
        drawAndWait(scene);
        times.push(performance.now() - started);
        spentMs += times.at(-1)!;
      }
    return median(times);
  });
}

/**
 * The row's figures but its error grids: the first frame (from `originMs`), the frames per size,
 * the changes.
 */
function timeView(views: RowViews, spec: BenchRowSpec, originMs: number): Omit<BenchRowResult, 'xyz'> {
  // The first frame, small: the program's compile and the table's build, without a slow row's
  // full-size fragment cost, which the timed frames then measure once each.
  views.resize(FIRST_FRAME_SIZE);
  const table = new TableWatch(views.own.view.table);
  drawAndWait(views.own);
  const firstFrameMs = performance.now() - originMs;
  const tableBuildMs = methodReads(spec.settings.mode, 'table') && spec.kind === 'bubble' ? table.firstBuildMs : null;
  // The view taking turns: its compile and build, untimed (the second in the page, it would share the first's).
  if (views.turns) drawAndWait(views.turns);
  const buildsBefore = table.builds;
  const shown: ShownFilm = { film: spec.settings };
  const { frames, turns } = frameTimes(views, spec, animatedFrames(views, shown));
  const rebuildsWhileAnimating = table.builds - buildsBefore;
  table.stop();
  const changeToFrameMs = changeTimes(views.own, spec, frames[0]!.medianMs, shown);
  return {
    firstFrameMs,
    tableBuildMs,
    rebuildsWhileAnimating,
    frames,
    changeToFrameMs,
    turns: spec.takesTurnsWith === null ? null : { model: spec.takesTurnsWith, frames: turns },
  };
}

window.benchRow = async (spec: BenchRowSpec) => {
  // A page's first row counts its first frame from navigation start: a cold page's, with the
  // modules' load and the context's creation. A later row in the same page (the smoke's
  // pagePerLane) counts from this call's start: its first frame is that of a page already warm.
  const originMs = rowsRun++ === 0 ? 0 : performance.now();
  // An HDR environment is fetched first, so the view shows it from its first frame.
  if (isHdrEnvironment(spec.settings.env)) await loadEnvironmentPixels(spec.settings.env);
  const views = new RowViews(
    rowScene(renderer, spec),
    spec.takesTurnsWith === null ? null : rowScene(renderer, { ...spec, earlierModel: spec.takesTurnsWith }),
  );
  let timed: Omit<BenchRowResult, 'xyz'>;
  try {
    timed = timeView(views, spec, originMs);
  } finally {
    views.dispose();
  }
  const left = leftOnRenderer();
  if (left) throw new Error(`the row left ${left} on the page's renderer`);

  let xyz: number[][][] = [];
  if (spec.grids.length > 0) {
    gridProbe ??= new FilmXyzProbe(new WebGLRenderer({ canvas: document.createElement('canvas') }));
    xyz = gridProbe.render(spec.grids, spec.settings.mode, spec.quality);
  }
  return { ...timed, xyz };
};
window.benchFlowSpeed = (plan: FlowSpeedPlan) => {
  const speeds = gpuFlowSpeed(renderer, plan);
  const left = leftOnRenderer();
  if (left) throw new Error(`the flow's simulations left ${left} on the page's renderer`);
  return speeds;
};
document.body.dataset.ready = 'yes';
