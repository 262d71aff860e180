/**
 * The parity harness's grids and comparison, shared by the GLSL's spec (parity.spec.ts) and the
 * node film's (webgpu*.spec.ts): the fixed and stress grids of film cases, the table's share of a
 * grid, and the comparison of rendered XYZ with the float64 reference by ΔE00.
 */
import { deltaE00 } from '../../src/physics/colorDifference.ts';
import { POLARIZATIONS, type Polarization } from '../../src/physics/filmReflectance.ts';
import type { FilmIndex } from '../../src/physics/filmIndex.ts';
import type { IlluminantSpec } from '../../src/physics/illuminants.ts';
import { type LightTint, WHITE_TINT } from '../../src/physics/lightTint.ts';
import { cosDeg } from '../../src/physics/snell.ts';
import { filmXyz, whiteXyz } from '../../src/physics/spectralIntegration.ts';
import { type Xyz } from '../../src/physics/spectralWeights.ts';
import { type DeltaStats, deltaStats } from '../../scripts/harness/deltaStats.ts';
import type { ParityGroup } from '../../scripts/harness/parityCase.ts';
import { mulberry32 } from '../seededRandom.ts';

/** The dispersive films of the parity cases: water at 20 °C, and n = 1.45 + 6000/λ² (λ in nm). */
const DISPERSIVE_FILMS: readonly (readonly [FilmIndex, Polarization])[] = [
  ['water', 'unpolarized'],
  [{ cauchy: [1.45, 6000, 0] }, 'p'],
];

export const ILLUMINANTS: readonly IlluminantSpec[] = [
  'D55',
  'D65',
  'D93',
  'E',
  'D65-table',
  { daylightCct: 4000 },
  { daylightCct: 12000 },
];

export interface Case {
  readonly thicknessNm: number;
  readonly angleDeg: number;
}
export interface Group extends Omit<ParityGroup, 'inputs'> {
  readonly cases: readonly Case[];
}

export const toParity = (g: Group): ParityGroup => ({ ...g, inputs: g.cases.map((c) => [c.thicknessNm, cosDeg(c.angleDeg)] as const) });

/** Every illuminant × every polarisation, nFilm drawn in 1.2–1.6, thickness 0–2000 nm, 0–85°, ends included. */
export function fixedDomain(): Group[] {
  const next = mulberry32(1);
  const groups: Group[] = [];
  for (const illuminant of ILLUMINANTS) {
    for (const polarization of POLARIZATIONS) {
      const cases: Case[] = [
        { thicknessNm: 0, angleDeg: 0 },
        { thicknessNm: 2000, angleDeg: 85 },
        { thicknessNm: 2000, angleDeg: 0 },
      ];
      while (cases.length < 40) cases.push({ thicknessNm: 2000 * next(), angleDeg: 85 * next() });
      const normalization = groups.length % 5 === 4 ? 'paper' : 'white';
      groups.push({ nOutside: 1, nFilm: 1.2 + 0.4 * next(), nInside: 1, illuminant, polarization, normalization, cases });
    }
  }
  // Dispersive films (docs/physics.md#a-dispersive-film): water unpolarised, a glass-like Cauchy film in p.
  for (const [nFilm, polarization] of DISPERSIVE_FILMS) {
    const cases: Case[] = [
      { thicknessNm: 0, angleDeg: 0 },
      { thicknessNm: 2000, angleDeg: 85 },
      { thicknessNm: 2000, angleDeg: 0 },
    ];
    while (cases.length < 80) cases.push({ thicknessNm: 2000 * next(), angleDeg: 85 * next() });
    groups.push({ nOutside: 1, nFilm, nInside: 1, illuminant: 'D65', polarization, normalization: 'white', cases });
  }
  return groups;
}

/** Thick films to 20 µm, grazing light to 90°, high index, and TIR (n_a > n_b > n_c). */
export function stressDomain(): Group[] {
  const next = mulberry32(2);
  const stacks = [
    { nOutside: 1, nFilm: 1.33, nInside: 1, maxNm: 20000, minDeg: 0 },
    { nOutside: 1, nFilm: 1.33, nInside: 1, maxNm: 2000, minDeg: 80 },
    { nOutside: 1, nFilm: 2.5, nInside: 1, maxNm: 20000, minDeg: 0 },
    { nOutside: 1.5, nFilm: 1.33, nInside: 1, maxNm: 2000, minDeg: 55 }, // TIR past 62.5° (at b), 41.8° (at c)
    { nOutside: 1.5, nFilm: 1.33, nInside: 1, maxNm: 20000, minDeg: 0 },
    { nOutside: 1.33, nFilm: 1.5, nInside: 1, maxNm: 5000, minDeg: 30 }, // TIR at the film's back face
    // Dispersive: water to 20 µm and near grazing, TIR with water between glass and air, a strongly dispersive high-index film.
    { nOutside: 1, nFilm: 'water', nInside: 1, maxNm: 20000, minDeg: 0 },
    { nOutside: 1.5, nFilm: 'water', nInside: 1, maxNm: 2000, minDeg: 55 },
    { nOutside: 1, nFilm: { cauchy: [2.3, 30000, 0] }, nInside: 1, maxNm: 20000, minDeg: 0 },
  ] as const;
  const groups: Group[] = [];
  stacks.forEach(({ maxNm, minDeg, ...n }, i) => {
    // Dispersive films in one polarisation each (their table is built from bins: seconds on a CPU rasteriser).
    for (const polarization of typeof n.nFilm === 'number' ? POLARIZATIONS : (['unpolarized'] as const)) {
      const cases: Case[] = [
        { thicknessNm: 0, angleDeg: 90 },
        { thicknessNm: maxNm, angleDeg: 89.9 },
        { thicknessNm: maxNm, angleDeg: 90 },
        { thicknessNm: 0, angleDeg: minDeg },
        { thicknessNm: 70, angleDeg: 70 },
      ];
      while (cases.length < 24) cases.push({ thicknessNm: maxNm * next(), angleDeg: minDeg + (89.9 - minDeg) * next() });
      groups.push({ ...n, illuminant: ILLUMINANTS[i % ILLUMINANTS.length]!, polarization, normalization: 'white', cases });
    }
  });
  return groups;
}

export interface Figures extends DeltaStats {
  readonly worst: string;
  /** The dispersive films' share of the cases. */
  readonly dispersive: DeltaStats | null;
}

export function compare(groups: readonly Group[], rendered: number[][][]): { figures: Figures; deltas: number[]; nonFinite: string[] } {
  const deltas: number[] = [];
  const dispersiveDeltas: number[] = [];
  const nonFinite: string[] = [];
  let worst = '';
  groups.forEach((g, gi) => {
    const white = whiteXyz(g.illuminant, g.normalization);
    g.cases.forEach((c, ci) => {
      const shader = rendered[gi]![ci]! as unknown as Xyz;
      // A colour the film reflects (the room's times the tint) is the light tinted by it: the tinted integral, computed without any matrix.
      const tint = g.lightTint ?? WHITE_TINT;
      const reflected = g.environmentColor ? { lightTint: g.environmentColor.map((v, i) => v * tint[i]!) as unknown as LightTint } : {};
      const reference = filmXyz({ ...g, ...c }, { ...g, ...reflected });
      const label = `${JSON.stringify({ ...g, cases: undefined, ...c })} shader ${shader.map((v) => v.toFixed(5))} reference ${reference.map((v) => v.toFixed(5))}`;
      const d = deltaE00(shader, reference, white);
      if (![...shader, d].every(Number.isFinite)) nonFinite.push(label);
      if (deltas.length === 0 || d > Math.max(...deltas)) worst = `ΔE00 ${d.toFixed(3)} at ${label}`;
      deltas.push(d);
      if (typeof g.nFilm !== 'number') dispersiveDeltas.push(d);
    });
  });
  const dispersive = dispersiveDeltas.length > 0 ? deltaStats(dispersiveDeltas) : null;
  return { figures: { ...deltaStats(deltas), worst, dispersive }, deltas, nonFinite };
}

/**
 * The table's share of a domain. A table is built per film, light and polarisation (seconds each
 * on a CPU rasteriser), while the polarisation is only a uniform of the same pass: so each light or
 * stack's constant-film groups (they come in runs of one per polarisation) become one group, in
 * one polarisation taken in turn, holding all their cases. Every light, stack and polarisation is
 * still met, with every case, from a quarter of the tables. The dispersive films' groups (one
 * polarisation each already) are kept as they are.
 */
export function perTable(groups: readonly Group[]): Group[] {
  const constant = groups.filter((g) => typeof g.nFilm === 'number');
  const runs = Array.from({ length: constant.length / POLARIZATIONS.length }, (_, i) =>
    constant.slice(i * POLARIZATIONS.length, (i + 1) * POLARIZATIONS.length),
  );
  const merged = runs.map((run, i) => {
    if (new Set(run.map((g) => g.polarization)).size !== POLARIZATIONS.length) throw new Error('a run must hold every polarisation once');
    return { ...run[i % POLARIZATIONS.length]!, cases: run.flatMap((g) => g.cases) };
  });
  return [...merged, ...groups.filter((g) => typeof g.nFilm !== 'number')];
}
