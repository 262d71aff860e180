/**
 * three.js's PhysicalLightingModel with the spectral film in its iridescence: where three's
 * `start()` evaluates its film (evalIridescence: Schlick Fresnel, two orders of the Airy sum, a
 * Gaussian fit of the colour-matching functions) for the lobe of the film's base, this model
 * gives the film's reflectance as the binned spectral integral (filmColor.ts), and the F0 three's
 * image-based light takes for it. The film's fields are the model's own before three's `start()`
 * reads them (its environment's multiple scattering reads iridescenceF0Dielectric inside
 * `start()`), and three's writes of them keep only three's film of the other lobe.
 */
import {
  DFGLUT,
  clamp,
  iridescence,
  iridescenceThickness,
  metalness,
  mix,
  normalView,
  positionViewDirection,
  roughness,
  specularF90,
  vec3,
} from 'three/tsl';
import { type Node, type NodeBuilder, PhysicalLightingModel } from 'three/webgpu';
import { FILM_STACK_DOMAIN } from '../physics/filmReflectance.ts';
import { type FloatNode } from './complex.ts';

/**
 * The film at a fragment, as nodes: its linear RGB reflectance under the light (three's per-channel
 * film), and in a scene with an environment its environment matrix in the working space (its
 * columns) with the light's tint t, so that rgb = M t.
 */
export interface FilmColor {
  readonly rgb: Node<'vec3'>;
  readonly matrix: { readonly columns: readonly Node<'vec3'>[]; readonly tint: Node<'vec3'> } | null;
}

/** The film at a thickness (nm) and n·v. */
export type FilmAt = (thicknessNm: FloatNode, cosIncidence: FloatNode) => FilmColor;

/** M v for a matrix given by its columns. */
export const matrixTimes = (columns: readonly Node<'vec3'>[], v: Node<'vec3'>): Node<'vec3'> =>
  columns[0]!.mul(v.x).add(columns[1]!.mul(v.y)).add(columns[2]!.mul(v.z));

/** The fields of three's film this model replaces. */
const FIELDS = ['iridescenceFresnel', 'iridescenceF0Dielectric', 'iridescenceF0Metallic'] as const;
type Field = (typeof FIELDS)[number];

/**
 * The F0 three's image-based light takes for the film: the F0 whose lobe (three's DFG single
 * scattering and its multiple scattering, computeMultiscattering) reflects the film's own F under
 * uniform light, F0 = (F·(1 − Ems/21) − F90·dfg.y) / (dfg.x + (20/21)·Ems·F); the twin of
 * tfcSpectralIridescenceF0 in shaders/meshMaterial/spectralIridescence.glsl, which derives it.
 */
function spectralF0(film: Node<'vec3'>, dfg: Node<'vec2'>, f90: FloatNode): Node<'vec3'> {
  const ems = dfg.x.add(dfg.y).oneMinus();
  const numerator = film.mul(ems.div(21).oneMinus()).sub(f90.mul(dfg.y));
  return numerator.div(
    film
      .mul(ems.mul(20 / 21))
      .add(dfg.x)
      .max(vec3(1e-4, 1e-4, 1e-4)),
  );
}

/** Operands of three's mix(dielectric, metallic, metalness), as its MathNode keeps them. */
const mixOperands = (node: Node): readonly [Node<'vec3'>, Node<'vec3'>] | null => {
  const m = node as unknown as { aNode?: Node<'vec3'>; bNode?: Node<'vec3'> };
  return m.aNode && m.bNode ? [m.aNode, m.bNode] : null;
};

export class SpectralLightingModel extends PhysicalLightingModel {
  private readonly three: Partial<Record<Field, Node>> = {};
  private spectral: {
    readonly fresnel: Node<'vec3'>;
    readonly f0: Node<'vec3'>;
    readonly dfg: Node<'vec2'>;
    readonly matrix: FilmColor['matrix'];
  } | null = null;

  /** `filmAt`: the film; `metallic`: it lies on the metal of the base colour (the metallic lobe), else it is the dielectric lobe. */
  constructor(
    three: PhysicalLightingModel,
    private readonly filmAt: FilmAt,
    private readonly metallic: boolean,
  ) {
    super(
      three.clearcoat,
      three.sheen,
      true,
      three.anisotropy,
      three.transmission,
      three.dispersion,
      three.retroreflection,
      three.diffuseRoughness,
    );
    for (const field of FIELDS)
      Object.defineProperty(this, field, {
        get: () => this.field(field),
        set: (value: Node | null) => {
          if (value) this.three[field] = value;
        },
      });
  }

  /** The film's fields, then three's start with its film of the other lobe. */
  override start(builder: NodeBuilder): void {
    const dotNVi = normalView.dot(positionViewDirection).clamp();
    const d = FILM_STACK_DOMAIN.thicknessNm;
    const film = this.filmAt(clamp(iridescenceThickness, d.min, d.max), dotNVi);
    const fresnel = film.rgb.toVar('spectralFilm');
    const dfg = (DFGLUT({ roughness, dotNV: dotNVi }) as unknown as Node<'vec2'>).toVar('spectralFilmDfg');
    this.spectral = { fresnel, f0: spectralF0(fresnel, dfg, specularF90).toVar('spectralFilmF0'), dfg, matrix: film.matrix };
    super.start(builder);
  }

  /**
   * three's image-based specular light, and in a scene with an environment what its light L gains
   * when the film reflects it as a spectrum: M (t L) in place of three's (M t) L, for the film's
   * lobe and weight, L the prefiltered radiance mixed with the irradiance / π in the share three
   * gives multiple scattering (Ems Favg); the twin of tfcEnvironmentThroughMatrix in
   * shaders/meshMaterial/spectralIridescence.glsl, which says why (docs/material.md#light).
   */
  override indirectSpecular(builder: NodeBuilder): void {
    super.indirectSpecular(builder);
    const spectral = this.spectral;
    if (!spectral?.matrix) return;
    const { radiance, iblIrradiance, reflectedLight } = builder.context as {
      radiance: Node<'vec3'>;
      iblIrradiance: Node<'vec3'>;
      reflectedLight: { indirectSpecular: Node<'vec3'> };
    };
    const { columns, tint } = spectral.matrix;
    const ems = spectral.dfg.x.add(spectral.dfg.y).oneMinus();
    const favg = spectral.f0.add(spectral.f0.oneMinus().div(21)).dot(vec3(1 / 3, 1 / 3, 1 / 3));
    const light = mix(radiance, iblIrradiance.div(Math.PI), clamp(ems.mul(favg), 0, 1)).toVar();
    const weight = iridescence.mul(this.metallic ? metalness : metalness.oneMinus());
    // three's film, `fresnel`, is M t already.
    const gain = matrixTimes(columns, tint.mul(light)).sub(spectral.fresnel.mul(light));
    reflectedLight.indirectSpecular.addAssign(gain.mul(weight));
  }

  private field(field: Field): Node | null {
    const spectral = this.spectral;
    if (!spectral) return this.three[field] ?? null;
    const ownLobe = this.metallic ? 'iridescenceF0Metallic' : 'iridescenceF0Dielectric';
    if (field === ownLobe) return spectral.f0;
    if (field !== 'iridescenceFresnel') return this.three[field] ?? spectral.f0;
    const lobes = this.three.iridescenceFresnel ? mixOperands(this.three.iridescenceFresnel) : null;
    const [dielectric, metallic] = lobes ?? [spectral.fresnel, spectral.fresnel];
    return this.metallic ? mix(dielectric, spectral.fresnel, metalness) : mix(spectral.fresnel, metallic, metalness);
  }
}
