import type { WebGLRenderer } from 'three';
import type { EvolvingField, FieldDerived, FieldName } from '../fields/fields.ts';
import type { FieldState } from '../fields/thicknessField.ts';
import { FlowFieldState } from '../gpuFilmDynamics/flowFieldState.ts';

/**
 * The simulation each evolving field's film lives in, for a renderer: the type requires one for
 * every field marked `evolves` in THICKNESS_FIELDS and none for another.
 */
const FIELD_STATES: { readonly [K in EvolvingField]: (renderer: WebGLRenderer) => FieldState<FieldDerived<K>> } = {
  flow: (renderer) => new FlowFieldState(renderer),
};

/** A new state for the field (it takes what the frame's field derives: drawnField's), or null for a field that does not evolve. */
export const createFieldState = (field: FieldName, renderer: WebGLRenderer): FieldState<FieldDerived> | null =>
  Object.hasOwn(FIELD_STATES, field) ? FIELD_STATES[field as EvolvingField](renderer) : null;
