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

/** The film's linear RGB reflectance at a thickness (nm) and n·v, as nodes. */
export type FilmRgb = (thicknessNm: FloatNode, cosIncidence: FloatNode) => Node<'vec3'>;

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
  private spectral: { readonly fresnel: Node<'vec3'>; readonly f0: Node<'vec3'> } | null = null;

  /** `filmRgb`: the film; `metallic`: it lies on the metal of the base colour (the metallic lobe), else it is the dielectric lobe. */
  constructor(
    three: PhysicalLightingModel,
    private readonly filmRgb: FilmRgb,
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
    const fresnel = this.filmRgb(clamp(iridescenceThickness, d.min, d.max), dotNVi).toVar('spectralFilm');
    const dfg = DFGLUT({ roughness, dotNV: dotNVi }) as unknown as Node<'vec2'>;
    this.spectral = { fresnel, f0: spectralF0(fresnel, dfg, specularF90).toVar('spectralFilmF0') };
    super.start(builder);
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
