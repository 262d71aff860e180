/**
 * Input checks shared by every entry point. A bad value throws a RangeError whose message names
 * the parameter, the value and the allowed range, before anything is computed with it.
 */
export class ParameterError extends RangeError {
  constructor(
    readonly parameter: string,
    message: string,
  ) {
    super(message);
    this.name = 'ParameterError';
  }
}

export function assertInRange(name: string, value: number, min: number, max: number, unit = ''): void {
  if (typeof value !== 'number' || !Number.isFinite(value) || value < min || value > max) {
    const u = unit ? ` ${unit}` : '';
    throw new ParameterError(name, `${name}: ${String(value)} is not allowed; expected a number in [${min}, ${max}]${u}`);
  }
}

export function assertOneOf<T extends string>(name: string, value: unknown, allowed: readonly T[]): asserts value is T {
  if (!allowed.includes(value as T)) {
    throw new ParameterError(name, `${name}: ${JSON.stringify(value)} is not allowed; expected one of ${allowed.join(', ')}`);
  }
}
