/**
 * The node film's parity probe (tests/e2e/webgpu*.spec.ts, the benchmark): film XYZ of the parity cases through
 * the TSL film (src/nodeMaterial/) on WebGPURenderer, into a float target, read back; one draw per
 * group, one texel per case, no colour conversion. `exact` evaluates the film per texel; `table`
 * looks it up in the node material's own table (NodeFilmTable), built over the group's largest
 * thickness, in only the columns the group's lookups read. The twin of scripts/harness/filmXyzProbe.ts for the GLSL.
 */
import { methodReads } from '../../src/methods/methods.ts';
import { FloatType, RenderTarget } from 'three';
import { Fn, float, int, ivec2, textureLoad, uniform, uniformTexture, uv, vec4 } from 'three/tsl';
import { NodeMaterial, QuadMesh, type WebGPURenderer } from 'three/webgpu';
import { filmColorUniforms, updateFilmColorUniforms } from '../../src/film/filmColor.ts';
import { filmSpectralBins } from '../../src/film/filmFillGpu.ts';
import { filmStackUniforms } from '../../src/film/filmStack.ts';
import { spectralBinDefines } from '../../src/film/spectralBinsTexture.ts';
import { filmFill } from '../../src/methods/filmFills.ts';
import { type FilmNodes, filmXyz } from '../../src/nodeMaterial/filmColor.ts';
import { filmInputs, floatRow, setFilmInputs } from '../../src/nodeMaterial/filmInputs.ts';
import { channelsOf } from '../../src/nodeMaterial/filmReflectance.ts';
import { NodeFilmTable } from '../../src/nodeMaterial/filmTable.ts';
import { type FilmQuality } from '../../src/settings/filmQuality.ts';
import { DEFAULT_SETTINGS } from '../../src/settings/filmParameters.ts';
import { type FilmSettings } from '../../src/settings/filmSettings.ts';
import type { ParityGroup } from './parityCase.ts';

export type NodeParityMode = 'exact' | 'table';

const holder = { uniforms: { ...filmColorUniforms(), ...filmStackUniforms() } };
const inputs = filmInputs();
const nOutside = uniform(1);
const cases = uniformTexture(floatRow(1));
const caseCount = uniform(1);
const tables = new Map<string, NodeFilmTable>();
const passes = new Map<string, { readonly quad: QuadMesh; readonly material: NodeMaterial }>();

const tableFor = (q: FilmQuality): NodeFilmTable => {
  const key = JSON.stringify(q);
  const table = tables.get(key) ?? new NodeFilmTable(q);
  tables.set(key, table);
  return table;
};

/** The pass drawing the film of `s` at each case (thickness, cos θ_i) of the case texture. */
function passFor(s: FilmSettings, mode: NodeParityMode, q: FilmQuality, film: Omit<FilmNodes, 'bins' | 'channels'>): QuadMesh {
  const bins = spectralBinDefines(filmSpectralBins(s, q, q.exactSpectralBins), q.spectralTailTolerance);
  const channels = channelsOf(s.polarization);
  const key = JSON.stringify([mode, q, film.fill, channels.kinds, bins]);
  const known = passes.get(key);
  if (known) return known.quad;
  const nodes: FilmNodes = {
    ...film,
    channels,
    bins: { count: bins.TFC_SPECTRAL_BINS!, first: bins.TFC_SPECTRAL_BIN_FIRST!, end: bins.TFC_SPECTRAL_BIN_END!, weights: inputs.weights },
  };
  const material = new NodeMaterial();
  material.fragmentNode = Fn(() => {
    const c = textureLoad(cases, ivec2(int(uv().x.mul(caseCount)), int(0)));
    const xyz = methodReads(mode, 'table') ? tableFor(q).lookups(c.x, c.y)[0]! : filmXyz(nodes, c.x, c.y);
    return vec4(xyz, float(1));
  })();
  const pass = { quad: new QuadMesh(material), material };
  passes.set(key, pass);
  return pass.quad;
}

/** XYZ per case of one group. */
async function renderGroup(renderer: WebGPURenderer, g: ParityGroup, mode: NodeParityMode, q: FilmQuality): Promise<number[][]> {
  const count = g.inputs.length;
  const data = new Float32Array(4 * count);
  g.inputs.forEach(([thicknessNm, cosIncidence], i) => data.set([thicknessNm, cosIncidence, 0, 0], 4 * i));
  cases.value = floatRow(count, data);
  caseCount.value = count;
  // env none: the node film computes the film's XYZ, one colour plane (filmPlanes), as a material's film does.
  const s: FilmSettings = {
    ...DEFAULT_SETTINGS,
    ...g,
    env: 'none',
    field: 'uniform',
    thicknessNm: Math.max(...g.inputs.map(([d]) => d)),
    mode,
  };
  updateFilmColorUniforms(holder, { ...s, mode: 'exact' }, q, null);
  setFilmInputs(inputs, holder.uniforms);
  nOutside.value = s.nOutside;
  const film = {
    fill: filmFill(s),
    nOutside,
    nFilm: inputs.nFilm,
    nInside: inputs.nInside,
    lines: inputs.lines,
    knots: inputs.knots,
    stack: { layers: inputs.layers, count: inputs.layerCount },
  };
  if (methodReads(mode, 'table')) {
    // A table filled before fills another film once that film's program is built off the frame.
    await tableFor(q).prepare(renderer, s, film);
    tableFor(q).updateAround(
      renderer,
      s,
      film,
      g.inputs.map(([d]) => d),
    );
  }
  const target = new RenderTarget(count, 1, { type: FloatType, depthBuffer: false });
  renderer.setRenderTarget(target);
  passFor(s, mode, q, film).render(renderer);
  renderer.setRenderTarget(null);
  const out = (await renderer.readRenderTargetPixelsAsync(target, 0, 0, count, 1)) as Float32Array;
  target.dispose();
  cases.value.dispose();
  return g.inputs.map((_, i) => [out[4 * i]!, out[4 * i + 1]!, out[4 * i + 2]!]);
}

/** XYZ per case of every group, in the groups' order, as the node film computes it. */
export async function renderNodeFilmXyz(
  renderer: WebGPURenderer,
  groups: readonly ParityGroup[],
  mode: NodeParityMode,
  quality: FilmQuality,
): Promise<number[][][]> {
  const out: number[][][] = [];
  for (const g of groups) out.push(await renderGroup(renderer, g, mode, quality));
  return out;
}
