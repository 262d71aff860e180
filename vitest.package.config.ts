import { defineConfig } from 'vitest/config';

// The packed library's test (tests/package) builds, packs and type-checks (~20 s of both cores),
// so it runs on its own, after the unit tests, rather than beside their CPU-bound tests.
export default defineConfig({
  test: { include: ['tests/package/**/*.test.ts'] },
});
