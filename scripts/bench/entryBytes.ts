/**
 * What each material entry of the library adds to a user's build: a minimal three.js app on the
 * entry's renderer, built by Vite as a user builds it, as three ships it and made spectral by the
 * entry from the library as it is packed (`vite build --mode lib`). Eager: the JavaScript the app
 * loads at start (its entry chunk and that chunk's static imports); emitted: every file of the
 * build (the chunks loaded later, the workers), all gzipped.
 */
import { mkdirSync, rmSync, writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { gzipSync } from 'node:zlib';
import { type Rolldown, build } from 'vite';

/** One material entry and the minimal app of its renderer, as three ships it and made spectral by the entry. */
export interface MaterialEntryApp {
  /** the package entry (package.json `exports`) */
  readonly entry: string;
  /** its module in the library's build (vite.config.ts's LIBRARY_ENTRIES) */
  readonly libraryFile: string;
  /** the renderer the app draws with, and its one iridescent material */
  readonly renderer: string;
  readonly material: string;
  /** the app's source: three's own where `spectral` is null, else made spectral through the entry's module at that path */
  readonly app: (spectral: string | null) => string;
}

/** The entries measured: one line per entry. */
export const MATERIAL_ENTRY_APPS: readonly MaterialEntryApp[] = [
  {
    entry: 'thin-film-color/material',
    libraryFile: 'material.js',
    renderer: 'WebGLRenderer',
    material: 'MeshPhysicalMaterial',
    app: (spectral) => `
import { Mesh, MeshPhysicalMaterial, PerspectiveCamera, Scene, TorusKnotGeometry, WebGLRenderer } from 'three';
${spectral ? `import { spectralIridescence } from ${JSON.stringify(spectral)};` : ''}
const material = new MeshPhysicalMaterial({ iridescence: 1, iridescenceIOR: 1.33 });
${spectral ? 'spectralIridescence(material);' : ''}
const scene = new Scene();
scene.add(new Mesh(new TorusKnotGeometry(), material));
new WebGLRenderer().render(scene, new PerspectiveCamera());
`,
  },
  {
    entry: 'thin-film-color/webgpu',
    libraryFile: 'webgpu.js',
    renderer: 'WebGPURenderer',
    material: 'MeshPhysicalNodeMaterial',
    app: (spectral) => `
import { Mesh, MeshPhysicalNodeMaterial, PerspectiveCamera, Scene, TorusKnotGeometry, WebGPURenderer } from 'three/webgpu';
${spectral ? `import { spectralIridescence } from ${JSON.stringify(spectral)};` : ''}
const material = new MeshPhysicalNodeMaterial({ iridescence: 1, iridescenceIOR: 1.33 });
${spectral ? 'spectralIridescence(material);' : ''}
const scene = new Scene();
scene.add(new Mesh(new TorusKnotGeometry(), material));
const renderer = new WebGPURenderer();
await renderer.init();
renderer.render(scene, new PerspectiveCamera());
`,
  },
];

/** What a material entry may add to three's minimal app, gzipped: at start, and emitted in all. */
export const ENTRY_BYTES_GOALS = { eager: 30 * 1024, emitted: 60 * 1024 } as const;

/** A build's JavaScript and assets, gzipped. */
export interface BuildBytes {
  /** the entry chunk and its static imports, transitively */
  readonly eagerGzipBytes: number;
  /** every file the build emits */
  readonly emittedGzipBytes: number;
}

export interface EntryBytes {
  readonly entry: string;
  readonly renderer: string;
  readonly material: string;
  readonly three: BuildBytes;
  readonly spectral: BuildBytes;
}

const gzipBytes = (data: string | Uint8Array) => gzipSync(data, { level: 9 }).length;

/** The eager and emitted bytes of Vite's build (defaults, as a user's) of an app whose one module is `source`. */
export async function appBytes(source: string, dir: string): Promise<BuildBytes> {
  mkdirSync(dir, { recursive: true });
  writeFileSync(join(dir, 'main.js'), source);
  const built = (await build({
    root: dir,
    configFile: false,
    logLevel: 'silent',
    build: { write: false, chunkSizeWarningLimit: 5000, rolldownOptions: { input: join(dir, 'main.js') } },
  })) as Rolldown.RolldownOutput;
  const files = new Map(built.output.map((f) => [f.fileName, f]));
  const eager = new Set<string>();
  const visit = (name: string): void => {
    const file = files.get(name);
    if (eager.has(name) || file?.type !== 'chunk') return;
    eager.add(name);
    for (const imported of file.imports) visit(imported);
  };
  for (const f of built.output) if (f.type === 'chunk' && f.isEntry) visit(f.fileName);
  let eagerGzipBytes = 0;
  let emittedGzipBytes = 0;
  for (const f of built.output) {
    const bytes = gzipBytes(f.type === 'chunk' ? f.code : f.source);
    emittedGzipBytes += bytes;
    if (eager.has(f.fileName)) eagerGzipBytes += bytes;
  }
  return { eagerGzipBytes, emittedGzipBytes };
}

/** Builds the library into a folder of its own (the package stage builds dist-lib meanwhile), then each entry's apps. */
export async function materialEntryBytes(): Promise<EntryBytes[]> {
  const root = resolve('.scratch', 'bench-entry-bytes');
  rmSync(root, { recursive: true, force: true });
  const library = join(root, 'lib');
  await build({ mode: 'lib', logLevel: 'silent', build: { outDir: library, emptyOutDir: true } });
  const measured: EntryBytes[] = [];
  for (const [i, e] of MATERIAL_ENTRY_APPS.entries())
    measured.push({
      entry: e.entry,
      renderer: e.renderer,
      material: e.material,
      three: await appBytes(e.app(null), join(root, `three-${i}`)),
      spectral: await appBytes(e.app(join(library, e.libraryFile)), join(root, `spectral-${i}`)),
    });
  rmSync(root, { recursive: true, force: true });
  return measured;
}
