import { type Complex, type RefractiveIndex, cSqrt } from './complex.ts';
import { DAIMON_MASUMURA_2007_WATER_20C } from './data/daimonMasumura2007.ts';
import { JOHNSON_CHRISTY_1972 } from './data/johnsonChristy1972.ts';
import { JOHNSON_CHRISTY_1974 } from './data/johnsonChristy1974.ts';
import { MALITSON_1965_SILICA } from './data/malitson1965.ts';
import { QUERRY_1985 } from './data/querry1985.ts';
import { RAKIC_1998_ALUMINIUM } from './data/rakic1998Aluminium.ts';
import { SARKAR_2019 } from './data/sarkar2019.ts';
import { sellmeier } from './sellmeier.ts';
import { HC_EV_NM, tabulatedIndex } from './tabulatedIndex.ts';

/** ñ(λ) = n + ik at λ in nm; a real number where the source gives n only (a transparent formula). */
export type IndexAt = (lambdaNm: number) => RefractiveIndex;

/** A wavelength range in nm. */
export interface RangeNm {
  readonly min: number;
  readonly max: number;
}

/**
 * A medium by name, from a published source (docs/physics.md#absorbing-media). What checks a
 * medium (its name, where it is defined, what it is) is here at once; its index data is read and
 * its interpolant built by `load`, the first time its index is asked for.
 */
export interface NamedMediumEntry {
  /** What it is and whose values, in one line (the colour tool's usage lists it). */
  readonly source: string;
  /** Where the source gives values: a table's first to last row, a formula's stated validity. */
  readonly rangeNm: RangeNm;
  /** Its ñ(λ) from its data file. */
  readonly load: () => IndexAt;
  /**
   * Also a film index (filmIndex.ts): real at every λ, offered where a real film index is asked
   * for (the diagram's, the panel's film index) as well as where any medium is.
   */
  readonly filmIndex?: true;
}

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

const JC_1972_NM = { min: 367.9, max: 892 };
const JC_1974_NM = { min: 368, max: 892 };

/**
 * Every named medium: metals for the inside (a film on a metal), oxides and water for the film,
 * though each may be used in either place. A new one is an entry here and its data file in data/.
 */
export const MEDIA = {
  water: {
    source: 'water at 20 °C, Daimon & Masumura 2007 (Sellmeier)',
    rangeNm: { min: 182, max: 1129 },
    load: () => sellmeier({ b: DAIMON_MASUMURA_2007_WATER_20C.k, cUm2: DAIMON_MASUMURA_2007_WATER_20C.lUm2 }),
    filmIndex: true,
  },
  Au: { source: 'gold, Johnson & Christy 1972', rangeNm: JC_1972_NM, load: () => tabulatedIndex(JOHNSON_CHRISTY_1972.Au).indexAt },
  Ag: { source: 'silver, Johnson & Christy 1972', rangeNm: JC_1972_NM, load: () => tabulatedIndex(JOHNSON_CHRISTY_1972.Ag).indexAt },
  Cu: { source: 'copper, Johnson & Christy 1972', rangeNm: JC_1972_NM, load: () => tabulatedIndex(JOHNSON_CHRISTY_1972.Cu).indexAt },
  Al: {
    source: 'aluminium, Rakić et al. 1998 (Lorentz–Drude)',
    // √ε on the principal branch: Im ε > 0 gives k > 0. The model holds well past the colour band.
    rangeNm: { min: 200, max: 2000 },
    load: () => (lambdaNm: number) => cSqrt(lorentzDrude(HC_EV_NM / lambdaNm)),
  },
  Ti: { source: 'titanium, Johnson & Christy 1974', rangeNm: JC_1974_NM, load: () => tabulatedIndex(JOHNSON_CHRISTY_1974.Ti).indexAt },
  Fe: { source: 'iron, Johnson & Christy 1974', rangeNm: JC_1974_NM, load: () => tabulatedIndex(JOHNSON_CHRISTY_1974.Fe).indexAt },
  Cr: { source: 'chromium, Johnson & Christy 1974', rangeNm: JC_1974_NM, load: () => tabulatedIndex(JOHNSON_CHRISTY_1974.Cr).indexAt },
  Ni: { source: 'nickel, Johnson & Christy 1974', rangeNm: JC_1974_NM, load: () => tabulatedIndex(JOHNSON_CHRISTY_1974.Ni).indexAt },
  TiO2: {
    source: 'titanium dioxide film, Sarkar et al. 2019',
    rangeNm: { min: 370, max: 840 },
    load: () => tabulatedIndex(SARKAR_2019.TiO2).indexAt,
  },
  Fe3O4: { source: 'magnetite, Querry 1985', rangeNm: { min: 370, max: 840 }, load: () => tabulatedIndex(QUERRY_1985.Fe3O4).indexAt },
  SiO2: {
    source: 'fused silica, Malitson 1965 (Sellmeier)',
    rangeNm: { min: 210, max: 3710 },
    load: () => sellmeier({ b: MALITSON_1965_SILICA.b, cUm2: MALITSON_1965_SILICA.cUm.map((c) => c ** 2) }),
  },
} as const satisfies Readonly<Record<string, NamedMediumEntry>>;

type Media = typeof MEDIA;
export type MediumName = keyof Media;
/** The names that are also film indices (FilmIndex). */
export type FilmMaterial = { [K in MediumName]: Media[K] extends { readonly filmIndex: true } ? K : never }[MediumName];
/** The names that are media only. */
export type NamedMedium = Exclude<MediumName, FilmMaterial>;

export const MEDIUM_NAMES = Object.keys(MEDIA) as readonly MediumName[];
const entry = (name: MediumName): NamedMediumEntry => MEDIA[name];
export const FILM_MATERIALS = MEDIUM_NAMES.filter((name) => entry(name).filmIndex) as readonly FilmMaterial[];
export const NAMED_MEDIA = MEDIUM_NAMES.filter((name) => !entry(name).filmIndex) as readonly NamedMedium[];

export const isMediumName = (text: unknown): text is MediumName => (MEDIUM_NAMES as readonly unknown[]).includes(text);

/** Where the named medium's source gives values. */
export const namedRangeNm = (name: MediumName): RangeNm => MEDIA[name].rangeNm;

/** What the named medium is and whose values, in one line. */
export const namedSource = (name: MediumName): string => MEDIA[name].source;

const loaded = new Map<MediumName, IndexAt>();

/** The named medium's ñ(λ), loaded the first time it is asked for. */
export function namedIndex(name: MediumName): IndexAt {
  let at = loaded.get(name);
  if (at === undefined) loaded.set(name, (at = MEDIA[name].load()));
  return at;
}
