import { XYZ_TO_LINEAR_SRGB, applyMatrix3, encode8, mapToGamut } from '../physics/colorConversions.ts';
import { resolveLayers } from '../physics/stackFilms.ts';
import { layersXyz } from '../physics/stackColor.ts';
import { transparentIndexAt } from '../physics/medium.ts';
import { DESIGN_NM, STACK_PRESETS, type StackPresetName } from '../physics/stackPresets.ts';
import { type LayerStack, layersReflectance } from '../physics/transferMatrix.ts';

/** The stacks the materials page shows, in its scene and as swatches, and the angles of incidence of each swatch. */
export const SWATCH_STACKS = ['arCoating', 'nacre'] as const satisfies readonly StackPresetName[];
export const SWATCH_ANGLES_DEG = [0, 45] as const;

/** A named stack at θ_i, as the transfer matrix takes it. */
const stackAt = (name: StackPresetName, angleDeg: number): LayerStack => {
  const p = STACK_PRESETS[name];
  return { nOutside: p.nOutside, films: resolveLayers(p.films, 0), nInside: p.nInside, angleDeg };
};

/** The reference colour (eqs 15–19, D65, sRGB, gamut-mapped) of a named stack at θ_i, 8 bits per channel. */
export function stackSwatchRgb8(name: StackPresetName, angleDeg: number): [number, number, number] {
  const xyz = layersXyz(stackAt(name, angleDeg));
  const [r, g, b] = mapToGamut(applyMatrix3(XYZ_TO_LINEAR_SRGB, xyz), xyz[1]).map(encode8);
  return [r!, g!, b!];
}

/** The coated lens's R at its design wavelength and normal incidence, and the bare glass's (Fresnel at 0°), in per cent. */
export function coatedLensPercent(): { readonly coated: number; readonly bare: number } {
  const glass = transparentIndexAt(STACK_PRESETS.arCoating.nInside, DESIGN_NM);
  return { coated: 100 * layersReflectance(DESIGN_NM, stackAt('arCoating', 0)), bare: 100 * ((glass - 1) / (glass + 1)) ** 2 };
}
