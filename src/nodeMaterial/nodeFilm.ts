/**
 * What a material made spectral by the WebGPU entry holds beside the shared film record
 * (src/meshMaterial/spectralFilm.ts): its TSL inputs and its table, brought up to the material
 * before each render; and the lighting model that draws its film.
 */
import { type MeshPhysicalMaterial, type Vector3 } from 'three';
import { clamp, float, ior, iridescenceIOR, vec2 } from 'three/tsl';
import {
  MeshPhysicalNodeMaterial,
  type Node,
  type NodeBuilder,
  type NodeFrame,
  type PhysicalLightingModel,
  type Renderer,
  type UniformNode,
} from 'three/webgpu';
import { updateFilmColorUniforms } from '../film/filmColor.ts';
import { filmSpectralBins } from '../film/filmFillGpu.ts';
import { spectralBinDefines } from '../film/spectralBinsTexture.ts';
import { FILM_STACK_DOMAIN } from '../physics/filmReflectance.ts';
import { filmFill } from '../methods/filmFills.ts';
import { methodReads } from '../methods/methods.ts';
import {
  type MaterialFilmSettings,
  drawnFilmSettings,
  filmKeyOf,
  filmSettingsOf,
  followMetal,
  metalOf,
  metalStateOf,
} from '../meshMaterial/materialFilm.ts';
import { type SpectralFilm, filmOf, warnOnce } from '../meshMaterial/spectralFilm.ts';
import { type CheckedOptions } from '../meshMaterial/spectralIridescenceOptions.ts';
import { type FloatNode } from './complex.ts';
import { type FilmInputs, setFilmInputs } from './filmInputs.ts';
import { channelsOf } from './filmReflectance.ts';
import { type FilmNodes, filmPlanesXyz, xyzToLinearWorking } from './filmColor.ts';
import { type FillFilm, NodeFilmTable } from './filmTable.ts';
import { type PhysicalMaterial, physical } from './physicalMaterial.ts';
import { FilmUpdateNode } from './filmUpdateNode.ts';
import { type Ahead, type LastDraw, isStandIn, materialBuilt, noteDraw, retireAt, retireFor } from './programAhead.ts';
import { type FilmColor, SpectralLightingModel, matrixTimes } from './spectralLightingModel.ts';
import { filmPlanes } from '../settings/filmLight.ts';
import { type PlaneCount } from '../physics/spectralWeights.ts';

/**
 * A spectral node film: the shared record, its TSL inputs, its table (null until `table` is drawn;
 * in a scene with an environment, of the columns of its environment matrix), the light's tint (a
 * colour that matrix maps), the renderer that drew it last, where it was last drawn, and the
 * program it builds ahead (programAhead.ts).
 */
export interface NodeFilm {
  readonly film: SpectralFilm;
  readonly inputs: FilmInputs;
  table: NodeFilmTable | null;
  readonly tint: UniformNode<'vec3', Vector3>;
  renderer: Renderer | null;
  lastDraw: LastDraw | null;
  readonly ahead: Ahead;
}

/**
 * Whether the film is drawn from the table: every method that does not integrate the bins per
 * fragment, `table`, and `fourier` in its place (its series per fragment is not ported: drawn from
 * the table, with a notice); a per-pixel iridescenceIORNode is drawn by `exact` (the table is made
 * for one index).
 */
export function drawsTable(m: PhysicalMaterial, s: MaterialFilmSettings): boolean {
  const node = (m as Partial<MeshPhysicalNodeMaterial>).iridescenceIORNode;
  return !methodReads(s.mode, 'spectralBins') && !node;
}

/**
 * The film's part of the material's program key: what its nodes are built from. Drawn from the
 * table, they are the lookup alone, whatever the film, its light or its polarisation (those are
 * the table's texels): the table's quality and the lobe the film lies on; drawn by `exact`, all
 * the film's defines say. A change of light or polarisation in `table` then builds no program.
 */
export function nodeProgramKey(m: MeshPhysicalMaterial, o: CheckedOptions): string {
  const s = filmSettingsOf(m, o, (_, value) => value);
  return drawsTable(m, s) ? `table ${JSON.stringify(o.quality)}${metalStateOf(m, o)}` : filmKeyOf(m, o);
}

/** The film's nodes that the pass and the material share: its fill, channels, the media's inputs. */
const sharedNodes = (f: NodeFilm, s: MaterialFilmSettings): Omit<FilmNodes, 'bins' | 'channels' | 'nFilm' | 'nInside'> => ({
  fill: filmFill(s),
  // three's film lies in air
  nOutside: float(1),
  lines: f.inputs.lines,
  knots: f.inputs.knots,
  stack: { layers: f.inputs.layers, count: f.inputs.layerCount },
});

/** The film's nodes the table's fill reads. */
const fillFilm = (f: NodeFilm, s: MaterialFilmSettings): FillFilm => ({
  ...sharedNodes(f, s),
  nFilm: f.inputs.nFilm,
  nInside: f.inputs.nInside,
});

/**
 * Brings the film's uniforms, inputs and table up to the material, the table drawn with
 * `renderer`; `o`: the options drawn (the film's, unless its program still draws those it was built for).
 */
export function updateNodeFilm(f: NodeFilm, m: PhysicalMaterial, renderer: Renderer | null, o: CheckedOptions = f.film.options): void {
  const s = drawnFilmSettings(physical(m), f.film, o);
  if (methodReads(s.mode, 'spectralTransform'))
    warnOnce(f.film, 'series', `mode ${s.mode} is drawn from the table on WebGPURenderer (its series per fragment is WebGLRenderer's)`);
  followMetal(physical(m), f.film);
  // The entry makes the film's uniforms with the film (spectralNodeMaterial.ts).
  const film = f.film as SpectralFilm & { uniforms: NonNullable<SpectralFilm['uniforms']> };
  updateFilmColorUniforms(film, { ...s, mode: 'exact' }, o.quality, null);
  setFilmInputs(f.inputs, film.uniforms);
  f.tint.value.fromArray(s.lightTint);
  if (renderer) f.renderer = renderer;
  if (renderer && f.table && drawsTable(m, s)) f.table.update(renderer, s, fillFilm(f, s));
}

/**
 * Builds off the frame the programs the film's next draw needs that its last one did not (the
 * material's, built ahead, and the table's fill for a new film): done when that draw builds none
 * on this thread. A film not drawn yet has none built: its first draw builds them.
 */
export async function prepareNodeFilm(f: NodeFilm, m: PhysicalMaterial): Promise<void> {
  await f.ahead.building;
  const s = drawnFilmSettings(physical(m), f.film);
  if (f.renderer && f.table && drawsTable(m, s)) await f.table.prepare(f.renderer, s, fillFilm(f, s));
}

/**
 * The film's XYZ by `exact` on the material, in its colour planes: three's iridescenceIOR and ior
 * (clamped to the film's domain) unless the options name the media.
 */
function exactXyz(f: NodeFilm, m: PhysicalMaterial, s: MaterialFilmSettings, thicknessNm: FloatNode, cosIncidence: FloatNode) {
  const o = f.film.options;
  const q = o.quality;
  const bins = spectralBinDefines(filmSpectralBins(s, q, q.exactSpectralBins), q.spectralTailTolerance);
  const d = FILM_STACK_DOMAIN;
  const three = (n: FloatNode, domain: { min: number; max: number }) => vec2(clamp(n, domain.min, domain.max), 0);
  return filmPlanesXyz(
    {
      ...sharedNodes(f, s),
      channels: channelsOf(s.polarization),
      bins: {
        count: bins.TFC_SPECTRAL_BINS!,
        first: bins.TFC_SPECTRAL_BIN_FIRST!,
        end: bins.TFC_SPECTRAL_BIN_END!,
        weights: f.inputs.weights,
      },
      nFilm: o.film === null ? three(iridescenceIOR, d.nFilm) : f.inputs.nFilm,
      nInside: o.base === null && metalOf(physical(m), o) === null ? three(ior, d.nInside) : f.inputs.nInside,
    },
    thicknessNm,
    cosIncidence,
    filmPlanes(s),
  );
}

/**
 * The film's table for its quality and colour planes, made again when either changes; the one it
 * replaces is let go at the first draw by the program of `token`, which reads the new one.
 */
function tableOf(f: NodeFilm, planes: PlaneCount, token: object): NodeFilmTable {
  const quality = f.film.options.quality;
  if (f.table && f.table.planes === planes && JSON.stringify(f.table.quality) === JSON.stringify(quality)) return f.table;
  const replaced = f.table;
  if (replaced) retireAt(f, token, () => replaced.dispose());
  return (f.table = new NodeFilmTable(quality, planes));
}

const nodeFilms = new WeakMap<object, NodeFilm>();

/** Makes `m` hold `f`. */
export const addNodeFilm = (m: PhysicalMaterial, f: NodeFilm): void => void nodeFilms.set(m, f);

/** The node film of a material made spectral by this entry. */
export const nodeFilmOf = (m: object): NodeFilm | undefined => nodeFilms.get(m);

/**
 * three's lighting model for the material, or where it draws iridescence the film's: `this` is
 * the node material built (a classic material's node copy), `builder.material` the material made
 * spectral.
 */
export function setupLightingModel(this: MeshPhysicalNodeMaterial, builder: NodeBuilder): PhysicalLightingModel {
  const three: PhysicalLightingModel = MeshPhysicalNodeMaterial.prototype.setupLightingModel.call(this);
  const m = materialBuilt(builder.material);
  const f = nodeFilms.get(m);
  if (!f || !filmOf(m) || !three.iridescence) return three;
  // This program, named: what waits for its first draw of the material (a stand-in's, a table replaced).
  const token = {};
  if (isStandIn(builder.material)) retireAt(f, token, () => builder.material.dispose());
  // The environment three lights the material with (setupEnvironment's): the film reflects it through its matrix.
  const environment = this.envNode ?? (this as { envMap?: unknown }).envMap ?? (builder as { environmentNode?: unknown }).environmentNode;
  f.film.sceneEnvironment = environment !== null && environment !== undefined;
  const s = drawnFilmSettings(physical(m), f.film);
  const planes = filmPlanes(s);
  const table = drawsTable(m, s) ? tableOf(f, planes, token) : null;
  // The options this program draws: the film's while they key it, else (a program built ahead
  // for them) the last it drew, until the material's version moves to the new one.
  const builtKey = nodeProgramKey(physical(m), f.film.options);
  let drawn = f.film.options;
  const refresh = (frame: NodeFrame) => {
    if (isStandIn(frame.material)) return;
    noteDraw(f, frame);
    retireFor(f, token);
    // The key is computed only for options not drawn yet, not every frame.
    if (f.film.options !== drawn && nodeProgramKey(physical(m), f.film.options) === builtKey) drawn = f.film.options;
    updateNodeFilm(f, m, frame.renderer, drawn);
  };
  const film = (thicknessNm: FloatNode, cosIncidence: FloatNode): FilmColor => {
    const columns = (table ? table.lookups(thicknessNm, cosIncidence) : exactXyz(f, m, s, thicknessNm, cosIncidence)).map(
      xyzToLinearWorking,
    );
    const update = (rgb: Node<'vec3'>) => new FilmUpdateNode(rgb, (frame) => refresh(frame)) as never;
    if (planes === 1) return { rgb: update(columns[0]!), matrix: null };
    const matrix = columns.map((c) => c.toVar());
    // Under the light itself, three's per-channel film: M t.
    return { rgb: update(matrixTimes(matrix, f.tint)), matrix: { columns: matrix, tint: f.tint } };
  };
  return new SpectralLightingModel(three, film, metalOf(physical(m), f.film.options) !== null);
}
