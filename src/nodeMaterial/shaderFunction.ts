/**
 * A TSL function with a layout: a function of the program's code, emitted once and called where
 * the graph uses it, rather than its nodes copied into the graph at every use. three builds a
 * layout function's body once per backend and keeps its code for every later program, so a
 * program made of such functions is built in time proportional to its call sites: what keeps an
 * option change's new program off the main thread's long tasks. The body reads its arguments
 * only (no uniform or texture: those are named per program, the code is shared).
 */
import { Fn } from 'three/tsl';
import { type Node } from 'three/webgpu';

/** The shader types the film's functions take and return. */
type ShaderType = 'float' | 'vec2' | 'vec4';

/** The nodes of a list of shader types. */
type NodesOf<A extends readonly ShaderType[]> = { readonly [K in keyof A]: Node<A[K]> };

/**
 * `body` as the shader function `name` of parameters `inputs` (name, type) returning `returns`;
 * called with nodes of those types, it gives the call's node.
 */
export function shaderFunction<const A extends readonly ShaderType[], R extends ShaderType>(
  name: string,
  returns: R,
  inputs: { readonly [K in keyof A]: readonly [string, A[K]] },
  body: (...args: NodesOf<A>) => Node<R>,
): (...args: NodesOf<A>) => Node<R> {
  const fn = Fn((args: readonly Node[]) => body(...(args as unknown as NodesOf<A>))).setLayout({
    name,
    type: returns,
    inputs: inputs.map(([input, type]) => ({ name: input, type })),
  });
  return (...args) => (fn as unknown as (...a: readonly Node[]) => Node<R>)(...args);
}
