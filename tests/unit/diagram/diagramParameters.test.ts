import { describe, expect, it } from 'vitest';
import { type Catalogue, EN } from '../../../src/i18n/en.ts';
import { JA } from '../../../src/i18n/ja.ts';
import { FILM_STACK_DOMAIN } from '../../../src/physics/filmReflectance.ts';
import { DEFAULT_DIAGRAM_SETTINGS, DIAGRAM_ATTRIBUTES, readDiagramAttributes } from '../../../src/diagram/diagramParameters.ts';

const read = (attributes: Record<string, string>, catalogue: Catalogue = EN) =>
  readDiagramAttributes((a) => attributes[a] ?? null, DEFAULT_DIAGRAM_SETTINGS, catalogue);

describe("the diagram's attributes", () => {
  it('are the documented ones, read as the bubble reads them', () => {
    expect([...DIAGRAM_ATTRIBUTES].sort()).toEqual(['angle', 'nfilm', 'ninside', 'noutside', 'polarization', 'thickness', 'wavelength']);
    const { settings, errors } = read({
      thickness: '420',
      angle: '12.5',
      wavelength: '380',
      nfilm: 'water',
      noutside: '1.2',
      polarization: 'paper',
    });
    expect(errors).toEqual([]);
    expect(settings).toMatchObject({
      thicknessNm: 420,
      angleDeg: 12.5,
      wavelengthNm: 380,
      nFilm: 'water',
      nOutside: 1.2,
      polarization: 'paper',
    });
  });

  it('refuse a bad value, naming the attribute and its range, and keep the earlier value', () => {
    const { settings, errors } = read({ thickness: '20001', angle: 'NaN', wavelength: '379', polarization: 'circular', nfilm: '5' });
    expect(settings).toEqual(DEFAULT_DIAGRAM_SETTINGS);
    const max = FILM_STACK_DOMAIN.thicknessNm.max;
    expect(errors).toEqual([
      `thickness="20001" is not allowed: expected a number from 0 to ${max} nm.`,
      'angle="NaN" is not allowed: expected a number from 0 to 90°.',
      'wavelength="379" is not allowed: expected a number from 380 to 830 nm.',
      'nfilm="5" is not allowed: expected a number from 1 to 4, water, or cauchy:A,B[,C] staying within that range.',
      'polarization="circular" is not allowed: expected one of unpolarized, paper, s, p.',
    ]);
    expect(read({ ninside: '0.5' }, JA).errors).toEqual(['ninside="0.5" は使えない：1 から 4 までの数値を指定すること。']);
  });
});
