/**
 * `npm run suite-times [-- report.json]`: where the browser suite's time goes. First its fixed
 * costs, each measured once here: the tests' site build, the static server's start, a Chromium
 * launch, a page load to its first frame and to its first frame in full per film method (whose
 * difference from `table` is mostly that method's shader compile and frame). Then the slowest 15
 * tests and the time per spec file, from a Playwright JSON report: the one given (e.g. from
 * `E2E_REPORT=report.json npm test`), or one made by running the browser suite here. Prints Markdown.
 */
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { chromium } from '@playwright/test';
import { preview } from 'vite';
import { FRAME_MARKS } from '../src/pages/frameMarks.ts';
import { MODES } from '../src/settings/filmSettings.ts';
import { checkedRenderer, chromiumLaunchOptions } from './chromium.ts';

/** The port of this script's own server (the suites use 5180, the benchmark 5192–5193). */
const PORT = 5194;
const REPORT = 'test-results/suite-times.json';
/** The view the fixed costs load: a uniform film, still, as most browser tests open it. */
const VIEW = '/?field=uniform&thickness=450&env=none&sides=front&animate=0';

const rows: [string, number][] = [];
async function timed<T>(what: string, act: () => Promise<T> | T): Promise<T> {
  const started = performance.now();
  const result = await act();
  rows.push([what, performance.now() - started]);
  return result;
}

await timed('site build with the tests’ pages (`vite build --mode e2e`)', () =>
  execFileSync('npx', ['vite', 'build', '--mode', 'e2e', '--logLevel', 'silent'], { stdio: 'inherit' }),
);
await timed('element build into it', () =>
  execFileSync('npx', ['vite', 'build', '--mode', 'element', '--outDir', 'dist-e2e', '--logLevel', 'silent'], { stdio: 'inherit' }),
);
const server = await timed('static server start (`vite preview`)', () =>
  preview({ mode: 'e2e', logLevel: 'silent', preview: { port: PORT, strictPort: true, host: '127.0.0.1' } }),
);
const browser = await timed('Chromium launch', () => chromium.launch(chromiumLaunchOptions()));
const webgl = await checkedRenderer(browser);
try {
  for (const mode of MODES) {
    const page = await browser.newPage({ viewport: { width: 640, height: 480 } });
    await page.goto(`http://127.0.0.1:${PORT}${VIEW}&mode=${mode}`);
    await page.waitForSelector('body[data-frames="ready"]', { timeout: 120_000 });
    const [first, complete] = await page.evaluate(
      (marks) => [marks.first, marks.firstComplete].map((m) => performance.getEntriesByName(m)[0]!.startTime),
      FRAME_MARKS,
    );
    rows.push([`page load (640×480, \`mode=${mode}\`) → first frame drawn`, first!], [`… → first frame drawn in full`, complete!]);
    await page.close();
  }
} finally {
  await browser.close();
  await new Promise((resolve) => server.httpServer.close(resolve));
}

const reportPath = process.argv[2];
if (!reportPath) {
  console.error('running the browser suite for its report (several minutes)');
  execFileSync('npx', ['playwright', 'test'], { stdio: ['ignore', 'ignore', 'inherit'], env: { ...process.env, E2E_REPORT: REPORT } });
}

interface Suite {
  readonly suites?: Suite[];
  readonly specs?: {
    readonly file: string;
    readonly title: string;
    readonly tests: { readonly results: { readonly duration: number }[] }[];
  }[];
}
const report = JSON.parse(readFileSync(reportPath ?? REPORT, 'utf8')) as { suites: Suite[]; stats: { duration: number } };
const tests: { file: string; title: string; ms: number }[] = [];
const walk = (s: Suite): void => {
  s.suites?.forEach(walk);
  for (const spec of s.specs ?? [])
    for (const t of spec.tests) for (const r of t.results) tests.push({ file: spec.file, title: spec.title, ms: r.duration });
};
report.suites.forEach(walk);
const perFile = new Map<string, number>();
for (const t of tests) perFile.set(t.file, (perFile.get(t.file) ?? 0) + t.ms);
const s = (ms: number) => `${(ms / 1000).toFixed(1)} s`;

const metadata = (report as { config?: { metadata?: { glBackend?: string } } }).config?.metadata;
console.log(`Fixed costs on ${webgl}; the tests' report from the backend ${metadata?.glBackend ?? 'it does not name'}.\n`);
console.log(`| fixed cost | time |\n|---|---|\n${rows.map(([what, ms]) => `| ${what} | ${s(ms)} |`).join('\n')}\n`);
console.log(
  `| slowest tests (of ${tests.length}; the run took ${s(report.stats.duration)}, the tests ${s(tests.reduce((a, t) => a + t.ms, 0))} in all) | time |\n|---|---|\n${[
    ...tests,
  ]
    .sort((a, b) => b.ms - a.ms)
    .slice(0, 15)
    .map((t) => `| ${t.file}: ${t.title} | ${s(t.ms)} |`)
    .join('\n')}\n`,
);
console.log(
  `| spec file | time |\n|---|---|\n${[...perFile]
    .sort((a, b) => b[1] - a[1])
    .map(([file, ms]) => `| ${file} | ${s(ms)} |`)
    .join('\n')}`,
);
