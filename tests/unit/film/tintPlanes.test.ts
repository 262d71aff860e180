/**
 * A tint in a film's three colour planes is a colour its environment matrix maps: the planes, the
 * table's key and the bin weights are those of the untinted light, so a change of tint changes none
 * of them. One plane (a material's film, or the untinted light's white) is computed under the tinted light.
 */
import { describe, expect, it } from 'vitest';
import { tableKey } from '../../../src/film/filmTable.ts';
import { releaseSpectralBinsTexture, spectralBinsTexture } from '../../../src/film/spectralBinsTexture.ts';
import { WHITE_TINT, type LightTint } from '../../../src/physics/lightTint.ts';
import { lightWeights, planeLights } from '../../../src/physics/spectralWeights.ts';
import { filmPlanes } from '../../../src/settings/filmLight.ts';
import { DEFAULT_SETTINGS } from '../../../src/settings/filmParameters.ts';
import type { FilmSettings } from '../../../src/settings/filmSettings.ts';

const TINT: LightTint = [1, 0.5, 0.2];
const film = (over: Partial<FilmSettings>): FilmSettings => ({ ...DEFAULT_SETTINGS, ...over });

describe("a tint and a film's colour planes", () => {
  it('three planes wherever the walls reflect a coloured environment or a tinted light; one for the untinted white and for a film with no environment', () => {
    expect(filmPlanes(film({ env: 'none' }))).toBe(1);
    expect(filmPlanes(film({ env: 'none', lightTint: TINT }))).toBe(3);
    expect(filmPlanes(film({ env: 'sky' }))).toBe(3);
    expect(filmPlanes({ lightTint: TINT })).toBe(1);
  });

  it("three planes' lights are the untinted light's times each basis spectrum, whatever the tint; one plane's is the tinted light", () => {
    const light = { illuminant: 'FL2', normalization: 'white', lightTint: TINT } as const;
    const untinted = planeLights({ ...light, lightTint: WHITE_TINT }, 3).map(lightWeights);
    expect(planeLights(light, 3).map(lightWeights)).toEqual(untinted);
    const [tinted] = planeLights(light, 1).map(lightWeights);
    const [white] = planeLights({ ...light, lightTint: WHITE_TINT }, 1).map(lightWeights);
    // Blue is scaled by the tint's 0.2 at short wavelengths: the tinted light's z̄ weights are far below the white's.
    expect(tinted!.z.reduce((a, b) => a + b, 0)).toBeLessThan(0.5 * white!.z.reduce((a, b) => a + b, 0));
  });

  it("a change of tint in three planes keeps the table's key and the bin texture; in one plane it changes both", () => {
    for (const env of ['sky', 'none'] as const) {
      const a = film({ env, lightTint: [0.9, 0.8, 0.7] });
      const b = film({ env, lightTint: TINT });
      expect(tableKey(a, 800), env).toBe(tableKey(b, 800));
      const holder = {};
      expect(spectralBinsTexture(a, 90, holder, filmPlanes(a))).toBe(spectralBinsTexture(b, 90, holder, filmPlanes(b)));
      releaseSpectralBinsTexture(holder);
    }
    const material = { ...film({}), env: undefined };
    expect(tableKey({ ...material, lightTint: TINT }, 800)).not.toBe(tableKey(material, 800));
    const holder = {};
    expect(spectralBinsTexture({ ...material, lightTint: TINT }, 90, holder, 1)).not.toBe(spectralBinsTexture(material, 90, holder, 1));
    releaseSpectralBinsTexture(holder);
  });
});
