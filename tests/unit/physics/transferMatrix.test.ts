/**
 * Stacks of films by the transfer matrix (docs/physics.md#stacks-of-films). Expected values come
 * from outside the recursion under test: the single film's eqs (13)–(14) for one layer, the
 * characteristic-matrix closed form of a quarter-wave mirror, energy conservation and symmetries,
 * and tmm (Byrnes 2016) through fixtures/tmmStacks.json, written by scripts/fixtures/tmmStacks.py.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { deltaE00 } from '../../../src/physics/colorDifference.ts';
import { type RefractiveIndex } from '../../../src/physics/complex.ts';
import { type ResolvedLayer } from '../../../src/physics/stackFilms.ts';
import { POLARIZATIONS, type Polarization, filmReflectance, filmTransmittance } from '../../../src/physics/filmReflectance.ts';
import { layersStepsPerNm, layersXyz } from '../../../src/physics/stackColor.ts';
import { type Medium } from '../../../src/physics/medium.ts';
import { dispersiveReflectance, filmXyz, integrateXyz, whiteXyz } from '../../../src/physics/spectralIntegration.ts';
import { spectralWeights } from '../../../src/physics/spectralWeights.ts';
import {
  type LayerStack,
  assertLayerStack,
  layersAbsorptance,
  layersReflectance,
  layersReflectanceSpectrum,
  layersTransmittance,
} from '../../../src/physics/transferMatrix.ts';
import { ParameterError } from '../../../src/input/validate.ts';
import { mulberry32 } from '../../seededRandom.ts';
import {
  ALGEBRAIC_TOL,
  BRAGG_CLOSED_FORM_TOL,
  CONVERGENCE_DE00,
  ENERGY_TOL,
  LAYER_IDENTITY_TOL,
  ROUNDING_TOL,
  TMM_LAYERS_TOL,
  TMM_SPECTRUM_DE00,
} from '../../tolerances.ts';

const PHYSICAL = ['unpolarized', 's', 'p'] as const satisfies readonly Polarization[];

/** ñ as a Medium: a real number, or complex:n,k. */
const medium = (n: number | readonly [number, number]): Medium => (typeof n === 'number' ? n : { complex: [n[0], n[1]] });
/** The same ñ as the single film takes it. */
const index = (n: number | readonly [number, number]): RefractiveIndex => (typeof n === 'number' ? n : { re: n[0], im: n[1] });

const METAL = [0.2, 3.4] as const;
const [N_H, N_L, N_GLASS, DESIGN_NM] = [2.35, 1.46, 1.52, 550];
/** (HL)^periods, quarter-wave at DESIGN_NM, H next to the outside. */
const bragg = (periods: number): ResolvedLayer[] =>
  Array.from({ length: periods }, () => [
    { n: N_H, thicknessNm: DESIGN_NM / (4 * N_H) },
    { n: N_L, thicknessNm: DESIGN_NM / (4 * N_L) },
  ]).flat();

describe('one layer is the single film, eqs (13)–(14)', () => {
  const films = [1.33, 2.5, [2, 0.5], METAL] as const;
  const insides = [1, 1.52, [1.5, 0.1], METAL] as const;
  it('R and T equal filmReflectance and filmTransmittance in every mode, past the critical angle and at grazing', () => {
    let worst = 0;
    let cases = 0;
    for (const nOutside of [1, 1.5])
      for (const nFilm of films)
        for (const nInside of insides)
          for (const thicknessNm of [0, 37, 250, 1234, 20000])
            for (const angleDeg of [0, 30, 50, 75, 89.9, 90])
              for (const lambdaNm of [380, 555, 830])
                for (const polarization of POLARIZATIONS) {
                  const film = { nOutside, nFilm: index(nFilm), nInside: index(nInside), thicknessNm, angleDeg };
                  const stack: LayerStack = { nOutside, films: [{ n: medium(nFilm), thicknessNm }], nInside: medium(nInside), angleDeg };
                  const dR = Math.abs(layersReflectance(lambdaNm, stack, polarization) - filmReflectance(lambdaNm, film, polarization));
                  const dT = Math.abs(layersTransmittance(lambdaNm, stack, polarization) - filmTransmittance(lambdaNm, film, polarization));
                  worst = Math.max(worst, dR, dT);
                  cases++;
                }
    expect(cases).toBe(2 * 4 * 4 * 5 * 6 * 3 * 4);
    expect(worst).toBeLessThan(LAYER_IDENTITY_TOL);
  });

  it('its colour is filmXyz, for constant and dispersive media', () => {
    const white = whiteXyz('D65');
    for (const [nFilm, nInside] of [
      [1.33, 1],
      ['TiO2', 'Au'],
      ['water', { complex: [1.5, 0.1] }],
    ] as const)
      for (const angleDeg of [0, 60])
        for (const polarization of ['unpolarized', 'paper'] as const) {
          const film = { nOutside: 1, nFilm, nInside, thicknessNm: 420, angleDeg };
          const stack: LayerStack = { nOutside: 1, films: [{ n: nFilm, thicknessNm: 420 }], nInside, angleDeg };
          const got = layersXyz(stack, { polarization });
          const want = filmXyz(film, { polarization });
          got.forEach((v, i) => expect(Math.abs(v - want[i]!)).toBeLessThan(ROUNDING_TOL));
          expect(deltaE00(got, want, white)).toBeLessThan(ALGEBRAIC_TOL);
        }
  });
});

describe('the colour of a stack', () => {
  it('converges: default sampling is within ΔE00 0.1 of a 0.01 nm step, cavities between mirrors included', () => {
    const white = whiteXyz('D65');
    const metal = medium([0.05, 4]);
    const stacks: LayerStack[] = [
      { nOutside: 1, films: bragg(8), nInside: N_GLASS, angleDeg: 0 },
      { nOutside: 1, films: bragg(8), nInside: N_GLASS, angleDeg: 70 },
      { nOutside: 1, films: Array.from({ length: 10 }, (_, i) => ({ n: i % 2 ? 1.33 : 2, thicknessNm: 1500 })), nInside: 1, angleDeg: 60 },
      // A Fabry–Perot filter: a 4-wave spacer between two (HL)^6 mirrors, its pass band 0.4 nm wide.
      {
        nOutside: 1,
        films: [...bragg(6), { n: N_L, thicknessNm: (4 * DESIGN_NM) / (2 * N_L) }, ...bragg(6).reverse()],
        nInside: N_GLASS,
        angleDeg: 0,
      },
      // A metal–dielectric–metal cavity.
      {
        nOutside: 1,
        films: [
          { n: metal, thicknessNm: 40 },
          { n: 1.46, thicknessNm: 3000 },
          { n: metal, thicknessNm: 200 },
        ],
        nInside: 1,
        angleDeg: 0,
      },
    ];
    for (const stack of stacks)
      expect(deltaE00(layersXyz(stack), layersXyz(stack, { stepsPerNm: 100 }), white)).toBeLessThan(CONVERGENCE_DE00);
  });
});

describe('a quarter-wave mirror at its design wavelength', () => {
  // Characteristic matrices (docs/physics.md#stacks-of-films): each period HL multiplies B by −n_L/n_H and
  // C by −n_H/n_L, so (HL)^N on n_s has Y = (n_H/n_L)^{2N} n_s and (HL)^N H has Y = n_H^{2N+2} / (n_L^{2N} n_s).
  const reflectance = (y: number) => ((1 - y) / (1 + y)) ** 2;
  it('(HL)^8 on glass: R = ((1 − Y)/(1 + Y))², Y = (n_H/n_L)^16 n_s', () => {
    const y = (N_H / N_L) ** 16 * N_GLASS;
    for (const polarization of POLARIZATIONS.filter((p) => p !== 'paper')) {
      const r = layersReflectance(DESIGN_NM, { nOutside: 1, films: bragg(8), nInside: N_GLASS, angleDeg: 0 }, polarization);
      expect(Math.abs(r - reflectance(y))).toBeLessThan(BRAGG_CLOSED_FORM_TOL);
    }
    expect(reflectance(y)).toBeGreaterThan(0.998);
  });

  it('(HL)^N H for N = 0 … 12: Y = n_H^{2N+2} / (n_L^{2N} n_s)', () => {
    for (let periods = 0; periods <= 12; periods++) {
      const films = [...bragg(periods), { n: N_H, thicknessNm: DESIGN_NM / (4 * N_H) }];
      const y = N_H ** (2 * periods + 2) / (N_L ** (2 * periods) * N_GLASS);
      const r = layersReflectance(DESIGN_NM, { nOutside: 1, films, nInside: N_GLASS, angleDeg: 0 });
      expect(Math.abs(r - reflectance(y))).toBeLessThan(BRAGG_CLOSED_FORM_TOL);
    }
  });
});

/** A stack of 1–12 films drawn at random: real indices in [1, 2.6] or, when `absorbing`, some complex ones. */
function randomStack(random: () => number, absorbing: boolean): LayerStack {
  const count = 1 + Math.floor(random() * 12);
  const films = Array.from({ length: count }, () => ({
    n: absorbing && random() < 0.3 ? medium([0.05 + 3 * random(), 4 * random()]) : 1 + 1.6 * random(),
    thicknessNm: random() < 0.1 ? 0 : 600 * random(),
  }));
  const nInside = absorbing && random() < 0.5 ? medium(METAL) : 1 + 1.6 * random();
  return { nOutside: [1, 1.33, 1.52, 2][Math.floor(random() * 4)]!, films, nInside, angleDeg: 90 * random() };
}

describe('conservation and bounds', () => {
  it('R + T = 1 and A = 0 for lossless stacks, evanescent films and total reflection included', () => {
    const random = mulberry32(7);
    let worst = 0;
    for (let i = 0; i < 300; i++) {
      const stack = randomStack(random, false);
      const lambdaNm = 380 + 450 * random();
      for (const p of PHYSICAL) {
        const sum = layersReflectance(lambdaNm, stack, p) + layersTransmittance(lambdaNm, stack, p);
        worst = Math.max(worst, Math.abs(sum - 1), Math.abs(layersAbsorptance(lambdaNm, stack, p)));
      }
    }
    expect(worst).toBeLessThan(ENERGY_TOL);
  });

  it('0 ≤ R, T, A and R ≤ 1 for absorbing stacks', () => {
    const random = mulberry32(11);
    for (let i = 0; i < 300; i++) {
      const stack = randomStack(random, true);
      const lambdaNm = 380 + 450 * random();
      for (const p of PHYSICAL) {
        const [r, t, a] = [
          layersReflectance(lambdaNm, stack, p),
          layersTransmittance(lambdaNm, stack, p),
          layersAbsorptance(lambdaNm, stack, p),
        ];
        expect(r).toBeGreaterThanOrEqual(0);
        expect(r).toBeLessThanOrEqual(1);
        expect(t).toBeGreaterThanOrEqual(0);
        expect(a).toBeGreaterThan(-ENERGY_TOL);
      }
    }
  });

  it('at grazing incidence everything is reflected', () => {
    const stack: LayerStack = { nOutside: 1, films: bragg(3), nInside: N_GLASS, angleDeg: 90 };
    for (const p of PHYSICAL) {
      expect(layersReflectance(480, stack, p)).toBe(1);
      expect(layersTransmittance(480, stack, p)).toBe(0);
    }
  });
});

describe('symmetries', () => {
  const random = mulberry32(23);
  const stacks = Array.from({ length: 60 }, (_, i) => randomStack(random, i % 2 === 1));
  const lambdas = stacks.map(() => 380 + 450 * random());
  /** Worst |ΔR| and |ΔT| between two stacks over the physical modes. */
  const differ = (a: LayerStack, b: LayerStack, lambdaNm: number): number =>
    Math.max(
      ...PHYSICAL.flatMap((p) => [
        Math.abs(layersReflectance(lambdaNm, a, p) - layersReflectance(lambdaNm, b, p)),
        Math.abs(layersTransmittance(lambdaNm, a, p) - layersTransmittance(lambdaNm, b, p)),
      ]),
    );

  it('R_s = R_p at normal incidence', () => {
    stacks.forEach((s, i) => {
      const normal = { ...s, angleDeg: 0 };
      expect(Math.abs(layersReflectance(lambdas[i]!, normal, 's') - layersReflectance(lambdas[i]!, normal, 'p'))).toBeLessThan(
        ROUNDING_TOL,
      );
    });
  });

  it('a 0 nm layer anywhere is no layer', () => {
    stacks.forEach((s, i) => {
      const at = Math.floor(random() * (s.films.length + 1));
      const withZero = { ...s, films: [...s.films.slice(0, at), { n: medium([1.7, 0.4]), thicknessNm: 0 }, ...s.films.slice(at)] };
      expect(differ(withZero, s, lambdas[i]!)).toBe(0);
    });
  });

  it('a stack of 0 nm films is the bare interface, its colour too', () => {
    const white = whiteXyz('D65');
    for (const nInside of [1, 1.52, medium(METAL)]) {
      const bare = { nOutside: 1.33, nFilm: nInside, nInside, thicknessNm: 0, angleDeg: 40 };
      const stack = { nOutside: 1.33, films: bragg(2).map((l) => ({ ...l, thicknessNm: 0 })), nInside, angleDeg: 40 };
      for (const p of PHYSICAL)
        expect(Math.abs(layersReflectance(500, stack, p) - dispersiveReflectance(500, bare, p))).toBeLessThan(ROUNDING_TOL);
      expect(deltaE00(layersXyz(stack), filmXyz(bare), white)).toBeLessThan(ALGEBRAIC_TOL);
    }
  });

  it('a layer split in two of the same medium is the same layer', () => {
    let worst = 0;
    stacks.forEach((s, i) => {
      const at = Math.floor(random() * s.films.length);
      const layer = s.films[at]!;
      const part = random() * layer.thicknessNm;
      const halves = [
        { n: layer.n, thicknessNm: part },
        { n: layer.n, thicknessNm: layer.thicknessNm - part },
      ];
      const split = { ...s, films: [...s.films.slice(0, at), ...halves, ...s.films.slice(at + 1)] };
      worst = Math.max(worst, differ(split, s, lambdas[i]!));
    });
    expect(worst).toBeLessThan(ROUNDING_TOL);
  });

  it("a layer of the outside's index, of any thickness, next to the outside changes nothing (real indices)", () => {
    stacks.forEach((s, i) => {
      const withOutside = { ...s, films: [{ n: s.nOutside, thicknessNm: 20000 * random() }, ...s.films] };
      // R is unchanged; so is T (the phase of a lossless layer on the way in has modulus 1).
      expect(differ(withOutside, s, lambdas[i]!)).toBeLessThan(ROUNDING_TOL);
    });
  });
});

describe('the edges of the domain stay finite', () => {
  const finite = (stack: LayerStack) => {
    for (const angleDeg of [0, 45, 80, 89.99, 90])
      for (const p of POLARIZATIONS)
        for (const lambdaNm of [380, 600, 830]) {
          const s = { ...stack, angleDeg };
          const values = [layersReflectance(lambdaNm, s, p), layersTransmittance(lambdaNm, s, p), layersAbsorptance(lambdaNm, s, p)];
          for (const v of values) expect(Number.isFinite(v)).toBe(true);
          expect(values[0]).toBeGreaterThanOrEqual(0);
          expect(values[0]).toBeLessThanOrEqual(1);
        }
  };
  it('64 films of 0.2+5i, 20 µm each, in air', () => {
    const films = Array.from({ length: 64 }, () => ({ n: medium([0.2, 5]), thicknessNm: 20000 }));
    finite({ nOutside: 1, films, nInside: 1, angleDeg: 0 });
    // The first layer is opaque: R is that of the bulk metal, 0.2+5i, at normal incidence.
    const bulk = (0.8 ** 2 + 25) / (1.2 ** 2 + 25);
    expect(Math.abs(layersReflectance(600, { nOutside: 1, films, nInside: 1, angleDeg: 0 }) - bulk)).toBeLessThan(ROUNDING_TOL);
  });
  it('64 alternating metal and evanescent films, 20 µm each, lit from n = 4', () => {
    const films = Array.from({ length: 64 }, (_, i) => ({ n: i % 2 ? 1 : medium([0.05, 100]), thicknessNm: 20000 }));
    finite({ nOutside: 4, films, nInside: medium(METAL), angleDeg: 0 });
    finite({ nOutside: 4, films: films.map((l) => ({ ...l, n: 1 })), nInside: 4, angleDeg: 0 });
  });
  it('its colour: finite, and sized by the films the light reaches', () => {
    const films = Array.from({ length: 64 }, (_, i) => ({ n: i % 2 ? 2.5 : medium([0.2, 5]), thicknessNm: 20000 }));
    const stack = { nOutside: 1, films, nInside: 1, angleDeg: 30 };
    // Only the first, opaque layer is reached: sampled as that one film on what lies behind it.
    const steps = layersStepsPerNm(stack);
    expect(steps).toBe(layersStepsPerNm({ ...stack, films: films.slice(0, 1), nInside: 2.5 }));
    expect(steps).toBeLessThan(layersStepsPerNm({ ...stack, films: films.map((l) => ({ ...l, n: 2.5 })) }));
    for (const v of layersXyz(stack)) expect(Number.isFinite(v)).toBe(true);
  });
});

interface FixtureStack {
  readonly name: string;
  readonly nOutside: number;
  readonly layers: readonly { readonly n: number | [number, number]; readonly thicknessNm: number }[];
  readonly nInside: number | [number, number];
  readonly angleDeg: number;
}
interface Fixtures {
  readonly points: readonly (FixtureStack & {
    readonly lambdaNm: number;
    readonly R: { readonly s: number; readonly p: number };
    readonly T: { readonly s: number; readonly p: number } | null;
  })[];
  readonly spectra: readonly (FixtureStack & { readonly lambdaMinNm: number; readonly stepNm: number; readonly R: readonly number[] })[];
}
const fixtures = JSON.parse(readFileSync(new URL('fixtures/tmmStacks.json', import.meta.url), 'utf8')) as Fixtures;
const stackOf = (f: FixtureStack): LayerStack => ({
  nOutside: f.nOutside,
  films: f.layers.map((l) => ({ n: medium(l.n), thicknessNm: l.thicknessNm })),
  nInside: medium(f.nInside),
  angleDeg: f.angleDeg,
});

describe('tmm (Byrnes 2016, coh_tmm)', () => {
  it('R_s, R_p and T at single wavelengths: 2–16 films, absorbing, on metals, past the critical angle', () => {
    expect(fixtures.points.length).toBeGreaterThan(50);
    let worst = 0;
    for (const f of fixtures.points) {
      const stack = stackOf(f);
      for (const p of ['s', 'p'] as const) {
        worst = Math.max(worst, Math.abs(layersReflectance(f.lambdaNm, stack, p) - f.R[p]));
        if (f.T) worst = Math.max(worst, Math.abs(layersTransmittance(f.lambdaNm, stack, p) - f.T[p]));
      }
    }
    expect(worst).toBeLessThan(TMM_LAYERS_TOL);
  });

  it('colours of R on a 1 nm grid, 380–830 nm: the same samples, and layersXyz', () => {
    const w = spectralWeights('D65');
    const white = whiteXyz('D65');
    for (const f of fixtures.spectra) {
      const stack = stackOf(f);
      const lambdas = f.R.map((_, i) => f.lambdaMinNm + i * f.stepNm);
      const ours = layersReflectanceSpectrum(stack, lambdas);
      expect(Math.max(...ours.map((r, i) => Math.abs(r - f.R[i]!)))).toBeLessThan(TMM_LAYERS_TOL);
      const fromTmm = integrateXyz((l) => f.R[Math.round((l - f.lambdaMinNm) / f.stepNm)]!, w, 1);
      expect(
        deltaE00(
          integrateXyz((l) => ours[Math.round((l - f.lambdaMinNm) / f.stepNm)]!, w, 1),
          fromTmm,
          white,
        ),
      ).toBeLessThan(TMM_SPECTRUM_DE00);
      expect(deltaE00(layersXyz(stack), fromTmm, white), f.name).toBeLessThan(TMM_SPECTRUM_DE00);
    }
  });
});

describe('bad stacks are refused, naming the field', () => {
  const good: LayerStack = { nOutside: 1, films: bragg(2), nInside: N_GLASS, angleDeg: 0 };
  const cases: [string, LayerStack, RegExp][] = [
    ['films', { ...good, films: [] }, /^films: 0 is not allowed; expected a number in \[1, 64\] films/],
    ['films', { ...good, films: bragg(33) }, /^films: 66 is not allowed/],
    [
      'films[2].thicknessNm',
      { ...good, films: [...bragg(1), { n: 1.5, thicknessNm: -1 }] },
      /^films\[2\]\.thicknessNm: -1 .*\[0, 20000\] nm/,
    ],
    ['films[0].thicknessNm', { ...good, films: [{ n: 1.5, thicknessNm: Number.NaN }] }, /^films\[0\]\.thicknessNm: NaN/],
    ['films[1].n', { ...good, films: [...bragg(1).slice(0, 1), { n: 0.5, thicknessNm: 10 }] }, /^films\[1\]\.n: 0\.5 is not allowed/],
    ['films[0].n', { ...good, films: [{ n: { complex: [1, -1] }, thicknessNm: 10 }] }, /^films\[0\]\.n: complex:1,-1 .*gain/],
    ['nOutside', { ...good, nOutside: 5 }, /^nOutside: 5 is not allowed/],
    ['nInside', { ...good, nInside: { complex: [0, 1] } }, /^nInside: complex:0,1 is not allowed/],
    ['angleDeg', { ...good, angleDeg: 91 }, /^angleDeg: 91 is not allowed; expected a number in \[0, 90\] degrees/],
  ];
  it.each(cases)('%s', (parameter, stack, message) => {
    for (const call of [
      () => assertLayerStack(stack),
      () => layersReflectance(550, stack),
      () => layersTransmittance(550, stack),
      () => layersXyz(stack),
    ]) {
      expect(call).toThrow(ParameterError);
      expect(call).toThrow(message);
      try {
        call();
      } catch (e) {
        expect((e as ParameterError).parameter).toBe(parameter);
      }
    }
  });
  it('a good stack passes', () => expect(() => assertLayerStack(good)).not.toThrow());
});
