import { VIEW_PARAMETERS } from '../settings/viewParameters.ts';
import { DEMO_VIEW_SETTINGS } from '../settings/demoView.ts';
import { MAX_CASES, MAX_CASES_NESTING_DEPTH } from './parseJsonArray.ts';
import { PICTURE_OPTIONS, VIEW_FIELDS, expectedOf } from './renderOptions.ts';
import { FRAME_MS, FRAME_MS_EXPECTED, TIME_LAPSE_EXPECTED } from './timeLapseOptions.ts';
import { optionLines } from './optionLines.ts';

/** The view's options, one per schema row: its flag (the URL name in kebab case), label, range and the demo's default (demoView.ts). */
const viewLines = optionLines(VIEW_PARAMETERS.map((row) => ({ ...row, defaultText: row.write(DEMO_VIEW_SETTINGS) })));
const pictureLines = optionLines(
  Object.entries(PICTURE_OPTIONS).map(([name, o]) => ({
    flag: name,
    label: name,
    expected: expectedOf(name),
    defaultText: String(o.fallback),
  })),
);

/** The fields of a view that are the picture's, not the schema's. */
const PICTURE_FIELDS = VIEW_FIELDS.filter((name) => !VIEW_PARAMETERS.some((row) => row.url === name)).join(', ');

/** `--help`: how to call the render command. */
export const RENDER_USAGE = `A picture of the demo (the bubble as index.html shows it) as a PNG, rendered in headless Chromium.

Usage: npm run --silent render -- [view options] --out FILE.png [--width W --height H] [--scale S] [--plots]

View options: the demo's URL parameters (the same ranges and defaults; each name in kebab case,
--thickness-range for thicknessRange):
${viewLines}

The picture:
  --out FILE.png        the file to write (replaced atomically)
${pictureLines}
  --plots               draw the plots at the probe (the lil-gui panel is never drawn)

Many views, one browser:
  --cases FILE.json     a JSON array (at most ${MAX_CASES}) of objects { "out", ... } with some of the
                        fields ${PICTURE_FIELDS} and the view options' URL names
                        (thicknessRange; values as in the URL, as JSON numbers or text; plots true
                        or false). The other options given apply to every view. Nested at most ${MAX_CASES_NESTING_DEPTH} levels deep.

A bubble's life, one animation (not with --time or --cases):
  --time-lapse START:END:STEP
                        one frame per film time START, START + STEP, … up to END (seconds), each
                        the view frozen at that time (animate 0), written as an animated PNG
                        (--out FILE.png) or an animated WebP (--out FILE.webp). Expected:
                        ${TIME_LAPSE_EXPECTED}
  --frame-ms MS         how long each frame is shown: ${FRAME_MS_EXPECTED} (${FRAME_MS.fallback})
                        Output: one JSON line { out, format, frames, frameMs, width, height, ms }.

Progress: the views (or a time-lapse's frames) done of the total and the time left, on stderr while
it runs, one line redrawn on a terminal; elsewhere only with
  --progress            one line per view or frame

Output: one JSON line per view, in input order: { out, width, height, ms } (the PNG's pixels; ms to render and write it).
Bad input: exit status 2, one line on stderr naming the option, nothing written.
No Chromium: exit status 3, one line on how to get one. A failed render: exit status 1.
`;
