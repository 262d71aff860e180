import { existsSync } from 'node:fs';
import { chromium, type Browser } from '@playwright/test';

/** Playwright's launch options for a Chromium (executablePath left out: Playwright's own). */
export interface ChromiumLaunchOptions {
  executablePath?: string;
  args: string[];
}

/** The Chromium found, as launch options, or one line saying why none was found and how to get one. */
export type ChromiumSearch = { readonly found: ChromiumLaunchOptions } | { readonly missing: string };

/** A CPU WebGL backend of headless Chromium: its launch flags and the WebGL2 renderer it must give. */
export interface GlBackend {
  readonly args: readonly string[];
  /** What the unmasked WebGL2 renderer string contains on this backend (docs/browser.md#backends). */
  readonly renderer: string;
}

/** Flags every backend shares: the GPU blocklist ignored (a CPU device is on it), no QUIC. */
const COMMON_ARGS = ['--ignore-gpu-blocklist', '--disable-quic'];

/**
 * The CPU backends the tests, the benchmark and the render command can run on (docs/browser.md#backends).
 * SwiftShader compiles on the calling thread; Mesa llvmpipe, through ANGLE's EGL, offers
 * KHR_parallel_shader_compile. Both enable EXT_disjoint_timer_query_webgl2 and WEBGL_lose_context.
 */
export const GL_BACKENDS = {
  llvmpipe: { args: ['--use-gl=angle', '--use-angle=gles-egl', ...COMMON_ARGS], renderer: 'llvmpipe' },
  swiftshader: { args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', ...COMMON_ARGS], renderer: 'SwiftShader' },
} as const satisfies Record<string, GlBackend>;
export type GlBackendName = keyof typeof GL_BACKENDS;
export const GL_BACKEND_NAMES = Object.keys(GL_BACKENDS) as GlBackendName[];

/** The backend used when TFC_GL is not set: the one with the shorter browser suite, every test passing (docs/testing.md). */
export const DEFAULT_GL_BACKEND: GlBackendName = 'llvmpipe';

/** The backend named by `setting` (TFC_GL's value; unset or empty means the default), or a message naming the known ones. */
export function parseGlBackend(setting: string | undefined): { readonly name: GlBackendName } | { readonly unknown: string } {
  if (setting === undefined || setting === '') return { name: DEFAULT_GL_BACKEND };
  if ((GL_BACKEND_NAMES as string[]).includes(setting)) return { name: setting as GlBackendName };
  return { unknown: `TFC_GL=${JSON.stringify(setting.slice(0, 40))} is not a known WebGL backend; known: ${GL_BACKEND_NAMES.join(', ')}.` };
}

/** The backend TFC_GL names; an unknown name stops the run (exit 2) with the list of known ones. */
export function glBackendName(): GlBackendName {
  const parsed = parseGlBackend(process.env.TFC_GL);
  if ('name' in parsed) return parsed.name;
  console.error(parsed.unknown);
  return process.exit(2);
}

/** The backend TFC_GL does not name: the browser tests' `@both-backends` tests run on it too (docs/testing.md). */
export const otherGlBackend = (): GlBackendName => GL_BACKEND_NAMES.find((n) => n !== glBackendName())!;

const found = (executablePath: string | undefined, backend: GlBackendName): ChromiumSearch => ({
  found: { ...(executablePath ? { executablePath } : {}), args: [...GL_BACKENDS[backend].args] },
});
const missing = (why: string): ChromiumSearch => ({
  missing: `${why} Install one (Debian: apt-get install -y chromium; elsewhere: npx playwright install chromium) or set CHROME_PATH.`,
});

/**
 * The Chromium that the browser tests, the benchmark and the render command launch: CHROME_PATH
 * if set, else Debian's /usr/bin/chromium, else the browser Playwright downloads with
 * `npx playwright install chromium`; with the flags of `backend` (the one TFC_GL names unless given).
 */
export function findChromium(backend: GlBackendName = glBackendName()): ChromiumSearch {
  const fromEnv = process.env.CHROME_PATH;
  if (fromEnv) return existsSync(fromEnv) ? found(fromEnv, backend) : missing(`CHROME_PATH=${fromEnv} does not exist.`);
  if (existsSync('/usr/bin/chromium')) return found('/usr/bin/chromium', backend);
  if (existsSync(chromium.executablePath())) return found(undefined, backend);
  return missing('no Chromium found.');
}

/**
 * WebGPU in headless Chromium on a CPU (docs/testing.md#webgpu): SwiftShader's Vulkan adapter, which
 * needs a system Vulkan driver (Debian's mesa-vulkan-drivers) and these features; this launch has no
 * WebGL2, and `--ignore-gpu-blocklist` loses its WebGPU context.
 */
export const WEBGPU_ARGS = ['--enable-unsafe-webgpu', '--enable-features=Vulkan,VulkanFromANGLE,DefaultANGLEVulkan', '--use-angle=vulkan'];

/** Launch options for the WebGPU tests: the Chromium found, with WEBGPU_ARGS for flags. */
export const webgpuLaunchOptions = (): ChromiumLaunchOptions => ({ ...chromiumLaunchOptions(), args: [...WEBGPU_ARGS] });

/** Launch options for the tests and the benchmark on `backend`: with no Chromium, the run stops (exit 1) with the line saying how to get one. */
export function chromiumLaunchOptions(backend: GlBackendName = glBackendName()): ChromiumLaunchOptions {
  const search = findChromium(backend);
  if ('found' in search) return search.found;
  console.error(search.missing);
  return process.exit(1);
}

/** The unmasked WebGL2 renderer string of a page of `browser`, or 'no WebGL2'. */
export async function webgl2Renderer(browser: Browser): Promise<string> {
  const page = await browser.newPage();
  try {
    return await page.evaluate(() => {
      const gl = document.createElement('canvas').getContext('webgl2');
      if (!gl) return 'no WebGL2';
      const info = gl.getExtension('WEBGL_debug_renderer_info');
      return String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
    });
  } finally {
    await page.close();
  }
}

/**
 * The renderer `browser` gives, checked against the backend `name` (the one TFC_GL names unless
 * given): a browser that fell back to another backend, or to no WebGL2 at all, throws. Returns one line for a report.
 */
export async function checkedRenderer(browser: Browser, name: GlBackendName = glBackendName()): Promise<string> {
  const renderer = await webgl2Renderer(browser);
  if (!renderer.includes(GL_BACKENDS[name].renderer)) {
    throw new Error(
      `The WebGL backend ${name} asks for a WebGL2 renderer with "${GL_BACKENDS[name].renderer}" in its name; Chromium gave "${renderer}".`,
    );
  }
  return `WebGL2 backend ${name}: ${renderer}`;
}
