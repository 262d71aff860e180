import { describe, expect, it } from 'vitest';
import { EN } from '../../../src/i18n/en.ts';
import { JA } from '../../../src/i18n/ja.ts';
import { catalogueFor, message } from '../../../src/i18n/messages.ts';

/** `{name}` marks: values filled in when shown (attribute names, numbers), not words of the language. */
const MARKS = /\{\w+\}/g;
const marksOf = (text: string) => [...text.matchAll(MARKS)].map((m) => m[0]).sort();

/**
 * Latin letters a Japanese text may hold: units and the symbols of the equations (r_ab, n_b, θri,
 * e^{iφ}, cos, Re/Im …). Runs of one or two letters are symbols; longer runs must be listed here.
 */
const SYMBOLS = new Set(['nm', 'cos']);

describe('the text catalogues', () => {
  it('have the same keys in every language, each with the same {marks}', () => {
    expect(Object.keys(JA).sort()).toEqual(Object.keys(EN).sort());
    for (const key of Object.keys(EN) as (keyof typeof EN)[]) expect(marksOf(JA[key]), key).toEqual(marksOf(EN[key]));
  });

  it('hold no English word in Japanese beyond units and symbols', () => {
    for (const [key, text] of Object.entries(JA)) {
      const words = (text.replace(MARKS, '').match(/[A-Za-z]+/g) ?? []).filter((w) => w.length > 2 && !SYMBOLS.has(w));
      expect(words, key).toEqual([]);
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
