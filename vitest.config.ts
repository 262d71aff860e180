import { availableParallelism } from 'node:os';
import { defineConfig } from 'vitest/config';

// Vitest would otherwise pick up Playwright's *.spec.ts files and fail on them.
// The slowest computing tests take ~2.6 s here (a convergence sweep over the whole domain): 60 s
// per test, not Vitest's 5 s, leaves room for a machine many times slower or busier; the same for
// the hooks that compute what a file's tests share (a film simulated for 10⁴ steps), not Vitest's 10 s.
// A worker per core: Vitest's default keeps one core for itself, which on a 2-core machine leaves
// one worker and the other core mostly idle (its own work is little beside the tests').
const UNIT_TESTS = 'tests/unit/**/*.test.ts';

// The files that read a module's state as a fresh import leaves it (the material's drawing not
// yet loaded, a store before its first Worker) or swap globals for a module's import: each in
// modules of its own. Every other file shares its worker's modules with the files run before it,
// which halves the suite's time (importing three, the physics and the app once per worker rather
// than once per file); they keep no state that another file reads.
const FRESH_MODULES = [
  'tests/unit/meshMaterial/spectralDrawing.test.ts',
  'tests/unit/nodeMaterial/spectralNodeMaterial.test.ts',
  'tests/unit/film/dispersiveRowsWorker.test.ts',
  'tests/unit/film/spectralTransformWorker.test.ts',
  'tests/unit/plots/interferenceScaleStore.test.ts',
];

export default defineConfig({
  test: {
    testTimeout: 60_000,
    hookTimeout: 60_000,
    maxWorkers: availableParallelism(),
    projects: [
      { extends: true, test: { name: 'shared', include: [UNIT_TESTS], exclude: FRESH_MODULES, isolate: false } },
      { extends: true, test: { name: 'fresh', include: FRESH_MODULES } },
    ],
  },
});
