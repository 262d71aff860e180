import { createFilmSimulation, advanceFilm, filmSeconds } from '../physics/filmDynamics/filmSimulation.ts';
import { PROFILE_THETA_DEG, sphereIntegral, thicknessProfileNm, thicknessRangeNm } from '../physics/filmDynamics/filmMeasures.ts';
import {
  FLOW_PARAMETERS,
  type FlowParameterRow,
  acceptsFlowValue,
  expectedFlowValue,
  type FlowParameterKey,
} from '../physics/filmDynamics/flowParameters.ts';
import { ParameterError, expectedNumber, isInDomain, type NumberDomain, rejectValue } from '../input/validate.ts';
import { FILM_PARAMETERS } from '../settings/filmParameters.ts';
import { optionLines } from './optionLines.ts';
import { parseStrictNumber } from './parseStrictNumber.ts';
import { type ProgressStream, progressReporter } from './progress.ts';
import { readFlags, urlSpellings } from './readFlags.ts';

/** How long a run may simulate (s): film time, not wall time; a second at the default grid takes minutes. */
export const FILM_SECONDS_DOMAIN: NumberDomain = { min: 0, max: 600, unit: 's' };

/** The flow parameters the settings schema has no row for: the film command's own flag and label. */
const OWN_FLAGS: Partial<Record<FlowParameterKey, { readonly flag: string; readonly label: string }>> = {
  ruptureThicknessNm: { flag: 'rupture-thickness', label: 'rupture thickness (nm)' },
  rimSpeedFactor: { flag: 'rim-speed-factor', label: 'rim speed / Taylor–Culick' },
};

/** A flow parameter's flag: its flag and label from the schema's row of the same key, else OWN_FLAGS; its range and default the simulation's. */
interface ParameterFlag {
  readonly flag: string;
  readonly label: string;
  readonly row: FlowParameterRow;
}

/**
 * The film command's flow parameters: each but the simulation speed (the page's film seconds per
 * second; the command's time is film time).
 */
export const PARAMETER_FLAGS: readonly ParameterFlag[] = FLOW_PARAMETERS.filter((row) => row.key !== 'simSpeed').map((row) => {
  const names = FILM_PARAMETERS.find((r) => r.key === row.key) ?? OWN_FLAGS[row.key];
  if (!names) throw new Error(`film: the flow parameter ${row.key} has no flag`);
  return { flag: names.flag, label: names.label, row };
});

const VALUE_FLAGS = [...PARAMETER_FLAGS.map((p) => p.flag), 'seconds'];
const FLAG_SPEC = {
  values: VALUE_FLAGS,
  switches: ['json', 'progress', 'help'],
  // Spellings with the unit that the schema's flags leave out.
  spellings: new Map([
    ...urlSpellings(VALUE_FLAGS),
    ['radius-mm', 'radius'],
    ['thickness-nm', 'thickness'],
    ['rupture-nm', 'rupture-thickness'],
  ]),
};

/** `--help`: how to call the film command. */
export const FILM_USAGE = `The flowing soap film of a bubble, simulated for T seconds of film time, as one JSON object:
  seconds, steps, thetaDeg (0, 5, …, 180 from the top), thicknessNm (azimuthal mean at each θ),
  minNm, maxNm, volumeRelativeChange, surfactantRelativeChange, ruptured.

Usage: npm run --silent film -- [options] --seconds T [--json]

  --seconds T           film time to simulate: ${expectedNumber(FILM_SECONDS_DOMAIN)} (required)
${optionLines(PARAMETER_FLAGS.map(({ flag, label, row }) => ({ flag, label, expected: expectedFlowValue(row), defaultText: String(row.defaultValue) })))}
  --json                JSON output (the only format)
  --progress            film seconds done and the time left on stderr where it is not a terminal
                        (on a terminal always, one line redrawn)
  --help                this text

Bad input: exit status 2, one line on stderr naming the option, nothing on stdout.
`;

export interface FilmCommandResult {
  readonly stdout: string;
  readonly stderr: string;
  /** 0 done, 1 an internal error, 2 bad input. */
  readonly exitCode: 0 | 1 | 2;
}

/**
 * `film`, apart from the process: arguments in, output text and exit status out; progress, while
 * the film is simulated, on `progress` (stderr). Every option is checked before anything is
 * computed, so bad input leaves stdout empty (exit 2, one line naming the option and its range on stderr).
 */
export function runFilmCommand(argv: readonly string[], progress: ProgressStream = { write: () => true }): FilmCommandResult {
  try {
    const { values, switches } = readFlags(argv, FLAG_SPEC);
    if (switches.has('help')) return { stdout: FILM_USAGE, stderr: '', exitCode: 0 };
    const given: Partial<Record<FlowParameterKey, number>> = {};
    for (const { flag, row } of PARAMETER_FLAGS) {
      const text = values.get(flag);
      if (text === undefined) continue;
      const value = parseStrictNumber(`--${flag}`, text, expectedFlowValue(row));
      if (!acceptsFlowValue(row, value)) rejectValue(`--${flag}`, value, expectedFlowValue(row));
      given[row.key] = value;
    }
    const secondsText = values.get('seconds');
    if (secondsText === undefined) throw new ParameterError('--seconds', '--seconds: missing; expected the film time to simulate');
    const seconds = parseStrictNumber('--seconds', secondsText, expectedNumber(FILM_SECONDS_DOMAIN));
    if (!isInDomain(seconds, FILM_SECONDS_DOMAIN)) rejectValue('--seconds', seconds, expectedNumber(FILM_SECONDS_DOMAIN));
    const reporter = progressReporter(progress, {
      tool: 'film',
      unit: FILM_SECONDS,
      total: seconds,
      asked: switches.has('progress'),
      everyMs: 1000,
    });
    return { stdout: `${JSON.stringify(simulate(given, seconds, reporter.report))}\n`, stderr: '', exitCode: 0 };
  } catch (error) {
    if (error instanceof ParameterError) return { stdout: '', stderr: errorLine(error.message), exitCode: 2 };
    const message = error instanceof Error ? error.message : String(error);
    return { stdout: '', stderr: errorLine(`internal error: ${message}`), exitCode: 1 };
  }
}

const errorLine = (message: string): string => `film: ${message.replace(/[\r\n]+/g, ' ')}\n`;

/** Progress in film seconds, to the hundredth. */
const FILM_SECONDS = { name: 'film seconds', digits: 2 };

/** The film after `seconds` of film time, `progress` told the film seconds done after each step. */
function simulate(given: Partial<Record<FlowParameterKey, number>>, seconds: number, progress: (filmSeconds: number) => void) {
  const sim = createFilmSimulation(given);
  const volume0 = sphereIntegral(sim, sim.state.eta);
  const surfactant0 = sphereIntegral(sim, sim.state.gamma);
  progress(0);
  advanceFilm(sim, seconds, () => progress(filmSeconds(sim)));
  progress(seconds);
  const { minNm, maxNm } = thicknessRangeNm(sim);
  return {
    seconds: filmSeconds(sim),
    steps: sim.state.steps,
    thetaDeg: PROFILE_THETA_DEG,
    thicknessNm: thicknessProfileNm(sim),
    minNm,
    maxNm,
    volumeRelativeChange: sphereIntegral(sim, sim.state.eta) / volume0 - 1,
    surfactantRelativeChange: sphereIntegral(sim, sim.state.gamma) / surfactant0 - 1,
    ruptured: sim.state.holes.length > 0,
  };
}
