/**
 * The library as a separate project gets it: `npm pack` (its prepack builds dist-lib/), then the
 * tarball installed offline into a fresh folder, its imports type-checked and run. three.js, the
 * peer dependency, is the repository's own copy linked into that folder (nothing is fetched; a
 * project of its own would install three from the registry).
 */
import { execFileSync } from 'node:child_process';
import { copyFileSync, mkdtempSync, mkdirSync, readFileSync, readdirSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterAll, describe, expect, it } from 'vitest';
import { XYZ_TO_LINEAR_SRGB, applyMatrix3 } from '../../src/physics/colorConversions.ts';
import { SOAP_FILM_IN_AIR, filmReflectance } from '../../src/physics/filmReflectance.ts';
import { filmXyz, whiteXyz } from '../../src/physics/spectralIntegration.ts';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const HERE = fileURLToPath(new URL('.', import.meta.url));
/** Build (vite, tsc for the types), pack, install and type-check take ~17 s alone here, 45–58 s beside the checks and unit tests with a core busy; allow for a slower machine. */
const PACK_TIMEOUT_MS = 240_000;

const dir = mkdtempSync(join(tmpdir(), 'tfc-consumer-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));
const run = (cmd: string, args: string[], cwd: string) =>
  execFileSync(cmd, args, { cwd, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });

describe('the packed library in a fresh project', () => {
  it(
    'installs from the tarball offline; its three entries type-check; the physics and the material run',
    () => {
      run('npm', ['run', 'build:lib'], ROOT); // what prepack runs, apart so that pack's --json output is alone on stdout
      const packed = JSON.parse(run('npm', ['pack', '--json', '--ignore-scripts', '--pack-destination', dir], ROOT)) as {
        filename: string;
        files: { path: string }[];
      }[];
      const files = packed[0]!.files.map((f) => f.path);
      expect(files).toContain('dist-lib/material.js');
      expect(files).toContain('dist-lib/types/packageEntries/physics.d.ts');
      expect(files.filter((f) => !f.startsWith('dist-lib/') && !['package.json', 'README.md', 'LICENSE'].includes(f))).toEqual([]);

      const project = join(dir, 'project');
      mkdirSync(project);
      writeFileSync(join(project, 'package.json'), JSON.stringify({ name: 'consumer', private: true, type: 'module' }));
      run(
        'npm',
        ['install', '--offline', '--no-audit', '--no-fund', '--no-save', '--legacy-peer-deps', join(dir, packed[0]!.filename)],
        project,
      );
      // The peer: the repository's three.js and its types, linked after the install (npm would
      // prune links it did not make, and fetch three itself without --legacy-peer-deps).
      mkdirSync(join(project, 'node_modules', '@types'), { recursive: true });
      symlinkSync(join(ROOT, 'node_modules', 'three'), join(project, 'node_modules', 'three'), 'dir');
      symlinkSync(join(ROOT, 'node_modules', '@types', 'three'), join(project, 'node_modules', '@types', 'three'), 'dir');

      copyFileSync(join(HERE, 'consumer.ts.txt'), join(project, 'consumer.ts'));
      const tsconfig = {
        compilerOptions: {
          target: 'ES2022',
          module: 'ESNext',
          moduleResolution: 'Bundler',
          lib: ['ES2022', 'DOM', 'DOM.Iterable'],
          strict: true,
          noEmit: true,
          types: [],
        },
        files: ['consumer.ts'],
      };
      writeFileSync(join(project, 'tsconfig.json'), JSON.stringify(tsconfig));
      run(process.execPath, [join(ROOT, 'node_modules', 'typescript', 'bin', 'tsc'), '-p', 'tsconfig.json'], project);

      // Run it: TypeScript's own transpiler strips the types; Node imports the installed package.
      const ts = readFileSync(join(project, 'consumer.ts'), 'utf8');
      const js = run(
        process.execPath,
        [
          '--input-type=module',
          '-e',
          `import ts from ${JSON.stringify(join(ROOT, 'node_modules', 'typescript', 'lib', 'typescript.js'))}; process.stdout.write(ts.transpileModule(${JSON.stringify(ts)}, { compilerOptions: { module: 99, target: 9 } }).outputText)`,
        ],
        project,
      );
      writeFileSync(join(project, 'consumer.mjs'), js);
      const out = JSON.parse(run(process.execPath, ['consumer.mjs'], project)) as Record<string, unknown>;

      // The packed physics computes what the source does.
      const stack = { ...SOAP_FILM_IN_AIR, thicknessNm: 0, angleDeg: 0 };
      expect(out.bare).toBe(filmReflectance(550, stack));
      expect(out.white).toEqual(whiteXyz('D65'));
      expect(out.rgb).toEqual(applyMatrix3(XYZ_TO_LINEAR_SRGB, filmXyz({ ...stack, thicknessNm: 450 })));
      // The packed material replaces three's film and brings its uniforms; bad options name the parameter.
      expect(out.spectral).toBe(true);
      // A three.js material: its options as properties, the user's onBeforeCompile called, a clone still spectral.
      expect(out.thinFilm).toBe(true);
      expect(out.userCompiled).toBe(true);
      expect(out.options).toEqual(['fourier', 'D65', 45]);
      expect(out.clone).toEqual(['exact', 'D55']);
      expect(out.replaced).toBe(true);
      expect(out.uniforms).toEqual(expect.arrayContaining(['uNFilm', 'uSpectralTransform', 'uXyzToLinearWorking']));
      expect(out.upgraded).toBe(1);
      expect(out.refused).toBe('mode');
      expect(out.names).toEqual(['ThinFilmMaterial', 'ParameterError', 'spectralIridescence', 'filmXyz', 'ThinFilmMaterial']);
    },
    PACK_TIMEOUT_MS,
  );

  // Reads the dist-lib/ the test above built (a file's tests run in order).
  it("the material entries reach no HDR environment's map: a user's build of either emits none", () => {
    const lib = join(ROOT, 'dist-lib');
    /** The files `file` imports, statically, dynamically or as a worker's URL (the built modules' relative specifiers). */
    const importsOf = (file: string): string[] =>
      [...readFileSync(join(lib, file), 'utf8').matchAll(/(?:from|import\s*\(?|new URL\()\s*["'](\.\/[^"']+)["']/g)].map((m) =>
        join(dirname(file), m[1]!),
      );
    for (const entry of ['material.js', 'webgpu.js']) {
      const reached = new Set<string>();
      const visit = (file: string): void => {
        if (reached.has(file)) return;
        reached.add(file);
        if (file.endsWith('.js')) importsOf(file).forEach(visit);
      };
      visit(entry);
      expect(reached.size, entry).toBeGreaterThan(2);
      expect(
        [...reached].filter((f) => /\.exr/.test(f)),
        entry,
      ).toEqual([]);
    }
    // What the check looks for is there to find: the element, which draws the environments, reaches the maps.
    expect(readdirSync(lib).filter((f) => /\.exr/.test(f)).length).toBeGreaterThan(0);
  });
});
