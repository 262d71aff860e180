import { describe, expect, it } from 'vitest';
import { DEFAULT_SETTINGS } from '../../src/render/filmSettings.ts';
import { MAX_VALUE_LENGTH, parseSettings, settingsToQuery } from '../../src/scene/params.ts';

describe('URL parameters', () => {
  it('reads every documented parameter', () => {
    const { settings, errors } = parseSettings(
      '?thickness=420&thicknessRange=300&speed=2&field=drainage&nFilm=1.4&nOutside=1.1&nInside=1.2&illuminant=7500' +
        '&polarization=s&normalization=paper&space=display-p3&mode=exact&sides=front&env=none&exposure=1.5&animate=0&time=12.5',
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
      env: 'none',
      exposure: 1.5,
      animate: false,
      timeSeconds: 12.5,
    });
  });

  const bad: [string, string, RegExp][] = [
    ['thickness', 'abc', /\[0, 20000\] nm/],
    ['thickness', '', /\[0, 20000\]/],
    ['thickness', 'NaN', /\[0, 20000\]/],
    ['thickness', 'Infinity', /\[0, 20000\]/],
    ['thickness', '-5', /\[0, 20000\]/],
    ['nFilm', '0.9', /\[1, 4\]/],
    ['nInside', '4.5', /\[1, 4\]/],
    ['illuminant', '3000', /4000, 25000/],
    ['illuminant', 'D50', /D55, D65, D93/],
    ['space', 'rec2020', /srgb, display-p3, wide-gamut/],
    ['mode', 'fast', /exact, table/],
    ['field', 'noise', /uniform, drainage, swirl/],
    ['animate', 'yes', /0 or 1/],
    ['exposure', '1'.repeat(MAX_VALUE_LENGTH + 1), /longer than/],
  ];
  it.each(bad)('refuses %s=%s, names the range, and keeps the default', (name, value, range) => {
    const { settings, errors } = parseSettings(`?${name}=${encodeURIComponent(value)}`);
    expect(settings).toEqual(DEFAULT_SETTINGS);
    expect(errors).toHaveLength(1);
    expect(errors[0]).toContain(name);
    expect(errors[0]).toMatch(range);
  });
});

describe('settingsToQuery', () => {
  it('round-trips through parseSettings, defaults left out', () => {
    const { settings } = parseSettings('?thickness=420&illuminant=7500&mode=exact&animate=0&time=3&nInside=1.2');
    const query = settingsToQuery(settings);
    expect(parseSettings(`?${query}`)).toEqual({ settings, errors: [] });
    expect(settingsToQuery(DEFAULT_SETTINGS)).toBe('');
  });
});

describe('the probe parameter', () => {
  it('reads x,y fractions of the view and writes them back', () => {
    const { settings, errors } = parseSettings('?probe=0.25,0.75');
    expect(errors).toEqual([]);
    expect(settings.probe).toEqual([0.25, 0.75]);
    expect(settingsToQuery(settings)).toBe('probe=0.25%2C0.75');
  });

  it.each(['', '0.5', '0.5,0.5,0.5', '1.5,0.5', '-0.1,0.5', 'NaN,0.5', 'Infinity,0', 'a,b', '0.5,'])('refuses %j, naming the range', (raw) => {
    const { settings, errors } = parseSettings(`?probe=${encodeURIComponent(raw)}`);
    expect(settings.probe).toEqual([0.5, 0.5]);
    expect(errors).toHaveLength(1);
    expect(errors[0]).toContain('probe');
    expect(errors[0]).toContain('[0, 1]');
  });
});
