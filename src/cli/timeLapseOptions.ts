/**
 * The time-lapse's own options (`--time-lapse START:END:STEP`, `--frame-ms`) and the animation
 * formats `--out` may name; the view of each frame is the render command's (renderOptions.ts).
 */
import { type NumberDomain, ParameterError, rejectValue } from '../input/validate.ts';
import { parameterNamed } from '../settings/settingsQuery.ts';
import { parseStrictNumber } from './parseStrictNumber.ts';
import { parseColonRange } from './tableValues.ts';

/** More frames than this is a typo (a step of 0.01 s instead of 1 s), not a film: 600 frames is a minute at 10 frames a second. */
export const MAX_TIME_LAPSE_FRAMES = 600;

/**
 * The frames' pixels a time-lapse may hold (device pixels, all frames): 2^28, 1 GiB as RGBA, which
 * the encoders hold at once; the default 640 × 480 window allows all MAX_TIME_LAPSE_FRAMES.
 */
export const MAX_TIME_LAPSE_PIXELS = 2 ** 28;

/**
 * How long each frame of a time-lapse is shown, in ms: whole milliseconds, as APNG's delay_num/1000
 * (16 bits) and WebP's frame duration store it; 20 ms is 50 frames a second, faster than most screens.
 */
export const FRAME_MS = { min: 20, max: 10_000, unit: 'ms', fallback: 100 } as const;

/** The animation formats, by the ending of `--out`. */
export const TIME_LAPSE_FORMATS = { '.png': 'apng', '.webp': 'webp' } as const;
export type TimeLapseFormat = (typeof TIME_LAPSE_FORMATS)[keyof typeof TIME_LAPSE_FORMATS];

/** The film times a view may freeze at: the `time` parameter's domain, as its schema row states it. */
const TIME_DOMAIN: NumberDomain = (() => {
  const { values, unit } = parameterNamed('time')!.expects;
  return { min: Number(values!.min), max: Number(values!.max), unit: unit ?? '' };
})();

/** What `--time-lapse START:END:STEP` accepts, as its refusals say. */
export const TIME_LAPSE_EXPECTED =
  `START:END:STEP in seconds of film time, START ≤ END in [${TIME_DOMAIN.min}, ${TIME_DOMAIN.max}], STEP > 0, ` +
  `at most ${MAX_TIME_LAPSE_FRAMES} frames, e.g. 0:30:1`;

export const FRAME_MS_EXPECTED = `a whole number in [${FRAME_MS.min}, ${FRAME_MS.max}] ms`;

/**
 * The film times (s) of `--time-lapse START:END:STEP`: START, START + STEP, …, up to END where a
 * step lands on it (see tableValues.ts `evenlySpaced`), each inside the `time` parameter's domain;
 * more than MAX_TIME_LAPSE_FRAMES is refused. Every refusal is a ParameterError naming `--time-lapse`.
 */
export function timeLapseTimes(text: string): number[] {
  let times: number[];
  try {
    times = parseColonRange('--time-lapse', text, TIME_DOMAIN);
  } catch (error) {
    if (!(error instanceof ParameterError)) throw error;
    // The range's own words name one part (the end, the step); the whole rule is what the user needs.
    return rejectValue('--time-lapse', text, `${TIME_LAPSE_EXPECTED} (${error.message.replace(/^--time-lapse: /, '')})`);
  }
  if (times.length > MAX_TIME_LAPSE_FRAMES) {
    return rejectValue('--time-lapse', text, `${TIME_LAPSE_EXPECTED} (here ${times.length} frames)`);
  }
  return times;
}

/** A ParameterError naming `--time-lapse` if `frames` frames of `devicePixels` each are more than MAX_TIME_LAPSE_PIXELS. */
export function checkTimeLapseSize(frames: number, devicePixels: number): void {
  if (frames * devicePixels <= MAX_TIME_LAPSE_PIXELS) return;
  throw new ParameterError(
    '--time-lapse',
    `--time-lapse: ${frames} frames of ${devicePixels} pixels are not allowed; expected at most ${MAX_TIME_LAPSE_PIXELS} pixels in all (fewer frames, or a smaller --width, --height or --scale)`,
  );
}

/** `--frame-ms`: how long each frame is shown (FRAME_MS.fallback when not given). */
export function frameMs(text: string | undefined): number {
  if (text === undefined) return FRAME_MS.fallback;
  const ms = parseStrictNumber('--frame-ms', text, FRAME_MS_EXPECTED);
  return Number.isInteger(ms) && ms >= FRAME_MS.min && ms <= FRAME_MS.max ? ms : rejectValue('--frame-ms', text, FRAME_MS_EXPECTED);
}

/** The animation format `out` asks for by its ending (case-insensitive), or a ParameterError naming `--out`. */
export function timeLapseFormat(out: string): TimeLapseFormat {
  const ending = Object.keys(TIME_LAPSE_FORMATS).find((e) => out.toLowerCase().endsWith(e)) as keyof typeof TIME_LAPSE_FORMATS | undefined;
  if (ending === undefined || out.length === ending.length) {
    return rejectValue('--out', out, `with --time-lapse, a file ending in ${Object.keys(TIME_LAPSE_FORMATS).join(' or ')}`);
  }
  return TIME_LAPSE_FORMATS[ending];
}
