/**
 * A spectral node material's next program, built off the frame. Where an option change asks for a
 * program the material has not drawn (`table` ↔ `exact`, say), three would build it inside the
 * next render, its nodes in one piece and, on WebGL2, its link waited for: a long task. Instead the
 * material keeps drawing the program it has, its film as last drawn, while a stand-in (a copy of
 * the material, keyed, lit and drawn as the material will be) is built by three's compileAsync in
 * the scene, from the camera and into the target the material was last drawn with: its nodes
 * built stage by stage with the page let in between, its GPU program compiled (linked in parallel
 * where the context can) without a wait on this thread. Once it is built the material's version
 * moves, and its next render finds the program in three's caches: it builds nothing.
 */
import { type Camera, type Material, type Object3D, type RenderTarget, type Scene } from 'three';
import { type NodeFrame, type Renderer } from 'three/webgpu';
import { type PhysicalMaterial } from './physicalMaterial.ts';
import { type NodeFilm } from './nodeFilm.ts';

/** Where and how the material was last drawn: what the stand-in is built for. */
export interface LastDraw {
  readonly renderer: Renderer;
  readonly object: Object3D;
  readonly camera: Camera;
  readonly scene: Scene;
  readonly target: RenderTarget | null;
}

/** What a film builds ahead: the build running, whether a change came meanwhile, and what a program's first draw lets go. */
export interface Ahead {
  building: Promise<void> | null;
  again: boolean;
  /** by the program they wait for (its build's token): what that program's first draw of the material releases */
  readonly retiring: WeakMap<object, (() => void)[]>;
}

export const newAhead = (): Ahead => ({ building: null, again: false, retiring: new WeakMap() });

/** Each stand-in and the material it stands in for. */
const standIns = new WeakMap<Material, PhysicalMaterial>();

/** The material a program is built for: the material itself, or the one a stand-in stands in for. */
export const materialBuilt = (m: Material): PhysicalMaterial => standIns.get(m) ?? (m as PhysicalMaterial);

/** Whether `m` is a stand-in (whose draws are builds ahead, not the material's). */
export const isStandIn = (m: Material | null): boolean => m !== null && standIns.has(m);

/**
 * Each render target a spectral material was drawn into, and whether it has been disposed since
 * (a target drawn into again is live again): a build ahead into a disposed one would compile
 * against attachments three has let go.
 */
const targetDisposed = new WeakMap<RenderTarget, boolean>();

/** Notes where the material was drawn, from a frame of its own draw (the caller leaves out a stand-in's builds). */
export function noteDraw(f: NodeFilm, frame: NodeFrame): void {
  const { renderer, object, camera, scene } = frame;
  if (!renderer || !object || !camera || !scene) return;
  const target = renderer.getRenderTarget();
  if (target) {
    if (!targetDisposed.has(target)) target.addEventListener('dispose', () => targetDisposed.set(target, true));
    targetDisposed.set(target, false);
  }
  f.lastDraw = { renderer, object, camera, scene, target };
}

/** Releases, once, what waits for the program of `token` to draw the material. */
export function retireFor(f: NodeFilm, token: object): void {
  const waiting = f.ahead.retiring.get(token);
  if (!waiting) return;
  f.ahead.retiring.delete(token);
  queueMicrotask(() => waiting.forEach((release) => release()));
}

/**
 * Has `release` run at the first draw of the material by the program of `token` (after that
 * render: what it releases may be three's, which a render must not lose midway).
 */
export function retireAt(f: NodeFilm, token: object, release: () => void): void {
  const waiting = f.ahead.retiring.get(token) ?? [];
  waiting.push(release);
  f.ahead.retiring.set(token, waiting);
}

/**
 * Builds `m`'s program for its options now off the frame, where it has been drawn: true; false
 * where it has not (its first draw builds it, as any first draw does), or where the target it was
 * last drawn into has been disposed since (three keys a program by its target's kind, and the next
 * draw, wherever it is, builds it), so that the caller moves the version at once.
 */
export function buildAhead(f: NodeFilm, m: PhysicalMaterial): boolean {
  const draw = f.lastDraw;
  if (!draw || (draw.target !== null && targetDisposed.get(draw.target) === true)) return false;
  if (f.ahead.building) {
    f.ahead.again = true;
    return true;
  }
  f.ahead.building = buildUntilCurrent(f, m, draw).finally(() => (f.ahead.building = null));
  return true;
}

/**
 * Builds stand-ins until one holds the material's options as they are when it is done; then moves
 * the material's version (also where a build failed: three then builds the program at the next draw).
 */
async function buildUntilCurrent(f: NodeFilm, m: PhysicalMaterial, draw: LastDraw): Promise<void> {
  try {
    do {
      f.ahead.again = false;
      const standIn = standInFor(m);
      const proxy = draw.object.clone(false) as Object3D & { material: Material };
      proxy.material = standIn;
      // compileAsync takes the render target as it starts (three's precompilation state), synchronously.
      const previous = draw.renderer.getRenderTarget();
      draw.renderer.setRenderTarget(draw.target);
      const compiled = draw.renderer.compileAsync(proxy, draw.camera, draw.scene);
      draw.renderer.setRenderTarget(previous);
      await compiled;
      // A stand-in overtaken by a later change goes with its program; the last one stays until the material draws its program.
      if (f.ahead.again) standIn.dispose();
    } while (f.ahead.again);
  } finally {
    m.needsUpdate = true;
  }
}

/**
 * A material that three keys, builds and lights as `m` with its present options: of `m`'s class,
 * holding `m`'s own properties (three's key lists them in their order; the film's hooks among them,
 * as values) and `m`'s program key. Not a clone: three's copy of a physical
 * node material reads its deprecated iridescenceThicknessRange, which warns.
 */
function standInFor(m: PhysicalMaterial): PhysicalMaterial {
  const standIn = new (m.constructor as new () => PhysicalMaterial)();
  const own = m as unknown as Record<string, unknown>;
  for (const key of Object.keys(m))
    if (!/^(uuid|version|_listeners)$/.test(key))
      Object.defineProperty(standIn, key, { configurable: true, enumerable: true, writable: true, value: own[key] });
  Object.defineProperty(standIn, 'customProgramCacheKey', { configurable: true, writable: true, value: () => m.customProgramCacheKey() });
  standIns.set(standIn, m);
  return standIn;
}
