import { describe, expect, it } from 'vitest';
import { EN } from '../../../src/i18n/en.ts';
import { JA } from '../../../src/i18n/ja.ts';
import { catalogueFor, message } from '../../../src/i18n/messages.ts';
import { expectationText } from '../../../src/settings/parameterRow.ts';
import { VIEW_PARAMETERS } from '../../../src/settings/viewParameters.ts';
import { englishLeftIn } from '../../latinInJapanese.ts';

/** `{name}` marks: values filled in when shown (attribute names, numbers), not words of the language. */
const MARKS = /\{\w+\}/g;
const marksOf = (text: string) => [...text.matchAll(MARKS)].map((m) => m[0]).sort();

describe('the text catalogues', () => {
  it('have the same keys in every language, each with the same {marks}', () => {
    expect(Object.keys(JA).sort()).toEqual(Object.keys(EN).sort());
    // A refusal in Japanese leaves out the English detail of what was wrong ({problem}): its range says what is allowed.
    const subset = new Set(['refusal.ignoredProblem', 'panel.notTaken']);
    for (const key of Object.keys(EN) as (keyof typeof EN)[])
      if (subset.has(key)) expect(marksOf(EN[key]), key).toEqual(expect.arrayContaining(marksOf(JA[key])));
      else expect(marksOf(JA[key]), key).toEqual(marksOf(EN[key]));
  });

  it('say what each schema row accepts as the row says it in English (one wording, two sources checked)', () => {
    for (const row of VIEW_PARAMETERS) expect(expectationText(row.expects, EN), row.url).toBe(row.expected);
  });

  it('label every schema row and every choice the panel lists', () => {
    for (const row of VIEW_PARAMETERS) {
      expect(EN, row.key).toHaveProperty([`param.${row.key}`]);
      const control = row.control;
      if (control?.kind === 'choice')
        for (const c of control.choices) expect(EN, `${row.key}=${c}`).toHaveProperty([`choice.${row.key}.${c}`]);
    }
  });

  it('hold no English word in Japanese beyond units and symbols', () => {
    for (const [key, text] of Object.entries(JA)) {
      expect(englishLeftIn(text.replace(MARKS, '')), key).toEqual([]);
      expect(/[\u3000-\u30ff\u4e00-\u9fff\uff00-\uffef]/.test(text) || text.replace(MARKS, '').length <= 4, `${key} has no Japanese`).toBe(
        true,
      );
    }
  });

  it("use the paper's terms", () => {
    const all = Object.values(JA).join('');
    for (const term of ['薄膜干渉', '膜厚', '屈折率', '入射角', '反射率', '等色関数', '色空間', '光源', '偏光'])
      expect(all).toContain(term);
  });

  it('are chosen by a lang value, English for a language without one, and fill in marks', () => {
    expect(catalogueFor('ja')).toBe(JA);
    expect(catalogueFor('ja-JP')).toBe(JA);
    expect(catalogueFor('en-GB')).toBe(EN);
    expect(catalogueFor('fr')).toBe(EN);
    expect(catalogueFor('')).toBe(EN);
    expect(catalogueFor('constructor')).toBe(EN);
    expect(message(EN, 'diagram.mediumA', { n: 1.5 })).toBe('medium a: n_a = 1.5');
    expect(message(JA, 'diagram.mediumA')).toBe('媒質 a：n_a = {n}');
  });
});
