/**
 * `npm run bench`: the float64 reference's speed in Node, then every film-colour method in
 * headless Chromium (frame times, table rebuild, first frame, ΔE00 against src/physics), the
 * flowing film's simulation speed on the GPU and in its float64 twin, the built demo's and the
 * package's size, the demo's first frame and render-on-demand counts. Prints
 * Markdown and writes bench-results.json (git-ignored; `npm run bench:docs` makes
 * docs/benchmarks.md of it). `--smoke` runs each kind of row and every figure once, small, and
 * writes its results elsewhere. Exit status 2 for a bad command line, 1 if a stage threw or a figure is missing or
 * not finite. Benchmarks measure; the tests check correctness.
 */
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname } from 'node:path';
import { benchUsage, parseBenchArgs } from './bench/benchArgs.ts';
import { FULL_PLAN, SMOKE_PLAN, withPorts } from './bench/benchPlan.ts';
import { resultProblems } from './bench/benchResults.ts';
import { benchMarkdown } from './bench/benchMarkdown.ts';
import { FLOW_SPEED_ROW, MATERIALS_ROW, NODE_ROW, ROWS } from './bench/rows.ts';

const rowNames = [...ROWS.map((r) => r.name), FLOW_SPEED_ROW, MATERIALS_ROW, NODE_ROW];
const parsed = parseBenchArgs(process.argv.slice(2), rowNames);
if ('error' in parsed) {
  console.error(parsed.error);
  process.exit(2);
}
if (parsed.args.help) {
  console.log(benchUsage(rowNames));
  process.exit(0);
}
const { smoke, only, port } = parsed.args;
const plan = withPorts(smoke ? SMOKE_PLAN : FULL_PLAN, port);
const picked = (name: string) => !only || only.some((text) => name.includes(text));
// The floor always runs: the other rows' frame times are given against it. The smoke leaves out
// the costlier variants of its rows (BenchRow.smoke) unless they are picked by name.
const rows = ROWS.filter((r, i) => i === 0 || (picked(r.name) && (!smoke || only !== null || r.smoke !== false)));
const extras = { materials: picked(MATERIALS_ROW), node: picked(NODE_ROW), flowSpeed: picked(FLOW_SPEED_ROW) };

// Vite, Playwright and the rows' code load only once the command line is known to be good.
const { runBench } = await import('./bench/runBench.ts');
const results = await runBench(plan, rows, extras);
console.log(benchMarkdown(results));
mkdirSync(dirname(plan.resultsFile), { recursive: true });
writeFileSync(plan.resultsFile, JSON.stringify(results, null, 2));
console.error(`${plan.resultsFile} written (${results.seconds.toFixed(0)} s)`);
const rowOf = (name: string) => ROWS.find((r) => r.name === name)!;
const problems = resultProblems(results, rowOf, extras);
if (problems.length > 0) {
  console.error(`The run is incomplete:\n${problems.map((p) => `- ${p}`).join('\n')}`);
  process.exit(1);
}
