/** Builds the demo and the element (as `npm run build` does) and reports the gzipped size of their JavaScript. */
import { readFileSync, readdirSync } from 'node:fs';
import { join, relative } from 'node:path';
import { gzipSync } from 'node:zlib';
import { build } from 'vite';

/** The embeddable element's bundle, where the build makes one. */
export const ELEMENT_BUNDLE = 'dist/thin-film-bubble.js';

export interface BundleSizes {
  /** every JS file in dist: path → bytes and gzipped bytes */
  readonly files: Record<string, { readonly bytes: number; readonly gzipBytes: number }>;
  /** what a page loads up front: every JS file but the element, the HDR environments' modules and the material's example page */
  readonly demoGzipBytes: number;
  readonly elementGzipBytes: number | null;
  /** each HDR environment's module (fetched only when shown), gzipped */
  readonly environmentGzipBytes: readonly number[];
}

/** An HDR environment's module, as the build names it (environmentMaps.ts imports `…/hdri/<name>.exr.js`). */
const isEnvironmentModule = (path: string) => /\.exr-[^/]*\.js$/.test(path);
/** The material's example page's own module (materials.html), which the demo does not load. */
const isExamplePage = (path: string) => /\/materials-[^/]*\.js$/.test(path);

const jsFiles = (dir: string): string[] =>
  readdirSync(dir, { withFileTypes: true }).flatMap((e) =>
    e.isDirectory() ? jsFiles(join(dir, e.name)) : e.name.endsWith('.js') ? [join(dir, e.name)] : [],
  );

export async function buildAndMeasure(): Promise<BundleSizes> {
  await build({ logLevel: 'silent' });
  await build({ logLevel: 'silent', mode: 'element' });
  const files: Record<string, { bytes: number; gzipBytes: number }> = {};
  for (const path of jsFiles('dist')) {
    const text = readFileSync(path);
    files[relative('.', path)] = { bytes: text.length, gzipBytes: gzipSync(text, { level: 9 }).length };
  }
  const element = files[ELEMENT_BUNDLE]?.gzipBytes ?? null;
  const demo = Object.entries(files)
    .filter(([path]) => path !== ELEMENT_BUNDLE && !isEnvironmentModule(path) && !isExamplePage(path))
    .reduce((sum, [, f]) => sum + f.gzipBytes, 0);
  const environments = Object.entries(files).filter(([path]) => isEnvironmentModule(path));
  return { files, demoGzipBytes: demo, elementGzipBytes: element, environmentGzipBytes: environments.map(([, f]) => f.gzipBytes) };
}
