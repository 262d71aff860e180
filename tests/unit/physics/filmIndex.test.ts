import { describe, expect, it } from 'vitest';
import { spectralBins } from '../../../src/physics/binnedIntegration.ts';
import { deltaE00 } from '../../../src/physics/colorDifference.ts';
import { dispersiveBinnedXyz, binnedXyz } from '../../../src/physics/binnedIntegration.ts';
import {
  type FilmIndex,
  filmIndexAt,
  filmIndexFromJson,
  filmIndexProblem,
  filmIndexText,
  readFilmIndex,
} from '../../../src/physics/filmIndex.ts';
import { type FilmStack, filmOptics } from '../../../src/physics/filmReflectance.ts';
import { filmXyz, whiteXyz } from '../../../src/physics/spectralIntegration.ts';
import { DEFAULT_FILM_QUALITY } from '../../../src/settings/filmQuality.ts';
import { LAMBDA_MAX_NM, LAMBDA_MIN_NM, spectralWeights } from '../../../src/physics/spectralWeights.ts';
import {
  DISPERSIVE_BINNED_DE00,
  DISPERSIVE_REFERENCE_DE00,
  FEW_OPERATIONS_TOL,
  FLOAT_TOLERANCE,
  WATER_INDEX_TOL,
} from '../../tolerances.ts';

/**
 * Water at 20 °C as measured, relative to air, at the Fraunhofer F, D and C lines (the handbooks'
 * table of the index of water: n_F = 1.33712, n_D = 1.33299, n_C = 1.33114), made absolute with
 * standard air's index, 1.00028 (Edlén), as the formula gives the index against vacuum.
 */
const MEASURED_IN_AIR = [
  [486.13, 1.33712],
  [589.29, 1.33299],
  [656.28, 1.33114],
] as const;
const AIR_INDEX = 1.00028;

/**
 * The IAPWS 1997 formulation of the index of ordinary water (Harvey, Gallagher and Levelt Sengers,
 * J. Phys. Chem. Ref. Data 27, 761 (1998)), a fit to a different body of measurements than the
 * formula under test: (n² − 1)/(n² + 2)/ρ̄ = a0 + a1 ρ̄ + a2 T̄ + a3 λ̄² T̄ + a4/λ̄² + a5/(λ̄² − λ̄_UV²)
 * + a6/(λ̄² − λ̄_IR²) + a7 ρ̄², with T̄ = T/273.15 K, ρ̄ = ρ/1000 kg m⁻³, λ̄ = λ/589 nm; at 20 °C,
 * ρ = 998.2071 kg m⁻³.
 */
function iapws1997Water(lambdaNm: number): number {
  const a = [0.244257733, 9.74634476e-3, -3.73234996e-3, 2.68678472e-4, 1.5892057e-3, 2.45934259e-3, 0.90070492, -1.66626219e-2];
  const rho = 998.2071 / 1000;
  const t = 293.15 / 273.15;
  const l2 = (lambdaNm / 589) ** 2;
  const lorentz =
    rho *
    (a[0]! +
      a[1]! * rho +
      a[2]! * t +
      a[3]! * l2 * t +
      a[4]! / l2 +
      a[5]! / (l2 - 0.229202 ** 2) +
      a[6]! / (l2 - 5.432937 ** 2) +
      a[7]! * rho * rho);
  return Math.sqrt((2 * lorentz + 1) / (1 - lorentz));
}

describe('the film index n(λ)', () => {
  it('gives water at 20 °C within 3e-4 of the measured F, D and C lines and of IAPWS 1997 at 404.7–656.3 nm', () => {
    for (const [lambdaNm, nAir] of MEASURED_IN_AIR)
      expect(Math.abs(filmIndexAt('water', lambdaNm) - nAir * AIR_INDEX)).toBeLessThan(WATER_INDEX_TOL);
    for (const lambdaNm of [404.7, 486.1, 589.3, 656.3]) {
      expect(Math.abs(filmIndexAt('water', lambdaNm) - iapws1997Water(lambdaNm))).toBeLessThan(WATER_INDEX_TOL);
    }
  });

  it('evaluates a Cauchy film as A + B/λ² + C/λ⁴ with λ in nm, and B = C = 0 as A exactly', () => {
    expect(Math.abs(filmIndexAt({ cauchy: [1.45, 6000, 0] }, 500) - (1.45 + 6000 / 250000))).toBeLessThan(FEW_OPERATIONS_TOL);
    expect(Math.abs(filmIndexAt({ cauchy: [1.4, 0, 1e9] }, 400) - (1.4 + 1e9 / 400 ** 4))).toBeLessThan(FEW_OPERATIONS_TOL);
    expect(filmIndexAt({ cauchy: [1.37, 0, 0] }, 433.3)).toBe(1.37);
  });

  it('reads and writes the URL forms, and refuses an index that leaves 1–4 anywhere in 380–830 nm, saying where', () => {
    for (const text of ['1.33', 'water', 'cauchy:1.45,6000', 'cauchy:1.45,6000,-200000000']) {
      const read = readFilmIndex(text);
      expect('index' in read && filmIndexText(read.index)).toBe(text);
    }
    expect(readFilmIndex('cauchy:3.9,20000')).toEqual({ problem: 'n at 380 nm is 4.0385, above 4' });
    expect(readFilmIndex('cauchy:1.01,-10000')).toEqual({ problem: 'n at 380 nm is 0.940748, below 1' });
    expect(filmIndexProblem({ cauchy: [1.12, -80000, 1e10] })).toBe('n at 500 nm is 0.96, below 1'); // the ends are 1.03, 1.05
    for (const bad of ['', 'cauchy:', 'cauchy:1.4', 'cauchy:1.4,a', 'cauchy:1,2,3,4', 'glass', '0x1f', 'Infinity']) {
      expect('problem' in readFilmIndex(bad)).toBe(true);
    }
    expect(readFilmIndex('9')).toEqual({ problem: 'n is 9, above 4' });
  });

  it('reads a cases file’s nFilm: a number, a material or { cauchy: [A, B(, C)] }', () => {
    expect(filmIndexFromJson(1.4)).toBe(1.4);
    expect(filmIndexFromJson('water')).toBe('water');
    expect(filmIndexFromJson({ cauchy: [1.45, 6000] })).toEqual({ cauchy: [1.45, 6000, 0] });
    for (const bad of ['glass', { cauchy: [1] }, { cauchy: [1, '2'] }, { cauchy: [1, 2], x: 1 }, [1.4], null]) {
      expect(filmIndexFromJson(bad)).toBeNull();
    }
  });
});

/**
 * An independent computation of a film's reflectance: the characteristic (transfer) matrix of one
 * layer, per polarisation with the tilted admittances η = n cos θ (s) and n / cos θ (p), at each
 * wavelength with the film's own n_b(λ); no total reflection in these cases (n_a = n_c = 1).
 */
function transferMatrixReflectance(index: FilmIndex, thicknessNm: number, angleDeg: number, lambdaNm: number): number {
  const sin = Math.sin((angleDeg * Math.PI) / 180);
  const nb = filmIndexAt(index, lambdaNm);
  const cosA = Math.cos((angleDeg * Math.PI) / 180);
  const cosB = Math.sqrt(1 - (sin / nb) ** 2);
  const delta = (2 * Math.PI * nb * thicknessNm * cosB) / lambdaNm;
  const [c, s] = [Math.cos(delta), Math.sin(delta)];
  const r = (ea: number, eb: number, ec: number) => {
    const num = [(ea - ec) * c, ((ea * ec) / eb - eb) * s];
    const den = [(ea + ec) * c, ((ea * ec) / eb + eb) * s];
    return (num[0]! ** 2 + num[1]! ** 2) / (den[0]! ** 2 + den[1]! ** 2);
  };
  return (r(cosA, nb * cosB, cosA) + r(1 / cosA, nb / cosB, 1 / cosA)) / 2;
}

/** Its XYZ: the midpoint rule every 0.05 nm on the 1 nm weights taken as linear between knots. */
function transferMatrixXyz(index: FilmIndex, thicknessNm: number, angleDeg: number): [number, number, number] {
  const w = spectralWeights('D65', 'white');
  const h = 0.05;
  const xyz: [number, number, number] = [0, 0, 0];
  for (let l = LAMBDA_MIN_NM + h / 2; l < LAMBDA_MAX_NM; l += h) {
    const i = Math.floor(l - LAMBDA_MIN_NM);
    const f = l - LAMBDA_MIN_NM - i;
    const r = transferMatrixReflectance(index, thicknessNm, angleDeg, l) * h;
    [w.x, w.y, w.z].forEach((t, k) => (xyz[k] = xyz[k]! + r * (t[i]! + (t[i + 1]! - t[i]!) * f)));
  }
  return xyz;
}

describe('the reference with a dispersive film', () => {
  const films: [FilmIndex, number, number][] = [
    ['water', 300, 0],
    ['water', 1200, 60],
    ['water', 4000, 30],
    [{ cauchy: [1.45, 6000, 0] }, 500, 45],
    [{ cauchy: [1.45, 6000, 0] }, 2000, 10],
    [{ cauchy: [1.6, 12000, 4e8] }, 800, 75],
  ];

  it(`matches a transfer-matrix computation per wavelength within ΔE00 ${DISPERSIVE_REFERENCE_DE00}`, () => {
    const white = whiteXyz('D65');
    for (const [nFilm, thicknessNm, angleDeg] of films) {
      const reference = filmXyz({ nOutside: 1, nFilm, nInside: 1, thicknessNm, angleDeg });
      expect(deltaE00(reference, transferMatrixXyz(nFilm, thicknessNm, angleDeg), white)).toBeLessThan(DISPERSIVE_REFERENCE_DE00);
    }
  });

  it('differs from the constant 1.333 by what dispersion does (ΔE00 > 0.3 for a 2 µm soap film)', () => {
    const white = whiteXyz('D65');
    const stack = { nOutside: 1, nInside: 1, thicknessNm: 2000, angleDeg: 0 };
    expect(deltaE00(filmXyz({ ...stack, nFilm: 'water' }), filmXyz({ ...stack, nFilm: 1.333 }), white)).toBeGreaterThan(0.3);
  });

  it('equals the constant-index result exactly when B = C = 0', () => {
    for (const [thicknessNm, angleDeg, polarization] of [
      [0, 0, 'unpolarized'],
      [550, 30, 'unpolarized'],
      [7000, 80, 'paper'],
      [20000, 89.9, 's'],
    ] as const) {
      const stack = { nOutside: 1, nInside: 1, thicknessNm, angleDeg };
      const constant = filmXyz({ ...stack, nFilm: 1.41 }, { polarization });
      expect(filmXyz({ ...stack, nFilm: { cauchy: [1.41, 0, 0] } }, { polarization })).toEqual(constant);
    }
  });

  it('refuses a Cauchy film that leaves the index domain, naming nFilm', () => {
    expect(() => filmXyz({ nOutside: 1, nFilm: { cauchy: [3.9, 20000, 0] }, nInside: 1, thicknessNm: 500, angleDeg: 0 })).toThrow(
      /^nFilm: cauchy:3\.9,20000 is not allowed \(n at 380 nm is 4\.0385, above 4\)/,
    );
  });
});

describe('the binned method with a dispersive film (the shaders’ twin)', () => {
  const bins = spectralBins(spectralWeights('D65', 'white'), DEFAULT_FILM_QUALITY.dispersiveSpectralBins);
  const white = whiteXyz('D65');

  it('is binnedXyz when n does not vary', () => {
    const stack = {
      nOutside: 1,
      nFilm: { cauchy: [1.5, 0, 0] },
      nInside: 1.2,
      thicknessNm: 700,
      angleDeg: 40,
    } satisfies FilmStack<FilmIndex>;
    const constant = binnedXyz(filmOptics({ ...stack, nFilm: 1.5 }), bins);
    dispersiveBinnedXyz(stack, 'unpolarized', bins).forEach((v, k) => expect(Math.abs(v - constant[k]!)).toBeLessThan(FLOAT_TOLERANCE));
  });

  it(`stays within ΔE00 ${DISPERSIVE_BINNED_DE00} of the reference for water and a Cauchy film, 0–2000 nm, 0–85°`, () => {
    for (const nFilm of ['water', { cauchy: [1.45, 6000, 0] }] as const) {
      for (let thicknessNm = 0; thicknessNm <= 2000; thicknessNm += 125) {
        for (const angleDeg of [0, 45, 85]) {
          const stack = { nOutside: 1, nFilm, nInside: 1, thicknessNm, angleDeg };
          expect(deltaE00(dispersiveBinnedXyz(stack, 'unpolarized', bins), filmXyz(stack), white)).toBeLessThan(DISPERSIVE_BINNED_DE00);
        }
      }
    }
  });
});
