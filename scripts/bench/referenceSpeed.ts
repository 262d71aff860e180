/** Speed of the float64 reference in Node: medians of repeated runs on a shared machine. */
import { filmOptics, filmReflectance, reflectanceAt } from '../../src/physics/filmReflectance.ts';
import { filmXyz } from '../../src/physics/spectralIntegration.ts';
import { median } from './median.ts';

const soap = { nOutside: 1, nFilm: 1.33, nInside: 1, thicknessNm: 500, angleDeg: 30 };

function timeMs(run: () => void, repeats: number): number {
  const times: number[] = [];
  for (let i = 0; i < repeats; i++) {
    const t0 = performance.now();
    run();
    times.push(performance.now() - t0);
  }
  return median(times);
}

export interface ReferenceSpeed {
  readonly reflectancePerSecondSharedOptics: number;
  readonly reflectancePerSecondFullCall: number;
  readonly table0to2000nmAt1nmMs: number;
  readonly thickestFilmColorMs: number;
  /** results feed this so no loop is optimised away */
  readonly sink: number;
}

export function referenceSpeed(): ReferenceSpeed {
  let sink = 0;
  const N = 200_000;
  const perLambdaMs = timeMs(() => {
    const o = filmOptics(soap);
    for (let i = 0; i < N; i++) sink += reflectanceAt(o, 380 + (i % 451));
  }, 7);
  const fullMs = timeMs(() => {
    for (let i = 0; i < N / 10; i++) sink += filmReflectance(380 + (i % 451), { ...soap, thicknessNm: i % 2000 });
  }, 7);
  const tableMs = timeMs(() => {
    for (let d = 0; d <= 2000; d++) sink += filmXyz({ ...soap, angleDeg: 0, thicknessNm: d })[1];
  }, 5);
  const thickMs = timeMs(() => {
    sink += filmXyz({ nOutside: 1, nFilm: 2.5, nInside: 1, thicknessNm: 20000, angleDeg: 0 })[1];
  }, 9);
  return {
    reflectancePerSecondSharedOptics: Math.round(N / (perLambdaMs / 1000)),
    reflectancePerSecondFullCall: Math.round(N / 10 / (fullMs / 1000)),
    table0to2000nmAt1nmMs: tableMs,
    thickestFilmColorMs: thickMs,
    sink,
  };
}

export const referenceSpeedMarkdown = (r: ReferenceSpeed, node: string): string => `| reference (Node ${node}, median) | value |
|---|---|
| R(λ) evaluations/s, unpolarised, optics shared across λ (as the integrator does) | ${(r.reflectancePerSecondSharedOptics / 1e6).toFixed(2)} M |
| R(λ) evaluations/s, each call from scratch (\`filmReflectance\`) | ${(r.reflectancePerSecondFullCall / 1e6).toFixed(2)} M |
| colour table 0–2000 nm at 1 nm steps (2001 colours, default accuracy), 0°, soap film | ${r.table0to2000nmAt1nmMs.toFixed(0)} ms |
| one colour of the costliest film in the domain (n 2.5, 20 µm, 0°) | ${r.thickestFilmColorMs.toFixed(1)} ms |`;
