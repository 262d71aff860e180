import { describe, expect, it } from 'vitest';
import { readStackField } from '../../../src/app/stackField.ts';
import { EN } from '../../../src/i18n/en.ts';
import { JA } from '../../../src/i18n/ja.ts';
import { VIEW_PARAMETERS } from '../../../src/settings/viewParameters.ts';

const row = VIEW_PARAMETERS.find((r) => r.key === 'layers')!;
const LAST = [{ n: 1.5, thicknessNm: 100 }] as const;

describe("the panel's layers text field", () => {
  it('is a text field in the film folder', () => {
    expect(row.control).toEqual({ folder: 'film', kind: 'stack' });
  });

  it('takes a stack, and the empty text as the single film, with no title', () => {
    expect(readStackField(row, '(2.35:56.6/1.46:91.1)*2', LAST, EN)).toEqual({
      films: [
        { n: 2.35, thicknessNm: 56.6 },
        { n: 1.46, thicknessNm: 91.1 },
        { n: 2.35, thicknessNm: 56.6 },
        { n: 1.46, thicknessNm: 91.1 },
      ],
      title: '',
    });
    expect(readStackField(row, '', LAST, EN)).toEqual({ films: [], title: '' });
  });

  it('keeps the last good stack for a bad text and says why in its title, as the Cauchy field does', () => {
    for (const [text, rule] of [
      ['(1.5:1', 'unbalanced parentheses'],
      ['(1.5:1)*0', 'not an integer in [1, 64]'],
      ['1.5:99999', 'is not a number in [0, 20000] nm or d'],
      ['gold:10', 'not a medium a film takes'],
    ] as const) {
      const reading = readStackField(row, text, LAST, EN);
      expect(reading.films, text).toBe(LAST);
      expect(reading.title, text).toBe(`not taken: ${row.problem!(text)!}`);
      expect(reading.title, text).toContain(rule);
      // The Japanese catalogue's message leaves out the English detail.
      expect(readStackField(row, text, LAST, JA)).toEqual({ films: LAST, title: JA['panel.notTaken'] });
    }
  });
});
