import { ParameterError } from '../../../src/input/validate.ts';

/** The parameter a call's ParameterError names, or `accepted` when it throws nothing. */
export const parameterOf = (f: () => unknown): string => {
  try {
    f();
  } catch (e) {
    if (e instanceof ParameterError) return e.parameter;
    throw e;
  }
  return 'accepted';
};
