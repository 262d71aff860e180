import type { DataTexture } from 'three';
import type { Environment, HdrEnvironment } from '../environments/environments.ts';
import { isHdrEnvironment } from '../environments/environments.ts';
import {
  environmentLoaded,
  environmentTexture,
  loadEnvironmentPixels,
  releaseEnvironmentTexture,
} from '../bubbleMaterials/environmentMaps.ts';

/**
 * A view's HDR environments: which have arrived and which failed (what the view offers its app's
 * frames, src/app/drawnFrame.ts), each fetched once however many frames ask meanwhile, and the map
 * of the one drawn, held while it is. `arrived` is called when one arrives or fails.
 */
export class EnvironmentLoads {
  /** HDR environments being fetched (one request each). */
  private readonly loading = new Set<HdrEnvironment>();
  /** HDR environments that failed to load, with why. */
  private readonly failed = new Map<HdrEnvironment, string>();
  private disposed = false;

  constructor(private readonly arrived: (env: HdrEnvironment) => void) {}

  /** Whether `env`'s map has arrived. */
  loaded(env: HdrEnvironment): boolean {
    return environmentLoaded(env);
  }

  /** Why `env` failed to load, or null. */
  failure(env: HdrEnvironment): string | null {
    return this.failed.get(env) ?? null;
  }

  /** The map of the environment drawn (held until another is drawn), or null for one without a map or not arrived. */
  map(env: Environment): DataTexture | null {
    const map = isHdrEnvironment(env) ? environmentTexture(env, this) : null;
    if (!map) releaseEnvironmentTexture(this);
    return map;
  }

  /** Fetches `env`'s map unless it is on its way or failed. */
  fetch(env: HdrEnvironment): void {
    if (this.loading.has(env) || this.failed.has(env) || environmentLoaded(env)) return;
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
