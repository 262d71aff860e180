import { ShaderChunk } from 'three';
import { FILM_METHOD_GLSL, glslAssembler, glslFilesByName } from '../gpu/glslAssembly.ts';
import { FILM_GLSL } from '../film/filmShaderSource.ts';

/** The material's GLSL: the film's files and its own (shaders/meshMaterial/). */
const OWN_FILES = import.meta.glob<string>('../../shaders/meshMaterial/*.glsl', { query: '?raw', import: 'default', eager: true });
const shaderSource = glslAssembler(glslFilesByName(OWN_FILES, FILM_METHOD_GLSL, FILM_GLSL), FILM_METHOD_GLSL);

/** The call in three's lights_fragment_begin chunk that gives the film over the dielectric base. */
const DIELECTRIC_FILM = 'evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.specularColor )';
/** The call that gives the film over the metallic base (three's base colour as F0, Schlick's Fresnel). */
const METALLIC_FILM = 'evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.diffuseColor )';
/** Ours, shaders/meshMaterial/spectralIridescence.glsl: the film's reflectance at the fragment's thickness and n·v. */
const SPECTRAL_FILM = 'tfcSpectralIridescence( material.iridescenceThickness, dotNVi )';
/**
 * three's F0 for the film's image-based light: Schlick's curve inverted at n·v. Ours inverts the
 * lobe the light is then integrated with, its DFG table's single scattering and three's multiple
 * scattering (docs/material.md#the-films-f0-for-image-based-light), so under uniform light the
 * surface reflects the film's own value at n·v at every angle.
 */
const THREE_F0 = (lobe: Lobe) => `material.iridescenceF0${lobe} = Schlick_to_F0( iridescenceFresnel${lobe}, 1.0, dotNVi );`;
const SPECTRAL_F0 = (lobe: Lobe) =>
  `material.iridescenceF0${lobe} = tfcSpectralIridescenceF0( iridescenceFresnel${lobe}, texture2D( dfgLUT, vec2( material.roughness, dotNVi ) ).rg, material.specularF90 );`;
type Lobe = 'Dielectric' | 'Metallic';

/** The includes of three's physical fragment shader the film is written into. */
const FILM_INCLUDES = ['#include <iridescence_fragment>', '#include <lights_fragment_begin>', '#include <lights_fragment_end>'] as const;

/**
 * After three's indirect light, in a scene with an environment: its light through the film's matrix
 * in place of three's product per channel (shaders/meshMaterial/spectralIridescence.glsl,
 * tfcEnvironmentThroughMatrix), for the film's lobe and weight.
 */
const ENVIRONMENT_THROUGH_MATRIX = (
  lobe: Lobe,
) => `#if defined( USE_IRIDESCENCE ) && defined( TFC_ENVIRONMENT_MATRIX ) && defined( RE_IndirectSpecular )
	reflectedLight.indirectSpecular += tfcEnvironmentThroughMatrix( radiance, iblIrradiance, material.dfg, material.iridescenceF0${lobe}, material.iridescence * ${lobe === 'Metallic' ? 'material.metalness' : '( 1.0 - material.metalness )'} );
#endif`;

/** Why the film could not be written into a fragment shader: what is missing, in words a warning can quote. */
export interface MissingFilmLines {
  readonly missing: string;
}

/**
 * three's physical fragment shader `fragment` with the spectral film written in: our GLSL after
 * three's iridescence declarations, three's lights_fragment_begin with the film's lobe replaced
 * (its value and its F0) — the dielectric lobe, or over a metal from the base colour
 * (docs/material.md#a-metal-from-its-colour) the metallic one — and after lights_fragment_end the
 * environment's light through the film's matrix. Where the shader (a user's edit)
 * or three's chunk (another three.js release) lacks a line the edit needs, what is missing.
 */
export function spectralFragmentShader(fragment: string, metal: boolean): string | MissingFilmLines {
  const missingInclude = FILM_INCLUDES.find((line) => !fragment.includes(line));
  if (missingInclude !== undefined) return { missing: `${missingInclude} (removed by an onBeforeCompile)` };
  const lobe: Lobe = metal ? 'Metallic' : 'Dielectric';
  const film = metal ? METALLIC_FILM : DIELECTRIC_FILM;
  const begin = ShaderChunk.lights_fragment_begin;
  const missingLine = [film, THREE_F0(lobe)].find((line) => !begin.includes(line));
  if (missingLine !== undefined) return { missing: `${missingLine} (in three.js's lights_fragment_begin)` };
  return fragment
    .replace(FILM_INCLUDES[0], `${FILM_INCLUDES[0]}\n#ifdef USE_IRIDESCENCE\n${shaderSource('spectralIridescence.glsl')}\n#endif`)
    .replace(FILM_INCLUDES[1], begin.replace(film, SPECTRAL_FILM).replace(THREE_F0(lobe), SPECTRAL_F0(lobe)))
    .replace(FILM_INCLUDES[2], `${FILM_INCLUDES[2]}\n${ENVIRONMENT_THROUGH_MATRIX(lobe)}`);
}
