import { ParameterError } from '../physics/validate.ts';
import type { ColorCase } from './colorCase.ts';
import { computeCaseColor } from './computeCaseColor.ts';
import { jsonLines, tableCsv, tableRow } from './formatOutput.ts';
import { type Command, parseCommandLine } from './parseCommandLine.ts';
import { parseCasesJson } from './parseCasesJson.ts';
import { USAGE } from './usage.ts';

export interface CommandResult {
  readonly stdout: string;
  readonly stderr: string;
  /** 0 done, 1 an internal error, 2 bad input. */
  readonly exitCode: 0 | 1 | 2;
}

/** Reads a file as text, or throws a ParameterError saying why it cannot. */
export type ReadTextFile = (path: string) => string;

/**
 * The whole command, apart from the process: arguments in, stdout/stderr text and exit status out.
 * All input is checked before anything is computed, and the output is complete before it is
 * returned, so bad input leaves stdout empty.
 */
export function runColorCommand(argv: readonly string[], readTextFile: ReadTextFile): CommandResult {
  try {
    return { stdout: render(parseCommandLine(argv), readTextFile), stderr: '', exitCode: 0 };
  } catch (error) {
    if (error instanceof ParameterError) return { stdout: '', stderr: errorLine(error.message), exitCode: 2 };
    const message = error instanceof Error ? error.message : String(error);
    return { stdout: '', stderr: errorLine(`internal error: ${message}`), exitCode: 1 };
  }
}

const errorLine = (message: string): string => `color: ${message.replace(/[\r\n]+/g, ' ')}\n`;

function render(command: Command, readTextFile: ReadTextFile): string {
  switch (command.kind) {
    case 'help':
      return USAGE;
    case 'cases':
      return jsonLines(command.cases.map((c) => computeCaseColor(c, command.gamut)));
    case 'casesFile': {
      const cases = parseCasesJson(readTextFile(command.path), command.path);
      return jsonLines(cases.map((c) => computeCaseColor(c, command.gamut)));
    }
    case 'table': {
      const { base, variable, gamut } = command;
      const rows = command.values.map((value, index) => {
        const c: ColorCase = { ...base, id: index, stack: { ...base.stack, [variable]: value } };
        return tableRow(c, computeCaseColor(c, gamut));
      });
      return command.format === 'csv' ? tableCsv(rows, base.wavelengthsNm) : jsonLines(rows);
    }
  }
}
