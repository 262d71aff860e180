import { describe, expect, it } from 'vitest';
import { parseSettings, settingsToQuery } from '../../../src/settings/settingsQuery.ts';
import { DEFAULT_VIEW_SETTINGS as DEFAULT_SETTINGS, VIEW_PARAMETERS } from '../../../src/settings/viewParameters.ts';
import { MAX_ECHOED_CHARS } from '../../../src/input/validate.ts';
import { ENVIRONMENTS, FIELDS, MODES } from '../../../src/settings/filmSettings.ts';
import { ABSURDLY_LONG, NOT_NUMBERS, notNames, outsideRange } from '../fixtures/badValues.ts';

describe('URL parameters', () => {
  it('reads every documented parameter', () => {
    const { settings, errors } = parseSettings(
      '?thickness=420&thicknessRange=300&speed=2&field=drainage&nFilm=1.4&nOutside=1.1&nInside=1.2&illuminant=7500' +
        '&polarization=s&normalization=paper&space=display-p3&mode=exact&sides=front&env=park&envRotation=90&tonemap=neutral&exposure=1.5&animate=0&time=12.5' +
        '&radius=25&surfactant=2e-7&evaporation=3&wind=0.5&seed=42&simSpeed=2&grid=32&renew=0&pixelRatio=1.5',
    );
    expect(errors).toEqual([]);
    expect(settings).toEqual({
      ...DEFAULT_SETTINGS,
      thicknessNm: 420,
      thicknessRangeNm: 300,
      swirlSpeed: 2,
      field: 'drainage',
      nFilm: 1.4,
      nOutside: 1.1,
      nInside: 1.2,
      illuminant: { daylightCct: 7500 },
      polarization: 's',
      normalization: 'paper',
      space: 'display-p3',
      mode: 'exact',
      sides: 'front',
      env: 'park',
      envRotationDeg: 90,
      tonemap: 'neutral',
      exposure: 1.5,
      animate: false,
      timeSeconds: 12.5,
      radiusMm: 25,
      surfactantMolM2: 2e-7,
      evaporationNmS: 3,
      windMps: 0.5,
      seed: 42,
      simSpeed: 2,
      gridN: 32,
      renew: false,
      pixelRatio: 1.5,
    });
  });

  it('reads a named metal, a complex constant and a named film, and writes them back', () => {
    for (const [query, media] of [
      ['?nInside=Au', { nInside: 'Au' }],
      ['?nInside=complex:2.6,3.4', { nInside: { complex: [2.6, 3.4] } }],
      ['?nFilm=TiO2&nInside=Ti', { nFilm: 'TiO2', nInside: 'Ti' }],
      ['?nFilm=Fe3O4&nInside=Fe', { nFilm: 'Fe3O4', nInside: 'Fe' }],
    ] as const) {
      const read = parseSettings(query);
      expect(read, query).toEqual({ settings: { ...DEFAULT_SETTINGS, ...media }, errors: [], refusals: [] });
      expect(parseSettings(`?${settingsToQuery(read.settings)}`).settings, query).toEqual(read.settings);
    }
  });

  it('refuses k < 0, n ≤ 0, an unknown name and a complex outside, naming the parameter and what is wrong', () => {
    for (const [query, name, why] of [
      ['?nInside=complex:2.6,-1', 'nInside', 'k < 0 would be a medium with gain'],
      ['?nInside=complex:0,3', 'nInside', 'n is 0, below 0.01'],
      ['?nFilm=complex:-1,0', 'nFilm', 'n is -1, below 0.01'],
      ['?nInside=Unobtainium', 'nInside', 'Au, Ag, Cu'],
      ['?nOutside=complex:1.5,0.1', 'nOutside', '[1, 4]'],
      ['?nOutside=Au', 'nOutside', '[1, 4]'],
    ] as const) {
      const { settings, errors } = parseSettings(query);
      expect(settings, query).toEqual(DEFAULT_SETTINGS);
      expect(errors, query).toHaveLength(1);
      expect(errors[0]!.startsWith(`${name}=`), errors[0]).toBe(true);
      expect(errors[0], query).toContain(why);
    }
  });

  it('reads a dispersive film, writes it back, and says what is wrong with one outside the index domain', () => {
    const water = parseSettings('?nFilm=water');
    expect(water).toEqual({ settings: { ...DEFAULT_SETTINGS, nFilm: 'water' }, errors: [], refusals: [] });
    const cauchy = parseSettings('?nFilm=cauchy:1.45,6000');
    expect(cauchy.settings.nFilm).toEqual({ cauchy: [1.45, 6000, 0] });
    expect(settingsToQuery(cauchy.settings)).toBe('nFilm=cauchy%3A1.45%2C6000');
    expect(parseSettings(`?${settingsToQuery({ ...DEFAULT_SETTINGS, nFilm: { cauchy: [1.6, 1e4, -3e8] } })}`).settings.nFilm).toEqual({
      cauchy: [1.6, 1e4, -3e8],
    });
    const bad = parseSettings('?nFilm=cauchy:3.9,20000');
    expect(bad.settings.nFilm).toBe(DEFAULT_SETTINGS.nFilm);
    expect(bad.errors).toHaveLength(1);
    expect(bad.errors[0]).toMatch(
      /^nFilm="cauchy:3.9,20000" ignored: expected .*cauchy:A,B\[,C\].* \(here n at 380 nm is 4.0385, above 4\)$/,
    );
  });

  /** The ranges the README documents, written out here rather than read from params.ts. */
  const NUMERIC: Record<string, [number, number]> = {
    thickness: [0, 20000],
    thicknessRange: [0, 20000],
    speed: [0, 10],
    nFilm: [1, 4],
    nOutside: [1, 4],
    nInside: [1, 4],
    exposure: [0, 100],
    envRotation: [0, 360],
    time: [0, 1_000_000],
    radius: [10, 100],
    surfactant: [1e-8, 1e-6],
    evaporation: [0, 100],
    wind: [0, 2],
    windTurn: [0, 360],
    simSpeed: [0, 10],
    pixelRatio: [0.25, 4],
  };
  /** The whole-number parameters: a fraction is refused as well. */
  const INTEGER: Record<string, [number, number]> = {
    seed: [0, 2_147_483_647],
    grid: [4, 256],
  };
  // The kinds that grow are listed by their registries; the message must name every member.
  const NAMED: Record<string, readonly string[]> = {
    field: FIELDS,
    polarization: ['unpolarized', 'paper', 's', 'p'],
    normalization: ['white', 'paper'],
    space: ['srgb', 'display-p3', 'wide-gamut'],
    mode: MODES,
    sides: ['both', 'front'],
    env: ENVIRONMENTS,
    tonemap: ['auto', 'none', 'agx', 'neutral'],
  };
  const rows: [string, string, string][] = [
    ...Object.entries(NUMERIC).flatMap(([name, [min, max]]) =>
      [...NOT_NUMBERS, ...outsideRange(min, max)].map((v): [string, string, string] => [name, v, `[${min}, ${max}]`]),
    ),
    ...Object.entries(INTEGER).flatMap(([name, [min, max]]) =>
      [...NOT_NUMBERS, ...outsideRange(min, max), String(min + 0.5)].map((v): [string, string, string] => [
        name,
        v,
        `an integer in [${min}, ${max}]`,
      ]),
    ),
    ...Object.entries(NAMED).flatMap(([name, allowed]) =>
      notNames(allowed).map((v): [string, string, string] => [name, v, allowed.join(', ')]),
    ),
    ...[...NOT_NUMBERS.filter((v) => v !== ''), ...outsideRange(4000, 25000), ...notNames(['D65', 'E'])].map(
      (v): [string, string, string] => ['illuminant', v, '[4000, 25000] K'],
    ),
    ...['FL13', 'LED-B6', 'line:379.9', 'line:780.1', 'line:', 'line:abc'].map((v): [string, string, string] => [
      'illuminant',
      v,
      'line:NM with NM in [380, 780] nm',
    ]),
    // An environment: a name, or a uniform colour of three numbers each in [0, 4].
    ...['color:', 'color:1,1', 'color:1,1,1,1', 'color:4.1,1,1', 'color:1,-0.1,1', 'color:1,1,NaN', 'colour:1,1,1', 'forest'].map(
      (v): [string, string, string] => ['env', v, 'color:R,G,B, each in [0, 4]'],
    ),
    // A tint: three numbers, each in [0, 1] (not two, not four, none outside, none not a number).
    ...['', '0.5', '0.5,0.5', '0.5,0.5,0.5,0.5', '1.1,0.5,0.5', '0.5,-0.1,0.5', '0.5,0.5,NaN', '0.5,,0.5', 'red', ABSURDLY_LONG].map(
      (v): [string, string, string] => ['lightTint', v, 'three numbers R,G,B, each in [0, 1]'],
    ),
    ...['animate', 'renew'].flatMap((name) =>
      ['', 'yes', 'true', '2', '-1', ABSURDLY_LONG].map((v): [string, string, string] => [name, v, '0 or 1']),
    ),
    ...[...NOT_NUMBERS, '0.5', '0.5,0.5,0.5', '1.5,0.5', '-0.1,0.5', 'NaN,0.5', 'Infinity,0', '0.5,'].map((v): [string, string, string] => [
      'probe',
      v,
      '[0, 1]',
    ]),
  ];

  /** Bad stacks of films and the rule each breaks (stackText.ts); the value's faulty part is quoted once more in the rule. */
  const LAYERS_ROWS: [string, string, string][] = [
    ['1.5', 'has no :NM'],
    ['unobtainium:100', 'not a medium a film takes'],
    ['9:100', 'n is 9, above 4'],
    ['1.5:-1', 'is not a number in [0, 20000] nm or d'],
    ['1.5:20001', 'is not a number in [0, 20000] nm or d'],
    ['(1.5:1)*0', 'not an integer in [1, 64]'],
    ['(1.5:1)*65', 'not an integer in [1, 64]'],
    ['(1.5:1)*64/1.5:1', 'more than 64 layers after repetition'],
    ['(1.5:1', 'unbalanced parentheses'],
    ['1.5:1)*2', 'unbalanced parentheses'],
    ['1.5:1//1.6:1', 'an empty entry'],
    ['(1.5:1)', 'must be followed by *N'],
    [ABSURDLY_LONG, 'of at most 8192 characters'],
  ].map(([v, rule]) => ['layers', v!, rule!]);

  it('the table of bad values covers every parameter', () => {
    expect(new Set([...rows, ...LAYERS_ROWS].map(([name]) => name))).toEqual(new Set(VIEW_PARAMETERS.map((row) => row.url)));
  });

  it.each(LAYERS_ROWS)('refuses %s=%j, names the parameter and the rule (%s), keeps the default', (name, value, rule) => {
    const { settings, errors } = parseSettings(`?${name}=${encodeURIComponent(value)}`);
    expect(settings).toEqual(DEFAULT_SETTINGS);
    expect(errors).toHaveLength(1);
    expect(errors[0]!.startsWith(`${name}=`)).toBe(true);
    expect(errors[0]).toContain('INDEX:NM entries separated by /');
    expect(errors[0]).toContain(rule);
    expect(errors[0]!.length).toBeLessThan(2 * MAX_ECHOED_CHARS + 240);
  });

  it.each(rows)('refuses %s=%s, names the parameter and %s, keeps the default', (name, value, range) => {
    const { settings, errors } = parseSettings(`?${name}=${encodeURIComponent(value)}`);
    expect(settings).toEqual(DEFAULT_SETTINGS);
    expect(errors).toHaveLength(1);
    expect(errors[0]!.startsWith(`${name}=`)).toBe(true);
    expect(errors[0]).toContain(range);
    // A long value is cut short: the message stays one readable line (a medium's row lists eleven names, the illuminant's its lights, runs shortened).
    expect(errors[0]!.length).toBeLessThan(MAX_ECHOED_CHARS + 260);
  });

  it('keeps the last good value of a repeated parameter, and reports each bad one', () => {
    const { settings, errors } = parseSettings('?thickness=400&thickness=NaN&nFilm=9&nFilm=1.4&exposure=-1');
    expect(settings).toEqual({ ...DEFAULT_SETTINGS, thicknessNm: 400, nFilm: 1.4 });
    expect(errors.map((e) => e.split('=')[0])).toEqual(['thickness', 'nFilm', 'exposure']);
  });

  it("skips unknown names, Object.prototype's included", () => {
    expect(parseSettings('?lesson=3&constructor=1&toString=x&__proto__=y&hasOwnProperty=1')).toEqual({
      settings: DEFAULT_SETTINGS,
      errors: [],
      refusals: [],
    });
  });

  it('builds on a base: a refused value leaves the base value', () => {
    const base = { ...DEFAULT_SETTINGS, thicknessNm: 777 };
    expect(parseSettings('?thickness=-3', base).settings).toEqual(base);
  });
});

describe('the env parameter', () => {
  it('reads a uniform colour and writes it back as it was given', () => {
    const { settings, errors } = parseSettings('?env=color:1,0.2,0.2');
    expect(errors).toEqual([]);
    expect(settings).toEqual({ ...DEFAULT_SETTINGS, env: { color: [1, 0.2, 0.2] } });
    expect(settingsToQuery(settings)).toBe('env=color%3A1%2C0.2%2C0.2');
    expect(parseSettings(`?${settingsToQuery(settings)}`)).toEqual({ settings, errors: [], refusals: [] });
  });

  it('refuses a colour outside its range, says which component and why, and keeps the default', () => {
    const { settings, errors } = parseSettings('?env=color:1,5,0');
    expect(settings).toEqual(DEFAULT_SETTINGS);
    expect(errors).toEqual([
      'env="color:1,5,0" ignored: expected one of sky, none, park, sunset, studio, city, or color:R,G,B, each in [0, 4] (here G is 5, above 4)',
    ]);
  });
});

describe('settingsToQuery', () => {
  it('round-trips through parseSettings, defaults left out', () => {
    const { settings } = parseSettings('?thickness=420&illuminant=7500&lightTint=1,0.5,0.2&mode=exact&animate=0&time=3&nInside=1.2');
    expect(settings.lightTint).toEqual([1, 0.5, 0.2]);
    const query = settingsToQuery(settings);
    expect(parseSettings(`?${query}`)).toEqual({ settings, errors: [], refusals: [] });
    expect(settingsToQuery(DEFAULT_SETTINGS)).toBe('');
  });
});

describe('the layers parameter', () => {
  it('is empty by default (the single film of nFilm), and reads an absent or empty value as that', () => {
    expect(DEFAULT_SETTINGS.layers).toEqual([]);
    for (const query of ['?layers=', '?layers=%20%20'])
      expect(parseSettings(query), query).toEqual({ settings: DEFAULT_SETTINGS, errors: [], refusals: [] });
    expect(settingsToQuery({ ...DEFAULT_SETTINGS, layers: [] })).toBe('');
  });

  it('reads a stack with groups and the field thickness d, and round-trips it through the URL', () => {
    for (const [text, count] of [
      ['(2.35:56.6/1.46:91.1)*8', 16],
      ['1.38:d/(TiO2:50/SiO2:90)*3', 7],
      ['water:d/cauchy:1.45,6000:120/complex:0.2,3.4:10', 3],
      [Array.from({ length: 64 }, (_, i) => `cauchy:1.45,${i * 97 + 0.123456789},-1.5e7:${i * 311.11}`).join('/'), 64],
    ] as const) {
      const read = parseSettings(`?layers=${encodeURIComponent(text)}&nInside=Au`);
      expect(read.errors, text).toEqual([]);
      expect(read.settings.layers, text).toHaveLength(count);
      const query = settingsToQuery(read.settings);
      expect(parseSettings(`?${query}`), text).toEqual({ ...read, refusals: [] });
    }
    expect(parseSettings('?layers=1.38:d/(TiO2:50/SiO2:90)*3').settings.layers.slice(0, 3)).toEqual([
      { n: 1.38, thicknessNm: 'd' },
      { n: 'TiO2', thicknessNm: 50 },
      { n: 'SiO2', thicknessNm: 90 },
    ]);
  });

  it('keeps the last good stack of a repeated parameter, and reports the bad one', () => {
    const { settings, errors } = parseSettings('?layers=1.5:100&layers=(1.5:1');
    expect(settings.layers).toEqual([{ n: 1.5, thicknessNm: 100 }]);
    expect(errors).toHaveLength(1);
    expect(errors[0]).toMatch(/^layers="\(1\.5:1" ignored: .*unbalanced parentheses/);
  });
});

describe('the probe parameter', () => {
  it('reads x,y fractions of the view and writes them back', () => {
    const { settings, errors } = parseSettings('?probe=0.25,0.75');
    expect(errors).toEqual([]);
    expect(settings.probe).toEqual([0.25, 0.75]);
    expect(settingsToQuery(settings)).toBe('probe=0.25%2C0.75');
  });
});
