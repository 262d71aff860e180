/** Where a flag's description starts in every tool's usage. */
export const DESCRIPTION_COLUMN = 24;

/** One line per flag: `--flag`, its label, what it accepts and its default (the colour tool's case flags, render's view options, film's flow parameters). */
export const optionLines = (options: readonly { flag: string; label: string; expected: string; defaultText: string }[]): string =>
  options
    .map(
      ({ flag, label, expected, defaultText }) =>
        `  --${flag}`.padEnd(DESCRIPTION_COLUMN) + `${label}: ${expected}${defaultText ? ` (${defaultText})` : ''}`,
    )
    .join('\n');
