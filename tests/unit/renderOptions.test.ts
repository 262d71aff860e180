/**
 * The render command's options (src/cli/renderOptions.ts). The view's options must be the URL's
 * parameters with the URL's refusals, so the URL parser (src/settings/settingsQuery.ts) is the
 * reference: every schema row, given the same texts, accepts and refuses exactly what the URL does.
 * The command renders the demo, so the defaults are the demo's (DEMO_VIEW_SETTINGS), read and written alike.
 */
import { describe, expect, it } from 'vitest';
import { parseSettings, settingsToQuery } from '../../src/settings/settingsQuery.ts';
import { VIEW_PARAMETERS } from '../../src/settings/viewParameters.ts';
import { DEMO_VIEW_SETTINGS } from '../../src/settings/demoView.ts';
import { PICTURE_OPTIONS, type RenderView, parseRenderCases, parseRenderCommandLine } from '../../src/cli/renderOptions.ts';
import { ParameterError } from '../../src/input/validate.ts';
import { FRAME_MS, MAX_TIME_LAPSE_FRAMES, TIME_LAPSE_EXPECTED } from '../../src/cli/timeLapseOptions.ts';
import { NOT_NUMBERS, outsideRange } from './fixtures/badValues.ts';

/** Texts of every kind the schema's rows take, and some no row takes. */
const CANDIDATES = [
  ...NOT_NUMBERS,
  ...outsideRange(0, 1),
  ...['0', '1', '0.5', '2', '550', '1e3', '30000', 'D93', 'D65-table', '6500', '3999', 'uniform', 'front', 'none', 'paper', 's'],
  ...['0.2,0.7', '2,0', '0.5', 'x'.repeat(65), '0.50000000000000000000000000000000000000000000000000000000000001'],
];

/** The command's verdict on one option: the view's URL query, or the error's message. */
function verdict(...args: string[]): { query: string } | { error: string } {
  try {
    const command = parseRenderCommandLine([...args, '--out', 'x.png']);
    if (command.kind !== 'views') throw new Error(`expected one view, got ${command.kind}`);
    return { query: command.views[0]!.query };
  } catch (error) {
    if (!(error instanceof ParameterError)) throw error;
    return { error: error.message };
  }
}

describe('render options: the URL parameters', () => {
  for (const row of VIEW_PARAMETERS) {
    it(`--${row.flag} takes and refuses what ?${row.url}= does`, () => {
      for (const text of [row.defaultText, row.write(DEMO_VIEW_SETTINGS), ...CANDIDATES]) {
        const url = parseSettings(new URLSearchParams([[row.url, text]]).toString(), DEMO_VIEW_SETTINGS);
        const got = verdict(`--${row.flag}`, text);
        if (url.errors.length === 0)
          expect(got, `--${row.flag} ${text.slice(0, 40)}`).toEqual({ query: settingsToQuery(url.settings, DEMO_VIEW_SETTINGS) });
        else {
          expect(got, `--${row.flag} ${text.slice(0, 40)}`).toHaveProperty('error');
          const { error } = got as { error: string };
          // One line naming the option and what it accepts (the URL's own words for the range).
          expect(error.startsWith(`--${row.flag}: `)).toBe(true);
          expect(error).toContain(row.expected);
          expect(error).not.toMatch(/[\r\n]/);
        }
      }
    });
  }

  it("leaves every one of the demo's defaults out of the query, so no options is the demo's default view", () => {
    expect(verdict()).toEqual({ query: '' });
    expect(verdict(...VIEW_PARAMETERS.flatMap((row) => [`--${row.flag}`, row.write(DEMO_VIEW_SETTINGS)]))).toEqual({ query: '' });
    // The schema's own default (the element's swirl in the sky) is not the demo's: the query names it.
    expect(verdict('--field', 'swirl', '--env', 'sky')).toEqual({ query: 'field=swirl&env=sky' });
  });

  it("spells each option as the URL name in kebab case (the query in the schema's order), and refuses the URL's camel case naming the option", () => {
    expect(verdict('--thickness-range', '600', '--n-film', '1.4', '--wind-turn', '30')).toEqual({
      query: 'thicknessRange=600&windTurn=30&nFilm=1.4',
    });
    for (const [old, flag] of [
      ['--thicknessRange', '--thickness-range'],
      ['--nFilm', '--n-film'],
      ['--nOutside', '--n-outside'],
      ['--envRotation', '--env-rotation'],
      ['--simSpeed', '--sim-speed'],
      ['--pixelRatio', '--pixel-ratio'],
    ]) {
      expect(verdict(old!, '1')).toEqual({ error: `${old}: unknown flag; it is spelt ${flag}` });
    }
  });
});

describe('render options: the picture', () => {
  it('defaults to a 640 × 480 window at scale 1 without plots', () => {
    const command = parseRenderCommandLine(['--out', 'a.png']);
    expect(command).toEqual({
      kind: 'views',
      views: [{ out: 'a.png', widthPx: 640, heightPx: 480, scale: 1, plots: false, query: '' } satisfies RenderView],
      progress: false,
    });
    expect(parseRenderCommandLine(['--out', 'a.png', '--progress'])).toMatchObject({ kind: 'views', progress: true });
  });

  it('reads --width, --height, --scale and --plots', () => {
    const command = parseRenderCommandLine(['--out', 'a.png', '--width', '16', '--height', '4096', '--scale', '1.5', '--plots']);
    expect(command.kind === 'views' && command.views[0]).toMatchObject({ widthPx: 16, heightPx: 4096, scale: 1.5, plots: true });
  });

  const refusals: [string[], string][] = [
    [['--width', '15'], '--width: "15" is not allowed; expected a whole number in [16, 4096] CSS px'],
    [['--width', '4097'], '--width: "4097" is not allowed; expected a whole number in [16, 4096] CSS px'],
    [['--height', '100.5'], '--height: "100.5" is not allowed; expected a whole number in [16, 4096] CSS px'],
    [['--scale', '2.01'], '--scale: "2.01" is not allowed; expected a number in [1, 2]'],
    [['--scale', 'NaN'], '--scale: "NaN" is not allowed; expected a number in [1, 2]'],
    [['--plots=1'], '--plots: "1" is not allowed; expected no value'],
    [['--bogus', '1'], '"--bogus": unknown flag; expected one of --out, --width'],
    [['--progress=1'], '--progress: "1" is not allowed; expected no value'],
    [['--thickness', '1', '--thickness', '2'], '--thickness: given more than once; expected it at most once'],
    [['stray'], 'argument: "stray" is not allowed; expected only flags'],
  ];
  for (const [args, message] of refusals) {
    it(`refuses ${args.join(' ')}`, () => {
      expect(() => parseRenderCommandLine([...args, '--out', 'a.png'])).toThrow(message);
    });
  }

  it('refuses a missing or empty --out', () => {
    expect(() => parseRenderCommandLine([])).toThrow('--out: no value is not allowed; expected the path of the PNG file to write');
    expect(() => parseRenderCommandLine(['--out', ''])).toThrow('--out: "" is not allowed; expected the path of the PNG file to write');
  });

  it('the picture options are not view parameters', () => {
    const urls = VIEW_PARAMETERS.map((row) => row.url);
    for (const name of ['out', 'plots', 'cases', 'help', ...Object.keys(PICTURE_OPTIONS)]) expect(urls).not.toContain(name);
  });
});

describe('render options: --cases', () => {
  const defaults = (...args: string[]) => {
    const command = parseRenderCommandLine(['--cases', 'views.json', ...args]);
    if (command.kind !== 'casesFile') throw new Error(`expected a cases file, got ${command.kind}`);
    return command.defaults;
  };
  const cases = (views: unknown, ...args: string[]) => parseRenderCases(JSON.stringify(views), 'views.json', defaults(...args));

  it('reads each view over the command line options, in order', () => {
    const views = cases(
      [
        { out: 'a.png', thickness: 450, field: 'uniform', animate: 0 },
        { out: 'b.png', illuminant: 'D93', width: 320, plots: true, probe: '0.25,0.5' },
      ],
      '--width',
      '200',
      '--env',
      'sky',
    );
    expect(views).toEqual([
      { out: 'a.png', widthPx: 200, heightPx: 480, scale: 1, plots: false, query: 'field=uniform&thickness=450&env=sky&animate=0' },
      { out: 'b.png', widthPx: 320, heightPx: 480, scale: 1, plots: true, query: 'illuminant=D93&env=sky&probe=0.25%2C0.5' },
    ]);
  });

  it('reads a medium as the URL writes it or as { "complex": [n, k] }, and refuses a gain medium naming the field', () => {
    const views = cases([
      { out: 'a.png', nInside: { complex: [2.6, 3.4] } },
      { out: 'b.png', nInside: 'Au', nFilm: 'TiO2' },
    ]);
    expect(views.map((v) => v.query)).toEqual(['nInside=complex%3A2.6%2C3.4', 'nFilm=TiO2&nInside=Au']);
    expect(() => cases([{ out: 'a.png', nInside: { complex: [2.6, -1] } }])).toThrow(
      /^case at index 0: nInside: .* \(here k is -1, below 0/,
    );
  });

  const refusals: [unknown, string][] = [
    [
      [{ out: 'a.png' }, { out: 'b.png', thickness: 30000 }],
      'case at index 1: thickness: 30000 is not allowed; expected a number in [0, 20000] nm',
    ],
    [[{ out: 'a.png', animate: true }], 'case at index 0: animate: true is not allowed; expected 0 or 1, as a string or a number'],
    [[{ out: 'a.png', plots: 1 }], 'case at index 0: plots: 1 is not allowed; expected true or false'],
    [[{ thickness: 400 }], 'case at index 0: out: no value is not allowed; expected the path of the PNG file to write'],
    [
      [{ out: 'a.png', colour: 'red' }],
      'case at index 0: "colour": unknown field; expected one of out, width, height, scale, plots, field',
    ],
    [
      [{ out: 'a.png' }, { out: 'a.png' }],
      'case at index 1: out: "a.png" is not allowed; expected a file no other view writes (case at index 0 does)',
    ],
    [['a.png'], 'case at index 0: case: "a.png" is not allowed; expected an object { "out", ... }'],
    [{ out: 'a.png' }, '--cases: {"out":"a.png"} is not allowed; expected a JSON array of views'],
  ];
  for (const [views, message] of refusals) {
    it(`refuses ${JSON.stringify(views)}`, () => {
      expect(() => cases(views)).toThrow(message);
    });
  }

  it('refuses --out beside --cases, and checks the shared options before the file is read', () => {
    expect(() => parseRenderCommandLine(['--cases', 'v.json', '--out', 'a.png'])).toThrow('--out: not allowed with --cases');
    expect(() => parseRenderCommandLine(['--cases', 'v.json', '--mode', 'fast'])).toThrow('--mode: "fast" is not allowed');
    // A shared option is named as the command line spells it; the same field in a case, as the case does.
    expect(() => cases([{ out: 'a.png' }], '--thickness-range', '-1')).toThrow('--thickness-range: "-1" is not allowed');
    expect(() => cases([{ out: 'a.png', thicknessRange: -1 }])).toThrow('case at index 0: thicknessRange: -1 is not allowed');
  });
});

describe('render options: --time-lapse', () => {
  const lapse = (...args: string[]) => {
    const command = parseRenderCommandLine(args);
    if (command.kind !== 'timeLapse') throw new Error(`expected a time-lapse, got ${command.kind}`);
    return command;
  };

  it('one frame per time from START to END in steps of STEP, each the view frozen at its time', () => {
    const command = lapse(
      '--field',
      'flow',
      '--grid',
      '16',
      '--seed',
      '3',
      '--width',
      '160',
      '--time-lapse',
      '0:0.3:0.1',
      '--out',
      'life.png',
    );
    expect(command.timesS).toEqual([0, 0.1, 0.2, 0.3]);
    expect(command).toMatchObject({ out: 'life.png', format: 'apng', frameMs: FRAME_MS.fallback });
    // Each frame's query is the one a still at that time has: the URL's own writer, animate 0.
    command.frames.forEach((frame, i) => {
      const stillAt = parseRenderCommandLine([
        ...['--field', 'flow', '--grid', '16', '--seed', '3', '--width', '160', '--animate', '0'],
        ...['--time', String(command.timesS[i]), '--out', 'life.png'],
      ]);
      expect(stillAt.kind === 'views' && stillAt.views[0]).toEqual(frame);
    });
    expect(new Set(command.frames.map((f) => f.query)).size).toBe(4);
  });

  it('takes .webp for an animated WebP, --frame-ms, and an END the step does not land on', () => {
    const command = lapse('--time-lapse', '1:2.5:1', '--frame-ms', '250', '--out', 'life.WEBP');
    expect(command).toMatchObject({ format: 'webp', frameMs: 250, timesS: [1, 2] });
    expect(lapse('--time-lapse', '4:4:1', '--out', 'a.png').timesS).toEqual([4]);
    expect(lapse('--time-lapse', `0:${MAX_TIME_LAPSE_FRAMES - 1}:1`, '--out', 'a.png').frames).toHaveLength(MAX_TIME_LAPSE_FRAMES);
  });

  const rule = TIME_LAPSE_EXPECTED;
  const refusals: [string[], string][] = [
    [['--time-lapse', '5:1:1'], `--time-lapse: "5:1:1" is not allowed; expected ${rule} (1 is not allowed; expected a number ≥ the start`],
    [['--time-lapse', '0:1:0'], `--time-lapse: "0:1:0" is not allowed; expected ${rule} (0 is not allowed; expected a number > 0)`],
    [['--time-lapse', '0:1:-1'], `--time-lapse: "0:1:-1" is not allowed; expected ${rule}`],
    [['--time-lapse', `0:${MAX_TIME_LAPSE_FRAMES}:1`], `expected ${rule} (here ${MAX_TIME_LAPSE_FRAMES + 1} frames)`],
    [['--time-lapse', '0:3:0.00001'], `--time-lapse: "0:3:0.00001" is not allowed; expected ${rule}`],
    [['--time-lapse', 'a:b:c'], `--time-lapse: "a:b:c" is not allowed; expected ${rule}`],
    [['--time-lapse', '0:30'], `--time-lapse: "0:30" is not allowed; expected ${rule}`],
    [['--time-lapse', '-1:3:1'], `--time-lapse: "-1:3:1" is not allowed; expected ${rule}`],
    [['--time-lapse', '0:2e6:1e5'], `--time-lapse: "0:2e6:1e5" is not allowed; expected ${rule}`],
    [['--time-lapse', ''], `--time-lapse: "" is not allowed; expected ${rule}`],
    [
      ['--time-lapse', '0:599:1', '--width', '1000', '--height', '1000'],
      '--time-lapse: 600 frames of 1000000 pixels are not allowed; expected at most 268435456 pixels in all',
    ],
    [['--time-lapse', '0:3:1', '--time', '2'], '--time-lapse: not allowed with --time (each frame is frozen at its own time)'],
    [['--time-lapse', '0:3:1', '--animate', '1'], '--time-lapse: not allowed with --animate 1'],
    [['--frame-ms', '50'], '--frame-ms: not allowed without --time-lapse'],
    [['--time-lapse', '0:3:1', '--frame-ms', '19'], '--frame-ms: "19" is not allowed; expected a whole number in [20, 10000] ms'],
    [['--time-lapse', '0:3:1', '--frame-ms', '100.5'], '--frame-ms: "100.5" is not allowed; expected a whole number in [20, 10000] ms'],
  ];
  for (const [args, message] of refusals) {
    it(`refuses ${args.join(' ')}`, () => {
      expect(() => parseRenderCommandLine([...args, '--out', 'a.png'])).toThrow(message);
    });
  }

  it('refuses an --out that is not .png or .webp, and --time-lapse with --cases', () => {
    expect(() => lapse('--time-lapse', '0:3:1', '--out', 'life.gif')).toThrow(
      '--out: "life.gif" is not allowed; expected with --time-lapse, a file ending in .png or .webp',
    );
    expect(() => lapse('--time-lapse', '0:3:1', '--out', '.png')).toThrow('--out: ".png" is not allowed');
    expect(() => parseRenderCommandLine(['--cases', 'v.json', '--time-lapse', '0:3:1'])).toThrow('--time-lapse: not allowed with --cases');
  });
});
