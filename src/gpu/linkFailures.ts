import type { WebGLRenderer } from 'three';

/** Programs whose link has been checked, per renderer's context. */
const checked = new WeakSet<WebGLProgram>();

/**
 * Where the GPU compiles in parallel, three's own check of a new program asks for its info log at
 * its first draw: a synchronous round trip that waits out all the GPU's queued work (up to seconds on
 * a CPU rasteriser), a stall the parallel compile was meant to spare. Such a renderer leaves that
 * check off (src/view/bubbleRenderer.ts) and its programs are checked here once compiled: the link status
 * is at hand without a wait then, and the logs are asked for only of a program that failed.
 * Returns one message per program that failed to link, each said once. The caller asks only of
 * programs of the context as it is (none compiled before a loss since): asking whether a program
 * is one (isProgram) would itself be a round trip that waits for the GPU.
 */
export function linkFailures(renderer: WebGLRenderer): string[] {
  const gl = renderer.getContext();
  const failures: string[] = [];
  for (const held of renderer.info.programs ?? []) {
    const { program, name } = held as { program: WebGLProgram; name: string };
    if (checked.has(program)) continue;
    checked.add(program);
    if (gl.getProgramParameter(program, gl.LINK_STATUS) !== false) continue;
    const shaders = gl.getAttachedShaders(program) ?? [];
    const logs = [gl.getProgramInfoLog(program), ...shaders.map((s) => gl.getShaderInfoLog(s))].filter((log) => log?.trim());
    failures.push(`the WebGL program ${name || '(unnamed)'} did not link: ${logs.join(' ')}`);
  }
  return failures;
}
