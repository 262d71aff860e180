import type { GamutMapping } from '../physics/colorConversions.ts';
import { ParameterError } from '../input/validate.ts';
import { chartLayout } from './chartLayout.ts';
import { chartPng } from './chartPng.ts';
import { chartSvg } from './chartSvg.ts';
import type { ColorCase } from './colorCase.ts';
import { computeCaseColor } from './computeCaseColor.ts';
import { type TableRow, jsonLines, tableCsv, tableRow } from './formatOutput.ts';
import { type Command, parseCommandLine } from './parseCommandLine.ts';
import { parseCasesJson } from './parseCasesJson.ts';
import { USAGE } from './usage.ts';

export interface CommandResult {
  readonly stdout: string;
  readonly stderr: string;
  /** 0 done, 1 an internal error, 2 bad input. */
  readonly exitCode: 0 | 1 | 2;
  /** A file to write (a chart) before stdout is printed; the caller writes it atomically. */
  readonly file?: { readonly path: string; readonly data: Buffer | string };
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
    const command = parseCommandLine(argv);
    if (command.kind === 'chart') return { ...renderChart(command), stderr: '', exitCode: 0 };
    return { stdout: render(command, readTextFile), stderr: '', exitCode: 0 };
  } catch (error) {
    if (error instanceof ParameterError) return { stdout: '', stderr: errorLine(error.message), exitCode: 2 };
    const message = error instanceof Error ? error.message : String(error);
    return { stdout: '', stderr: errorLine(`internal error: ${message}`), exitCode: 1 };
  }
}

const errorLine = (message: string): string => `color: ${message.replace(/[\r\n]+/g, ' ')}\n`;

/** The rows of a table that varies `variable` over `values`, the rest of the case `base`. */
function tableRows(base: ColorCase, variable: 'thicknessNm' | 'angleDeg', values: readonly number[], gamut: GamutMapping): TableRow[] {
  return values.map((value, index) => {
    const c: ColorCase = { ...base, id: index, stack: { ...base.stack, [variable]: value } };
    return tableRow(c, computeCaseColor(c, gamut));
  });
}

/** A chart's file, and one JSON line on stdout saying what was written. */
function renderChart(command: Extract<Command, { kind: 'chart' }>): { stdout: string; file: NonNullable<CommandResult['file']> } {
  const { base, thicknessNm, anglesDeg, gamut } = command;
  const rowAt = (angleDeg: number) => tableRows({ ...base, stack: { ...base.stack, angleDeg } }, 'thicknessNm', thicknessNm, gamut);
  const colors = (anglesDeg ?? [base.stack.angleDeg]).map(rowAt);
  const layout = chartLayout({ thicknessNm, anglesDeg, colors, stripHeightPx: command.stripHeightPx });
  const data = command.format === 'png' ? chartPng(layout) : chartSvg(layout);
  const summary = { out: command.out, format: command.format, width: layout.width, height: layout.height, cells: layout.cells.length };
  return { stdout: `${JSON.stringify(summary)}\n`, file: { path: command.out, data } };
}

function render(command: Exclude<Command, { kind: 'chart' }>, readTextFile: ReadTextFile): string {
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
      const rows = tableRows(base, variable, command.values, gamut);
      return command.format === 'csv' ? tableCsv(rows, base.wavelengthsNm, base.films.length) : jsonLines(rows);
    }
  }
}
