import { type Complex, cSqrt } from './complex.ts';
import { JOHNSON_CHRISTY_1972 } from './data/johnsonChristy1972.ts';
import { JOHNSON_CHRISTY_1974 } from './data/johnsonChristy1974.ts';
import { MALITSON_1965_SILICA } from './data/malitson1965.ts';
import { QUERRY_1985 } from './data/querry1985.ts';
import { RAKIC_1998_ALUMINIUM } from './data/rakic1998Aluminium.ts';
import { SARKAR_2019 } from './data/sarkar2019.ts';
import { HC_EV_NM, type TabulatedIndex, tabulatedIndex } from './tabulatedIndex.ts';

/**
 * Media by name, each ñ(λ) = n + ik from a published source (docs/physics.md#absorbing-media):
 * metals for the inside (a film on a metal) and oxides for the film, though either may be used
 * in either place. `rangeNm` is where the source gives values: a table's first to last row, a
 * formula's stated validity.
 */
export const NAMED_MEDIA = ['Au', 'Ag', 'Cu', 'Al', 'Ti', 'Fe', 'Cr', 'Ni', 'TiO2', 'Fe3O4', 'SiO2'] as const;
export type NamedMedium = (typeof NAMED_MEDIA)[number];

export const isNamedMedium = (text: unknown): text is NamedMedium => (NAMED_MEDIA as readonly unknown[]).includes(text);

/** ε(ħω) of the Lorentz–Drude model (data/rakic1998Aluminium.ts), ħω in eV. */
function lorentzDrude(energyEv: number): Complex {
  const { plasmaEv, drude, oscillators } = RAKIC_1998_ALUMINIUM;
  const wp2 = plasmaEv * plasmaEv;
  const w = energyEv;
  // −f0 ω_p² / (ω² + iωΓ0)
  const dRe = w * w;
  const dIm = w * drude.gammaEv;
  const d2 = dRe * dRe + dIm * dIm;
  let re = 1 - (drude.f * wp2 * dRe) / d2;
  let im = (drude.f * wp2 * dIm) / d2;
  for (const o of oscillators) {
    // f ω_p² / (ω_j² − ω² − iωΓ_j)
    const lRe = o.omegaEv * o.omegaEv - w * w;
    const lIm = -w * o.gammaEv;
    const l2 = lRe * lRe + lIm * lIm;
    re += (o.f * wp2 * lRe) / l2;
    im -= (o.f * wp2 * lIm) / l2;
  }
  return { re, im };
}

/** n of fused silica, Malitson's Sellmeier formula (data/malitson1965.ts), λ in nm. */
function silicaIndex(lambdaNm: number): number {
  const x = (lambdaNm / 1000) ** 2;
  let n2 = 1;
  MALITSON_1965_SILICA.b.forEach((b, i) => (n2 += (b * x) / (x - MALITSON_1965_SILICA.cUm[i]! ** 2)));
  return Math.sqrt(n2);
}

const formula = (indexAt: (lambdaNm: number) => Complex, rangeNm: { min: number; max: number }): TabulatedIndex => ({ indexAt, rangeNm });

/** Each named medium's ñ(λ) and where it is defined. */
export const NAMED_MEDIUM_INDEX: Readonly<Record<NamedMedium, TabulatedIndex>> = {
  Au: tabulatedIndex(JOHNSON_CHRISTY_1972.Au),
  Ag: tabulatedIndex(JOHNSON_CHRISTY_1972.Ag),
  Cu: tabulatedIndex(JOHNSON_CHRISTY_1972.Cu),
  // √ε on the principal branch: Im ε > 0 gives k > 0. The model holds well past the colour band.
  Al: formula((lambdaNm) => cSqrt(lorentzDrude(HC_EV_NM / lambdaNm)), { min: 200, max: 2000 }),
  Ti: tabulatedIndex(JOHNSON_CHRISTY_1974.Ti),
  Fe: tabulatedIndex(JOHNSON_CHRISTY_1974.Fe),
  Cr: tabulatedIndex(JOHNSON_CHRISTY_1974.Cr),
  Ni: tabulatedIndex(JOHNSON_CHRISTY_1974.Ni),
  TiO2: tabulatedIndex(SARKAR_2019.TiO2),
  Fe3O4: tabulatedIndex(QUERRY_1985.Fe3O4),
  SiO2: formula((lambdaNm) => ({ re: silicaIndex(lambdaNm), im: 0 }), MALITSON_1965_SILICA.rangeNm),
};

/** A one-line source of each named medium, for docs and usage. */
export const NAMED_MEDIUM_SOURCE: Readonly<Record<NamedMedium, string>> = {
  Au: 'gold, Johnson & Christy 1972',
  Ag: 'silver, Johnson & Christy 1972',
  Cu: 'copper, Johnson & Christy 1972',
  Al: 'aluminium, Rakić et al. 1998 (Lorentz–Drude)',
  Ti: 'titanium, Johnson & Christy 1974',
  Fe: 'iron, Johnson & Christy 1974',
  Cr: 'chromium, Johnson & Christy 1974',
  Ni: 'nickel, Johnson & Christy 1974',
  TiO2: 'titanium dioxide film, Sarkar et al. 2019',
  Fe3O4: 'magnetite, Querry 1985',
  SiO2: 'fused silica, Malitson 1965',
};
