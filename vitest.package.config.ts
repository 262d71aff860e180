import { defineConfig } from 'vitest/config';

// The packed library's test (tests/package) builds, packs and type-checks (~20 s of both cores):
// `npm test` runs it beside the checks that time nothing (`npm run checks`: type check, lint,
// format), not beside the unit tests' CPU-bound tests.
export default defineConfig({
  test: { include: ['tests/package/**/*.test.ts'] },
});
