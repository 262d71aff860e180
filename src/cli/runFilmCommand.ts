import { createFilmSimulation, advanceFilm, filmSeconds } from '../physics/flow/filmSimulation.ts';
import { PROFILE_THETA_DEG, sphereIntegral, thicknessProfileNm, thicknessRangeNm } from '../physics/flow/filmMeasures.ts';
import { FLOW_PARAMETERS, acceptsFlowValue, expectedFlowValue, type FlowParameterKey } from '../physics/flow/flowParameters.ts';
import { ParameterError, expectedNumber, isInDomain, type NumberDomain, rejectValue } from '../input/validate.ts';
import { parseStrictNumber } from './parseStrictNumber.ts';
import { readFlags } from './readFlags.ts';

/** How long a run may simulate (s): film time, not wall time; a second at the default grid takes minutes. */
export const FILM_SECONDS_DOMAIN: NumberDomain = { min: 0, max: 600, unit: 's' };

const PARAMETER_FLAGS = FLOW_PARAMETERS.filter((r) => r.flag !== null);
const VALUE_FLAGS = [...PARAMETER_FLAGS.map((r) => r.flag!), 'seconds'];

export const FILM_USAGE = [
  'npm run --silent film -- [options] --seconds T [--json]',
  'Simulates the soap film flowing on a bubble for T seconds of film time and prints one JSON object:',
  '  seconds, steps, thetaDeg (0, 5, …, 180 from the top), thicknessNm (azimuthal mean at each θ),',
  '  minNm, maxNm, volumeRelativeChange, surfactantRelativeChange, ruptured.',
  'Options:',
  `  --seconds T  film time to simulate, ${expectedNumber(FILM_SECONDS_DOMAIN)} (required)`,
  ...PARAMETER_FLAGS.map((r) => `  --${r.flag}  ${r.label}: ${expectedFlowValue(r)}, default ${r.defaultValue}`),
  '  --json  JSON output (the only format)',
  '  --help  this text',
  '',
].join('\n');

export interface FilmCommandResult {
  readonly stdout: string;
  readonly stderr: string;
  /** 0 done, 1 an internal error, 2 bad input. */
  readonly exitCode: 0 | 1 | 2;
}

/**
 * `film`, apart from the process: arguments in, output text and exit status out. Every option is
 * checked before anything is computed, so bad input leaves stdout empty (exit 2, one line naming
 * the option and its range on stderr).
 */
export function runFilmCommand(argv: readonly string[]): FilmCommandResult {
  try {
    const { values, switches } = readFlags(argv, VALUE_FLAGS, ['json', 'help']);
    if (switches.has('help')) return { stdout: FILM_USAGE, stderr: '', exitCode: 0 };
    const given: Partial<Record<FlowParameterKey, number>> = {};
    for (const r of PARAMETER_FLAGS) {
      const text = values.get(r.flag!);
      if (text === undefined) continue;
      const value = parseStrictNumber(`--${r.flag}`, text, expectedFlowValue(r));
      if (!acceptsFlowValue(r, value)) rejectValue(`--${r.flag}`, value, expectedFlowValue(r));
      given[r.key] = value;
    }
    const secondsText = values.get('seconds');
    if (secondsText === undefined) throw new ParameterError('--seconds', '--seconds: missing; expected the film time to simulate');
    const seconds = parseStrictNumber('--seconds', secondsText, expectedNumber(FILM_SECONDS_DOMAIN));
    if (!isInDomain(seconds, FILM_SECONDS_DOMAIN)) rejectValue('--seconds', seconds, expectedNumber(FILM_SECONDS_DOMAIN));
    return { stdout: `${JSON.stringify(simulate(given, seconds))}\n`, stderr: '', exitCode: 0 };
  } catch (error) {
    if (error instanceof ParameterError) return { stdout: '', stderr: errorLine(error.message), exitCode: 2 };
    const message = error instanceof Error ? error.message : String(error);
    return { stdout: '', stderr: errorLine(`internal error: ${message}`), exitCode: 1 };
  }
}

const errorLine = (message: string): string => `film: ${message.replace(/[\r\n]+/g, ' ')}\n`;

function simulate(given: Partial<Record<FlowParameterKey, number>>, seconds: number) {
  const sim = createFilmSimulation(given);
  const volume0 = sphereIntegral(sim, sim.state.eta);
  const surfactant0 = sphereIntegral(sim, sim.state.gamma);
  advanceFilm(sim, seconds);
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
