import { availableParallelism } from 'node:os';
import { defineConfig } from 'vitest/config';

// Vitest would otherwise pick up Playwright's *.spec.ts files and fail on them.
// The slowest computing tests take ~2.6 s here (a convergence sweep over the whole domain): 60 s
// per test, not Vitest's 5 s, leaves room for a machine many times slower or busier; the same for
// the hooks that compute what a file's tests share (a film simulated for 10⁴ steps), not Vitest's 10 s.
// A worker per core: Vitest's default keeps one core for itself, which on a 2-core machine leaves
// one worker and the other core mostly idle (its own work is little beside the tests').
export default defineConfig({
  test: { include: ['tests/unit/**/*.test.ts'], testTimeout: 60_000, hookTimeout: 60_000, maxWorkers: availableParallelism() },
});
