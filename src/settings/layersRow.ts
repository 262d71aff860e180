import { FIELD_THICKNESS, type FilmLayer, LAYERS_DOMAIN } from '../physics/stackFilms.ts';
import { LAYERS_EXPECTED, layersText, readLayers } from '../physics/stackText.ts';
import type { Expectation, PanelFolder, ParameterRow, RowNames } from './parameterRow.ts';
import { textRow } from './textRows.ts';

/**
 * The longest layers text the URL reads: every one of LAYERS_DOMAIN.count.max films written out
 * with a Cauchy film's three coefficients and a thickness, each number at full precision, fits.
 */
export const LAYERS_MAX_CHARS = 8192;

/** What a layers text accepts, as a catalogue's values (the catalogue's test holds its English to LAYERS_EXPECTED). */
const EXPECTS: Expectation = {
  key: 'expected.layers',
  values: {
    ...LAYERS_DOMAIN.thicknessNm,
    field: FIELD_THICKNESS,
    nMin: LAYERS_DOMAIN.repeat.min,
    nMax: LAYERS_DOMAIN.repeat.max,
    count: LAYERS_DOMAIN.count.max,
  },
};

/**
 * A stack of films (stackText.ts): `INDEX:THICKNESS` entries separated by `/`, groups `(…)*N`.
 * The empty text is the empty list, the default: no stack, the single film of the row `nFilm`.
 */
export const layersRow = <S, K extends keyof S & string>(n: RowNames<S, K>, folder: PanelFolder | null): ParameterRow<S> => ({
  ...textRow<S, K, readonly FilmLayer[]>(n, [] as S[K] & readonly FilmLayer[], folder, {
    expected: LAYERS_EXPECTED,
    expects: EXPECTS,
    parse: (raw) => {
      if (raw.trim() === '') return { value: [] };
      const reading = readLayers(raw);
      return 'films' in reading ? { value: reading.films } : reading;
    },
    text: layersText,
    control: (folder) => ({ folder, kind: 'stack' }),
  }),
  maxLength: LAYERS_MAX_CHARS,
});
