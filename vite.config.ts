import { defineConfig, type Plugin, type UserConfig } from 'vite';
import { glslWithoutCommentsPlugin } from './scripts/build/glslWithoutComments.ts';

/** Where pages (the teaching page in public/, embedding pages) load the element from. */
const ELEMENT_URL = '/thin-film-bubble.js';
const ELEMENT_ENTRY = 'src/element/index.ts';
/** The site's pages (public/ is copied as it is): the demo, and the example page of the material for any three.js scene. */
const SITE_PAGES = ['index.html', 'materials.html'];
/** The browser tests' own pages, built only into the tests' site (`--mode e2e`, dist-e2e/). */
const TEST_PAGES = [
  'tests/e2e/harness/parity.html',
  'tests/e2e/harness/material.html',
  'tests/e2e/harness/webgpu.html',
  'scripts/harness/materialGrid.html',
];

/**
 * The library's entries (package.json `exports`): the float64 physics, the spectral material for
 * three.js scenes (WebGLRenderer's, and WebGPURenderer's), and the element; three.js stays outside (a peer dependency).
 */
const LIBRARY_ENTRIES = {
  physics: 'src/packageEntries/physics.ts',
  material: 'src/packageEntries/material.ts',
  webgpu: 'src/packageEntries/webgpu.ts',
  element: ELEMENT_ENTRY,
};

/**
 * The library's and the element's files (the light's Web Worker, the HDR environments) are found
 * beside the module that loads them (`new URL('./assets/…', import.meta.url)`), wherever it is served from.
 */
const MODULE_RELATIVE = './';

/** In development, the element's URL serves its source, so public/ pages work unbuilt. */
const elementInDevelopment = (): Plugin => ({
  name: 'thin-film-bubble-dev-url',
  configureServer(server) {
    server.middlewares.use((req, _res, next) => {
      if (req.url === ELEMENT_URL) req.url = `/${ELEMENT_ENTRY}`;
      next();
    });
  },
});

/** The demo site: its pages (and, for the browser tests, theirs) into `outDir`. */
const site = (pages: readonly string[], outDir: string): UserConfig => ({
  plugins: [elementInDevelopment(), glslWithoutCommentsPlugin()],
  server: { port: 5173, strictPort: true },
  // The HDR environments' modules (plain ES modules of one string each) are served as they
  // are: pre-bundling them would only risk a reload when a page first imports one.
  optimizeDeps: { exclude: ['@pmndrs/assets'] },
  preview: { port: 4173, strictPort: true },
  // three.js's renderer is most of the ~660 kB (~180 kB gzipped); it is imported piecemeal and tree-shaken.
  build: { outDir, chunkSizeWarningLimit: 800, rolldownOptions: { input: [...pages] } },
});

// GLSL files are imported as text with Vite's `?raw` suffix; every build ships them without comments.
// `vite build` makes the demo site; `vite build --mode element` adds the standalone element
// module (three.js included) to the same dist/ as thin-film-bubble.js (`--outDir` for another);
// `vite build --mode lib` writes the library's ES modules to dist-lib/ (their types:
// `tsc -p tsconfig.lib.json`). `vite build --mode e2e` makes the site with the tests' pages in
// dist-e2e/, which the browser tests are served from (`vite preview --mode e2e`).
export default defineConfig(({ mode }): UserConfig => {
  if (mode === 'e2e') return site([...SITE_PAGES, ...TEST_PAGES], 'dist-e2e');
  if (mode === 'lib')
    return {
      publicDir: false,
      base: MODULE_RELATIVE,
      plugins: [glslWithoutCommentsPlugin()],
      build: {
        outDir: 'dist-lib',
        emptyOutDir: false, // the types are written beside them
        chunkSizeWarningLimit: 800,
        lib: { entry: LIBRARY_ENTRIES, formats: ['es'] },
        // Class and function names kept (`ThinFilmMaterial`, `ParameterError` in a stack trace and in `.name`).
        rolldownOptions: { external: [/^three($|\/)/], output: { keepNames: true } },
      },
    };
  if (mode !== 'element') return site(SITE_PAGES, 'dist');
  return {
    publicDir: false,
    base: MODULE_RELATIVE,
    plugins: [glslWithoutCommentsPlugin()],
    build: {
      emptyOutDir: false,
      chunkSizeWarningLimit: 800,
      // An app build with one entry, not library mode: library mode leaves ES output unminified.
      rolldownOptions: {
        input: ELEMENT_ENTRY,
        preserveEntrySignatures: 'exports-only',
        output: { entryFileNames: ELEMENT_URL.slice(1) },
      },
    },
  };
});
