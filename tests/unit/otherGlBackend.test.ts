import { afterEach, describe, expect, it, vi } from 'vitest';
import { GL_BACKEND_NAMES, chromiumLaunchOptions, otherGlBackend } from '../../scripts/chromium.ts';

/** The browser tests run their `@both-backends` tests on the WebGL backend TFC_GL does not name (playwright.config.ts). */
describe('the other WebGL backend', () => {
  afterEach(() => vi.unstubAllEnvs());

  it('is the one TFC_GL does not name, for each name and for none (the default, llvmpipe)', () => {
    expect(GL_BACKEND_NAMES).toEqual(['llvmpipe', 'swiftshader']);
    vi.stubEnv('TFC_GL', '');
    expect(otherGlBackend()).toBe('swiftshader');
    vi.stubEnv('TFC_GL', 'llvmpipe');
    expect(otherGlBackend()).toBe('swiftshader');
    vi.stubEnv('TFC_GL', 'swiftshader');
    expect(otherGlBackend()).toBe('llvmpipe');
  });

  it("launches Chromium with the named backend's flags, whatever TFC_GL names", () => {
    vi.stubEnv('CHROME_PATH', process.execPath); // an existing file: no search for a browser
    vi.stubEnv('TFC_GL', 'llvmpipe');
    expect(chromiumLaunchOptions('swiftshader').args).toContain('--use-angle=swiftshader');
    expect(chromiumLaunchOptions().args).toContain('--use-angle=gles-egl');
  });
});
