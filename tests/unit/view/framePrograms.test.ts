/**
 * A frame's programs compiled in parallel are checked once compiled: a program that failed to link
 * is reported once, by name and with its logs; one that linked is not. A context lost while they
 * compiled has none of them, and nothing is asked of it. The renderer and its WebGL context are
 * fakes whose compiles finish when the test says.
 */
import type { Camera, Object3D, Scene, WebGLRenderer } from 'three';
import { describe, expect, it } from 'vitest';
import { compileFramePrograms } from '../../../src/view/framePrograms.ts';

const LINK_STATUS = 0x8b82;

interface FakeProgram {
  readonly linked: boolean;
  readonly log: string;
}

/** A renderer with parallel compile (three's own check off) holding `programs`, whose compileAsync resolves when `finish` is called. */
function fakeRenderer(programs: { name: string; program: FakeProgram }[], lost = false) {
  const canvas = new EventTarget();
  const asked: FakeProgram[] = [];
  let finish = () => {};
  const gl = {
    LINK_STATUS,
    isContextLost: () => lost,
    getProgramParameter: (program: FakeProgram, parameter: number) => {
      asked.push(program);
      return parameter === LINK_STATUS ? program.linked : null;
    },
    getAttachedShaders: () => [],
    getProgramInfoLog: (program: FakeProgram) => program.log,
    getShaderInfoLog: () => '',
  };
  const renderer = {
    domElement: canvas,
    debug: { checkShaderErrors: false },
    info: { programs },
    getContext: () => gl,
    compileAsync: () => new Promise<void>((resolve) => (finish = resolve)),
  };
  return { renderer: renderer as unknown as WebGLRenderer, canvas, asked, finish: () => finish() };
}

const mesh = {} as Object3D;
const compile = (renderer: WebGLRenderer) => compileFramePrograms(renderer, {} as Camera, {} as Scene, [mesh], []);

/** What compileFramePrograms reported on the console. */
async function reported(run: () => Promise<void>): Promise<string[]> {
  const said: string[] = [];
  const error = console.error;
  console.error = (text: string) => said.push(text);
  try {
    await run();
  } finally {
    console.error = error;
  }
  return said;
}

describe('compileFramePrograms', () => {
  it('reports a program that failed to link once, by name with its log, and not one that linked', async () => {
    const broken = { linked: false, log: "ERROR: 'tfcMissing' : undeclared identifier" };
    const { renderer, finish } = fakeRenderer([
      { name: 'tfcBubble', program: { linked: true, log: '' } },
      { name: 'tfcFilmTablePass', program: broken },
    ]);
    const first = await reported(async () => {
      const done = compile(renderer);
      finish();
      await done;
    });
    expect(first).toEqual([`the WebGL program tfcFilmTablePass did not link: ${broken.log}`]);
    const again = await reported(async () => {
      const done = compile(renderer);
      finish();
      await done;
    });
    expect(again).toEqual([]);
  });

  // A lost context's programs, or a restored one's list holding them: their names may be the new context's other objects.
  for (const [when, event, lostAtStart] of [
    ['lost while the programs compiled', 'webglcontextlost', false],
    ['restored while the programs compiled', 'webglcontextrestored', false],
    ['lost as the compile started', null, true],
  ] as const) {
    it(`asks nothing of a context ${when}`, async () => {
      const { renderer, canvas, asked, finish } = fakeRenderer(
        [{ name: 'tfcBubble', program: { linked: false, log: 'stale' } }],
        lostAtStart,
      );
      const said = await reported(async () => {
        const done = compile(renderer);
        if (event) canvas.dispatchEvent(new Event(event));
        finish();
        await done;
      });
      expect(said).toEqual([]);
      expect(asked).toEqual([]);
    });
  }
});
