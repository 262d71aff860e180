import { describe, expect, it } from 'vitest';
import { XYZ_TO_LINEAR_SRGB } from '../../../src/physics/colorConversions.ts';
import { SOAP_FILM_IN_AIR, filmReflectance } from '../../../src/physics/filmReflectance.ts';
import { layersXyz } from '../../../src/physics/stackColor.ts';
import { filmXyz } from '../../../src/physics/spectralIntegration.ts';
import { DESIGN_NM, STACK_PRESETS } from '../../../src/physics/stackPresets.ts';
import { layersReflectance } from '../../../src/physics/transferMatrix.ts';
import { EN } from '../../../src/i18n/en.ts';
import { DEFAULT_SETTINGS } from '../../../src/settings/filmParameters.ts';
import { filmSpectrum } from '../../../src/plots/filmSpectrum.ts';
import { interferenceScale } from '../../../src/plots/interferenceScale.ts';
import { probeColor } from '../../../src/plots/probeColor.ts';
import { probeDescription } from '../../../src/plots/probeDescription.ts';
import { ALGEBRAIC_TOL, FEW_OPERATIONS_TOL } from '../../tolerances.ts';

const LIGHT = { illuminant: 'D65', polarization: 'unpolarized', normalization: 'white' } as const;

describe('the plots of a stack of films', () => {
  it('a stack of one soap layer plots the single film’s R(λ), eq (13)', () => {
    const film = { ...SOAP_FILM_IN_AIR, thicknessNm: 420, angleDeg: 30 };
    const s = filmSpectrum({ ...film, layers: [{ n: 1.33, thicknessNm: 420 }] }, 'D65', 'unpolarized');
    expect(s.layerCount).toBe(1);
    expect(s.filmIndex).toBeNull();
    for (const i of [0, 100, 175, 450])
      expect(Math.abs(s.reflectance[i]! - filmReflectance(s.lambdasNm[i]!, film))).toBeLessThan(ALGEBRAIC_TOL);
  });

  it("a layer of thickness d takes the probe's thickness; the others keep theirs", () => {
    const film = { nOutside: 1, nFilm: 1.33, nInside: 1.52, thicknessNm: 250, angleDeg: 20 };
    const s = filmSpectrum(
      {
        ...film,
        layers: [
          { n: 2.1, thicknessNm: 'd' },
          { n: 1.38, thicknessNm: 100 },
        ],
      },
      'D65',
      's',
    );
    const resolved = {
      nOutside: 1,
      nInside: 1.52,
      angleDeg: 20,
      films: [
        { n: 2.1, thicknessNm: 250 },
        { n: 1.38, thicknessNm: 100 },
      ],
    };
    for (const i of [0, 170, 450])
      expect(Math.abs(s.reflectance[i]! - layersReflectance(s.lambdasNm[i]!, resolved, 's'))).toBeLessThan(FEW_OPERATIONS_TOL);
  });

  it("the mirror's spectrum is its stack's (16 layers), highest near its design wavelength, and an empty list is the single film", () => {
    const p = STACK_PRESETS.braggMirror;
    const film = { nOutside: p.nOutside, nFilm: 1.33, nInside: p.nInside, thicknessNm: 300, angleDeg: 0 };
    const s = filmSpectrum({ ...film, layers: p.films }, 'D65', 'unpolarized');
    expect(s.layerCount).toBe(16);
    expect(s.reflectance[DESIGN_NM - 380]!).toBeGreaterThan(0.99);
    const single = filmSpectrum({ ...film, layers: [] }, 'D65', 'unpolarized');
    expect(single.layerCount).toBe(0);
    expect(Math.abs(single.reflectance[100]! - filmReflectance(480, { ...film, nInside: 1.52 }))).toBeLessThan(FEW_OPERATIONS_TOL);
  });

  it("the probed colour of a one-layer stack is the paper's film's XYZ (eqs 15–18 over eq 13's R), the transfer matrix's to rounding", () => {
    const p = STACK_PRESETS.arCoating;
    const film = { nOutside: 1, nFilm: 1.33, nInside: p.nInside, thicknessNm: 500, angleDeg: 10, layers: p.films };
    const layer = { n: 1.38, thicknessNm: p.films[0]!.thicknessNm as number };
    const xyz = filmXyz({ nOutside: 1, nFilm: layer.n, nInside: p.nInside, thicknessNm: layer.thicknessNm, angleDeg: 10 }, LIGHT);
    const c = probeColor(film, LIGHT, XYZ_TO_LINEAR_SRGB, xyz);
    c.xyz.forEach((v, i) => expect(Math.abs(v - xyz[i]!)).toBeLessThan(FEW_OPERATIONS_TOL));
    expect(c.deltaE00).toBeLessThan(FEW_OPERATIONS_TOL);
    const recursion = layersXyz({ nOutside: 1, nInside: p.nInside, angleDeg: 10, films: [layer] }, LIGHT);
    c.xyz.forEach((v, i) => expect(Math.abs(v - recursion[i]!)).toBeLessThan(ALGEBRAIC_TOL));
  });

  it('the scale of a stack that does not follow the field is one colour; one with a d layer changes along it', () => {
    const options = { ...LIGHT, xyzToLinearRgb: XYZ_TO_LINEAR_SRGB };
    const base = { nOutside: 1, nFilm: 1.33, nInside: 1.52, angleDeg: 0 };
    const fixed = interferenceScale({ ...base, layers: [{ n: 1.38, thicknessNm: 100 }] }, 600, 4, options);
    expect(new Set(fixed.map((c) => c.xyz.join()))).toHaveProperty('size', 1);
    const following = interferenceScale({ ...base, layers: [{ n: 1.38, thicknessNm: 'd' }] }, 600, 4, options);
    expect(new Set(following.map((c) => c.xyz.join())).size).toBe(4);
  });

  it('the sentence for a screen reader says the film is a stack', () => {
    const reading = { thicknessNm: 300, angleDeg: 0, renderedXyz: [0.1, 0.1, 0.1] as const };
    const stack = { ...DEFAULT_SETTINGS, layers: STACK_PRESETS.braggMirror.films };
    expect(probeDescription(stack, [0.5, 0.5], reading, EN)).toContain('A stack of 16 layers');
    expect(probeDescription(DEFAULT_SETTINGS, [0.5, 0.5], reading, EN)).not.toContain('stack');
  });
});
