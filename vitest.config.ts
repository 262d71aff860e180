import { defineConfig } from 'vitest/config';

// Vitest would otherwise pick up Playwright's *.spec.ts files and fail on them.
export default defineConfig({
  test: { include: ['tests/unit/**/*.test.ts'] },
});
