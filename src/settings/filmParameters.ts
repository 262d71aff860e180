import { FILM_STACK_DOMAIN, POLARIZATIONS, SOAP_FILM_IN_AIR } from '../physics/filmReflectance.ts';
import { FIELD_SETTINGS, type FieldSettings } from '../fields/fields.ts';
import { FLOW_PARAMETERS, type FlowParameterKey } from '../physics/filmDynamics/flowParameters.ts';
import { NORMALIZATIONS } from '../physics/spectralWeights.ts';
import { FIELDS, type FilmSettings, MODES, SIDES, SPACES, TONE_MAPPINGS } from './filmSettings.ts';
import { DEFAULT_LIGHT } from './filmLight.ts';
import { layersRow } from './layersRow.ts';
import { type ParameterRow, defaultsOf } from './parameterRow.ts';
import { environmentRow, illuminantRow, lightTintRow, mediumRow } from './textRows.ts';
import { choiceRow, flagRow, numberRow } from './valueRows.ts';

type Row = ParameterRow<FilmSettings>;

/** The FLOW_PARAMETERS row of a flow parameter (a settings field of the same name, where the settings have it). */
export const flowParameterRow = (key: FlowParameterKey) => FLOW_PARAMETERS.find((r) => r.key === key)!;

/** The rows of the fields' own settings, as the fields declare them (FIELD_SETTINGS). */
const fieldRows = (): Row[] =>
  Object.entries(FIELD_SETTINGS).map(([name, setting]) => {
    const names = { key: name as keyof FieldSettings, url: setting.url };
    return setting.kind === 'flag'
      ? flagRow(names, setting.defaultValue, setting.folder)
      : numberRow(names, setting.domain, setting.defaultValue, setting.folder, setting.step);
  });

/**
 * The schema of what a rendered bubble depends on: one row per parameter, with its names (URL,
 * attribute, command-line flag), domain or choices, default (the default view: a swirling soap
 * bubble in daylight), label and panel control. The film's own domains are FILM_STACK_DOMAIN's;
 * the rows of the fields' own settings follow the thickness, as the fields declare them.
 */
export const FILM_PARAMETERS: readonly Row[] = [
  choiceRow({ key: 'field', url: 'field' }, FIELDS, 'swirl', 'film'),
  // The flowing film's mean thickness is this one: its default is the simulation's.
  numberRow(
    { key: 'thicknessNm', url: 'thickness' },
    FILM_STACK_DOMAIN.thicknessNm,
    flowParameterRow('thicknessNm').defaultValue,
    'film',
    1,
  ),
  ...fieldRows(),
  mediumRow({ key: 'nFilm', url: 'nFilm' }, SOAP_FILM_IN_AIR.nFilm, 'film', 'film'),
  layersRow({ key: 'layers', url: 'layers' }, 'film'),
  numberRow({ key: 'nOutside', url: 'nOutside' }, FILM_STACK_DOMAIN.nOutside, SOAP_FILM_IN_AIR.nOutside, 'film', 0.01),
  mediumRow({ key: 'nInside', url: 'nInside' }, SOAP_FILM_IN_AIR.nInside, 'film', 'inside'),
  illuminantRow({ key: 'illuminant', url: 'illuminant' }, DEFAULT_LIGHT.illuminant, 'light and colour'),
  lightTintRow({ key: 'lightTint', url: 'lightTint' }, DEFAULT_LIGHT.lightTint, 'light and colour'),
  choiceRow({ key: 'polarization', url: 'polarization' }, POLARIZATIONS, DEFAULT_LIGHT.polarization, 'light and colour'),
  choiceRow({ key: 'normalization', url: 'normalization' }, NORMALIZATIONS, DEFAULT_LIGHT.normalization, 'light and colour'),
  choiceRow({ key: 'space', url: 'space' }, SPACES, 'srgb', 'light and colour'),
  numberRow({ key: 'exposure', url: 'exposure' }, { min: 0, max: 100, unit: '' }, 1, 'light and colour', 0.01),
  choiceRow({ key: 'tonemap', url: 'tonemap' }, TONE_MAPPINGS, 'auto', 'light and colour'),
  choiceRow({ key: 'mode', url: 'mode' }, MODES, 'table', 'view'),
  environmentRow({ key: 'env', url: 'env' }, 'sky', 'view'),
  numberRow({ key: 'envRotationDeg', url: 'envRotation' }, { min: 0, max: 360, unit: 'degrees' }, 0, 'view', 1),
  choiceRow({ key: 'sides', url: 'sides' }, SIDES, 'both', 'view'),
  numberRow({ key: 'timeSeconds', url: 'time' }, { min: 0, max: 1e6, unit: 's' }, 0, null),
];

/** The default view. */
export const DEFAULT_SETTINGS: FilmSettings = defaultsOf(FILM_PARAMETERS);
