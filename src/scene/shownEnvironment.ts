import type { DataTexture } from 'three';
import { type Environment, type HdrEnvironment, STAND_IN_ENVIRONMENT, isHdrEnvironment } from '../environments/environments.ts';
import { environmentTexture, loadEnvironmentPixels, releaseEnvironmentTexture } from '../bubble/environmentMaps.ts';

/** Where a view's HDR environment stands: shown, on its way (the stand-in meanwhile), or failed (the stand-in instead). */
export type EnvironmentStatus =
  | { readonly state: 'shown' }
  | { readonly state: 'loading'; readonly env: HdrEnvironment }
  | { readonly state: 'failed'; readonly env: HdrEnvironment; readonly reason: string };

/**
 * The environment a view shows for its settings: an HDR one once its map has arrived, the
 * stand-in (STAND_IN_ENVIRONMENT) while it is on its way or if it failed. Each map is fetched
 * once per view however many frames ask meanwhile; `arrived` is called when one arrives or fails.
 */
export class ShownEnvironment {
  /** HDR environments being fetched (one request each). */
  private readonly loading = new Set<HdrEnvironment>();
  /** HDR environments that failed to load, with why. */
  private readonly failed = new Map<HdrEnvironment, string>();
  private mapShown = false;
  private disposed = false;

  constructor(private readonly arrived: (env: HdrEnvironment) => void) {}

  /** `s` with the environment shown in place of the one asked for, and its map (null for an environment without one). */
  show<S extends { readonly env: Environment }>(s: S): { readonly settings: S; readonly map: DataTexture | null } {
    const env = s.env;
    const map = isHdrEnvironment(env) ? environmentTexture(env, this) : null;
    if (!map) releaseEnvironmentTexture(this);
    if (isHdrEnvironment(env) && !map && !this.failed.has(env) && !this.loading.has(env)) this.load(env);
    this.mapShown = map !== null;
    return { settings: isHdrEnvironment(env) && !map ? { ...s, env: STAND_IN_ENVIRONMENT } : s, map };
  }

  /** Whether `env`, the environment last asked for, is shown, still on its way, or failed. */
  status(env: Environment): EnvironmentStatus {
    if (!isHdrEnvironment(env) || this.mapShown) return { state: 'shown' };
    const reason = this.failed.get(env);
    return reason === undefined ? { state: 'loading', env } : { state: 'failed', env, reason };
  }

  private load(env: HdrEnvironment): void {
    this.loading.add(env);
    const done = () => {
      this.loading.delete(env);
      if (!this.disposed) this.arrived(env);
    };
    loadEnvironmentPixels(env).then(done, (error: unknown) => {
      this.failed.set(env, error instanceof Error ? error.message : String(error));
      done();
    });
  }

  dispose(): void {
    this.disposed = true;
    releaseEnvironmentTexture(this);
  }
}
