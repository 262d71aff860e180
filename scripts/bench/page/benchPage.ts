/**
 * The benchmark page: one row per page load. It builds the demo's BubbleView with the row's
 * settings and quality, times frames synced with a 1-pixel readPixels, and renders the error
 * grids through the same film shader (FilmXyzProbe) on its own renderer.
 */
import { DataTexture, Mesh, MeshBasicMaterial, RGBAFormat, SRGBColorSpace, WebGLRenderer } from 'three';
import { BubbleView, createBubbleRenderer } from '../../../src/scene/bubbleView.ts';
import { FilmXyzProbe } from '../../harness/filmXyzProbe.ts';
import { loadEnvironmentPixels } from '../../../src/bubble/environmentMaps.ts';
import { isHdrEnvironment } from '../../../src/settings/filmSettings.ts';
import { type BenchRowSpec, CHANGES, FIRST_FRAME_SIZE, FIT_OVER_BUDGET, type FrameTime, fitSizes, fittedFrameMs } from '../benchRow.ts';

const canvas = document.querySelector<HTMLCanvasElement>('#bubble');
if (!canvas) throw new Error('bench.html must hold #bubble');

/** A frame four times the pixels taking at least this many times as long is mostly a cost per pixel. */
const PIXEL_BOUND = 2;

const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)]!;

/** A 256² sRGB texture for the floor row: the sphere then costs one texture fetch per pixel. */
function checkerTexture(): DataTexture {
  const size = 256;
  const data = new Uint8Array(4 * size * size);
  for (let i = 0; i < size * size; i++) {
    const v = (((i % size) >> 4) + ((i / size) >> 4)) % 2 ? 220 : 90;
    data.set([v, (v * 3) >> 2, 255 - v, 255], 4 * i);
  }
  const t = new DataTexture(data, size, size, RGBAFormat);
  t.colorSpace = SRGBColorSpace;
  t.needsUpdate = true;
  return t;
}

window.benchRow = async (spec: BenchRowSpec) => {
  // An HDR environment is fetched first, so the view shows it from its first frame.
  if (isHdrEnvironment(spec.settings.env)) await loadEnvironmentPixels(spec.settings.env);
  const view = new BubbleView(createBubbleRenderer(canvas), spec.settings, spec.quality);
  if (!spec.reflections) {
    // The model before environment reflections: reflectedRadiance (shaders/bubble/environment.glsl) returns the light's white.
    const m = view.bubble.material;
    m.onBeforeCompile = (shader) => {
      shader.fragmentShader = shader.fragmentShader.replace(/vec3 reflectedRadiance\(vec3 direction\) \{/, '$&\n  return vec3(1.0);');
    };
    m.customProgramCacheKey = () => 'walls reflect white';
  }
  if (spec.kind === 'textured') {
    view.bubble.visible = false;
    view.scene.add(new Mesh(view.bubble.geometry, new MeshBasicMaterial({ map: checkerTexture() })));
  }
  const gl = view.renderer.getContext();
  const pixel = new Uint8Array(4);
  let time = spec.settings.timeSeconds;
  const frame = () => {
    const started = performance.now();
    time += 1 / 60; // the animated field moves, as in the demo's loop
    view.apply({ ...view.current, timeSeconds: time });
    view.render();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    return performance.now() - started;
  };
  // The first frame, small: the program's compile and the table's build, without a slow row's
  // full-size fragment cost, which the timed frames then measure once each.
  view.resize(...FIRST_FRAME_SIZE);
  view.render();
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
  const firstFrameMs = performance.now();
  const tableBuildMs = spec.settings.mode === 'table' && spec.kind === 'bubble' ? view.table.lastBuildMs : null;
  const buildsBefore = view.table.builds;

  // Per size: up to 3 warm-up frames, then up to `frames` timed ones within the budget. Where a
  // frame at a 16th of the pixels, times 16, would outlast FIT_OVER_BUDGET budgets, the frame
  // time is fitted from that frame and one at a quarter of the pixels (fittedFrameMs): a slow row's
  // full frame (tens of seconds of per-fragment bins on a CPU rasteriser) is not drawn. A frame over
  // the budget, timed or fitted, is its own measurement, and the larger sizes are not timed (null):
  // each would cost more than it.
  const frames: (FrameTime | null)[] = [];
  const pixels = ([w, h]: readonly [number, number]) => w * h;
  let slow = false;
  for (const size of spec.sizes) {
    if (slow) {
      frames.push(null);
      continue;
    }
    const [small, larger] = fitSizes(size);
    view.resize(...small);
    // Over the threshold, a second frame confirms it (the faster of the two): on a busy machine one
    // frame of a fast row can come late.
    const overThreshold = (ms: number) => (ms * pixels(size)) / pixels(small) > FIT_OVER_BUDGET * spec.frameBudgetMs;
    let smallMs = frame();
    if (overThreshold(smallMs)) smallMs = Math.min(smallMs, frame());
    if (overThreshold(smallMs)) {
      view.resize(...larger);
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
      if (largerMs >= PIXEL_BOUND * smallMs && fittedMs > FIT_OVER_BUDGET * spec.frameBudgetMs) {
        slow = true;
        frames.push({ medianMs: fittedMs, fittedFrom: [small, larger] });
        continue;
      }
    }
    view.resize(...size);
    const warm = [frame()];
    slow = warm[0]! > spec.frameBudgetMs;
    if (slow) {
      frames.push({ medianMs: warm[0]!, count: 1 });
      continue;
    }
    while (warm.length < Math.min(3, spec.frames)) warm.push(frame());
    const count = Math.max(Math.min(3, spec.frames), Math.min(spec.frames, Math.floor(spec.frameBudgetMs / Math.min(...warm))));
    const times = Array.from({ length: count }, frame);
    frames.push({ medianMs: median(times), count });
  }
  const rebuildsWhileAnimating = view.table.builds - buildsBefore;
  // Each change and its way back (timed too where `changesBack`, while that change has taken less
  // than the budget; else drawn with the next change), up to `changeRepeats` times while that
  // change has taken less than the budget; none (null) for the textured sphere, which shows no
  // film, for a row that does not time them, and for a row whose frame alone outlasts the budget.
  view.resize(...spec.sizes[0]!);
  const changesTimed = spec.kind === 'bubble' && spec.timesChanges && frames[0]!.medianMs <= spec.frameBudgetMs;
  const changeToFrameMs = CHANGES.map(({ values }) => {
    if (!changesTimed) return null;
    const times: number[] = [];
    let spentMs = 0;
    for (let repeat = 0; repeat < spec.changeRepeats && (repeat === 0 || spentMs < spec.frameBudgetMs); repeat++)
      for (const [i, v] of values(spec.settings).entries()) {
        const started = performance.now();
        view.apply({ ...view.current, ...v });
        if (i > 0 && !(spec.changesBack && spentMs < spec.frameBudgetMs)) continue; // drawn with the next change
        view.render();
        gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
        times.push(performance.now() - started);
        spentMs += times.at(-1)!;
      }
    return median(times);
  });
  view.dispose();

  let xyz: number[][][] = [];
  if (spec.grids.length > 0) {
    const renderer = new WebGLRenderer({ canvas: document.createElement('canvas') });
    xyz = new FilmXyzProbe(renderer).render(spec.grids, spec.settings.mode, spec.quality);
    renderer.dispose();
  }
  return { firstFrameMs, tableBuildMs, rebuildsWhileAnimating, frames, changeToFrameMs, xyz };
};
document.body.dataset.ready = 'yes';
