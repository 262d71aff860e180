/** How many times a page is loaded for WebGPU: a fresh browser's first WebGPU page may find no adapter. */
const WEBGPU_LOAD_ATTEMPTS = 3;

/**
 * Loads a page with `load`, which answers the backend WebGPURenderer started on, again until it is
 * `backend`, WEBGPU_LOAD_ATTEMPTS times at most; whether it was.
 */
export async function loadOnBackend(backend: string, load: () => Promise<string>): Promise<boolean> {
  for (let attempt = 0; attempt < WEBGPU_LOAD_ATTEMPTS; attempt++) if ((await load()) === backend) return true;
  return false;
}
