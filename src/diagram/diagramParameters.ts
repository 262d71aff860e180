import { FILM_MATERIALS, type FilmIndex } from '../physics/filmIndex.ts';
import { FILM_STACK_DOMAIN, POLARIZATIONS, type Polarization, SOAP_FILM_IN_AIR } from '../physics/filmReflectance.ts';
import { LAMBDA_MAX_NM, LAMBDA_MIN_NM } from '../physics/spectralWeights.ts';
import { type NumberDomain, quoted } from '../input/validate.ts';
import type { Catalogue, MessageKey } from '../i18n/en.ts';
import { message } from '../i18n/messages.ts';
import { FILM_PARAMETERS } from '../settings/filmParameters.ts';
import type { FilmSettings } from '../settings/filmSettings.ts';
import { type ParameterRow, defaultsOf } from '../settings/parameterRow.ts';
import { filmIndexRow } from '../settings/textRows.ts';
import { numberRow } from '../settings/valueRows.ts';

/** What <thin-film-diagram> shows: one film at one wavelength. */
export interface DiagramSettings {
  readonly thicknessNm: number;
  readonly angleDeg: number;
  readonly wavelengthNm: number;
  readonly nFilm: FilmIndex;
  readonly nOutside: number;
  readonly nInside: number;
  readonly polarization: Polarization;
}

/** The wavelengths the diagram shows: the colour integral's band (eqs 16–18). */
export const WAVELENGTH_DOMAIN: NumberDomain = { min: LAMBDA_MIN_NM, max: LAMBDA_MAX_NM, unit: 'nm' };

/** What a row accepts, for messages in any language: a number domain, a list of names, or a film index. */
export type Accepts =
  | { readonly kind: 'number'; readonly domain: NumberDomain }
  | { readonly kind: 'choice'; readonly choices: readonly string[] }
  | { readonly kind: 'filmIndex' };

interface DiagramRow {
  readonly row: ParameterRow<DiagramSettings>;
  readonly accepts: Accepts;
}

type Shared = keyof DiagramSettings & keyof FilmSettings;

/** A row of the bubble's schema (FILM_PARAMETERS) for a field the diagram shares, read and checked as it is there. */
function filmRow(key: Shared, accepts: Accepts): DiagramRow {
  const row = FILM_PARAMETERS.find((r) => r.key === key);
  if (!row) throw new Error(`FILM_PARAMETERS has no row ${key}`);
  // Its reading sets only `key`, a field of both settings with the same type.
  return { row: row as unknown as ParameterRow<DiagramSettings>, accepts };
}

/**
 * The diagram's attributes: the film's from the bubble's schema (the same names, checks and
 * defaults), the angle of incidence (FILM_STACK_DOMAIN) and the wavelength (the visible band).
 */
export const DIAGRAM_ROWS: readonly DiagramRow[] = [
  filmRow('thicknessNm', { kind: 'number', domain: FILM_STACK_DOMAIN.thicknessNm }),
  {
    row: numberRow<DiagramSettings, 'angleDeg'>({ key: 'angleDeg', url: 'angle' }, FILM_STACK_DOMAIN.angleDeg, 30, null),
    accepts: { kind: 'number', domain: FILM_STACK_DOMAIN.angleDeg },
  },
  {
    row: numberRow<DiagramSettings, 'wavelengthNm'>({ key: 'wavelengthNm', url: 'wavelength' }, WAVELENGTH_DOMAIN, 550, null),
    accepts: { kind: 'number', domain: WAVELENGTH_DOMAIN },
  },
  // The diagram's beams are of transparent media: its film and inside take a film index and a real number.
  {
    row: filmIndexRow<DiagramSettings, 'nFilm'>({ key: 'nFilm', url: 'nFilm' }, SOAP_FILM_IN_AIR.nFilm, null),
    accepts: { kind: 'filmIndex' },
  },
  filmRow('nOutside', { kind: 'number', domain: FILM_STACK_DOMAIN.nOutside }),
  {
    row: numberRow<DiagramSettings, 'nInside'>(
      { key: 'nInside', url: 'nInside' },
      FILM_STACK_DOMAIN.nInside,
      SOAP_FILM_IN_AIR.nInside,
      null,
    ),
    accepts: { kind: 'number', domain: FILM_STACK_DOMAIN.nInside },
  },
  filmRow('polarization', { kind: 'choice', choices: POLARIZATIONS }),
];

export const DIAGRAM_ATTRIBUTES = DIAGRAM_ROWS.map((r) => r.row.attribute);
export const DEFAULT_DIAGRAM_SETTINGS: DiagramSettings = defaultsOf(DIAGRAM_ROWS.map((r) => r.row));

/** A unit as a message writes it after a number ('' for none). */
export function unitText(unit: string, catalogue: Catalogue): string {
  if (unit === 'degrees') return catalogue['common.unit.degrees'];
  return unit === 'nm' ? ` ${catalogue['common.unit.nm']}` : unit && ` ${unit}`;
}

/** Why `raw` is refused for `attribute`, in the catalogue's language, with the allowed range. */
export function refusal(attribute: string, raw: string, accepts: Accepts, catalogue: Catalogue): string {
  const value = quoted(raw);
  const key: MessageKey =
    accepts.kind === 'number' ? 'diagram.error.number' : accepts.kind === 'choice' ? 'diagram.error.choice' : 'diagram.error.filmIndex';
  const domain = accepts.kind === 'number' ? accepts.domain : FILM_STACK_DOMAIN.nFilm;
  return message(catalogue, key, {
    attribute,
    value,
    min: domain.min,
    max: domain.max,
    unit: unitText(domain.unit, catalogue),
    choices: accepts.kind === 'choice' ? accepts.choices.join(', ') : '',
    materials: FILM_MATERIALS.join(', '),
    cauchy: 'cauchy:A,B[,C]',
  });
}

/** The settings the attributes ask for (`get` reads one): a refused value is named in `errors` and `base`'s kept. */
export function readDiagramAttributes(
  get: (attribute: string) => string | null,
  base: DiagramSettings,
  catalogue: Catalogue,
): { readonly settings: DiagramSettings; readonly errors: readonly string[] } {
  let settings = base;
  const errors: string[] = [];
  for (const { row, accepts } of DIAGRAM_ROWS) {
    const raw = get(row.attribute);
    if (raw === null) continue;
    const read = row.read(raw);
    if (read) settings = { ...settings, ...read };
    else errors.push(refusal(row.attribute, raw, accepts, catalogue));
  }
  return { settings, errors };
}
