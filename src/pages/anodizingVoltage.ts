/**
 * The voltage that grows an anodic oxide of a given thickness on titanium: d ≈ a·V, the growth
 * constant a about 2 nm/V, between 1.6 and 2.8 nm/V depending on the electrolyte (and its
 * temperature and the current), so a voltage read from a thickness is an estimate.
 */
export const ANODIZING_NM_PER_V = { nominal: 2, min: 1.6, max: 2.8 } as const;

/** The slider's label: `TiO₂ 60 nm ≈ 30 V (21–38 V for 1.6–2.8 nm/V)`, voltages rounded to whole volts. */
export function anodizingText(thicknessNm: number): string {
  const { nominal, min, max } = ANODIZING_NM_PER_V;
  const v = (nmPerV: number) => Math.round(thicknessNm / nmPerV);
  return `TiO₂ ${thicknessNm} nm ≈ ${v(nominal)} V (${v(max)}–${v(min)} V for ${min}–${max} nm/V)`;
}
