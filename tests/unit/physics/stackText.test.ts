import { describe, expect, it } from 'vitest';
import { FIELD_THICKNESS, type FilmLayer } from '../../../src/physics/stackFilms.ts';
import { LAYERS_EXPECTED, layersText, parseLayers, readLayers } from '../../../src/physics/stackText.ts';
import { type Medium } from '../../../src/physics/medium.ts';
import { NAMED_MEDIA } from '../../../src/physics/namedMedia.ts';
import { ParameterError } from '../../../src/input/validate.ts';
import { mulberry32 } from '../../seededRandom.ts';

const layers = (text: string): readonly FilmLayer[] => parseLayers('layers', text);

describe('the layers text', () => {
  it('reads entries INDEX:THICKNESS from the outside in, every medium a film takes', () => {
    expect(layers('1.46:100/water:d/cauchy:1.45,6000:50.5/TiO2:0/complex:0.2,3.4:20000')).toEqual([
      { n: 1.46, thicknessNm: 100 },
      { n: 'water', thicknessNm: FIELD_THICKNESS },
      { n: { cauchy: [1.45, 6000, 0] }, thicknessNm: 50.5 },
      { n: 'TiO2', thicknessNm: 0 },
      { n: { complex: [0.2, 3.4] }, thicknessNm: 20000 },
    ]);
    expect(layers('cauchy:1.6,10000,-3e8:1e2')).toEqual([{ n: { cauchy: [1.6, 1e4, -3e8] }, thicknessNm: 100 }]);
  });

  it('repeats a group N times, groups nested, the count the product of the repeats', () => {
    const mirror = layers('(2.35:56.6/1.46:91.1)*8');
    expect(mirror).toHaveLength(16);
    mirror.forEach((l, i) => expect(l).toEqual(i % 2 === 0 ? { n: 2.35, thicknessNm: 56.6 } : { n: 1.46, thicknessNm: 91.1 }));
    expect(layers('1.38:d/(TiO2:50/SiO2:90)*3').map((l) => l.n)).toEqual(
      ['1.38', 'TiO2', 'SiO2', 'TiO2', 'SiO2', 'TiO2', 'SiO2'].map(asMedium),
    );
    // ((a)*2/b)*3/c: (2 + 1)·3 + 1 layers, in this order.
    const nested = layers('((1.5:1)*2/1.6:2)*3/1.7:3');
    expect(nested.map((l) => l.thicknessNm)).toEqual([1, 1, 2, 1, 1, 2, 1, 1, 2, 3]);
    expect(layers('(((1.5:1)*4)*4)*4')).toHaveLength(64);
    expect(layers('(1.5:1)*1')).toEqual([{ n: 1.5, thicknessNm: 1 }]);
  });

  it('ignores whitespace around every token', () => {
    expect(layers(' ( 1.5 : 10 /\twater : d ) * 2 / TiO2:5 ')).toEqual(layers('(1.5:10/water:d)*2/TiO2:5'));
  });

  it('prints a text that reads back into the same layers, a repeated block as (…)*N where that is shorter', () => {
    expect(layersText(layers('(2.35:56.6/1.46:91.1)*8'))).toBe('(2.35:56.6/1.46:91.1)*8');
    expect(layersText(layers('1.38:d/(TiO2:50/SiO2:90)*3'))).toBe('1.38:d/(TiO2:50/SiO2:90)*3');
    expect(layersText(layers('1.5:1/1.5:1'))).toBe('(1.5:1)*2');
    expect(layersText(layers('1.5:1/1.6:1/1.5:1'))).toBe('1.5:1/1.6:1/1.5:1');
    expect(layersText(layers('2.35:56.6/1.46:91.1/1.46:91.1'))).toBe('2.35:56.6/(1.46:91.1)*2');
    expect(layersText([])).toBe('');
  });

  it('round-trips random stacks: parse(print(x)) equals x, and printing is canonical', () => {
    const rand = mulberry32(20240611);
    const pick = <T>(xs: readonly T[]): T => xs[Math.floor(rand() * xs.length)]!;
    const medium = (): Medium =>
      pick<() => Medium>([
        () => 1 + 3 * rand(),
        () => +(1 + 3 * rand()).toFixed(2),
        () => 'water',
        () => pick(NAMED_MEDIA),
        () => ({ cauchy: [1.3 + 0.3 * rand(), 1e4 * rand(), rand() < 0.5 ? 0 : 1e8 * rand()] }),
        () => ({ complex: [0.01 + 3 * rand(), 5 * rand()] }),
      ])();
    const layer = (): FilmLayer => ({
      n: medium(),
      thicknessNm: pick<() => FilmLayer['thicknessNm']>([
        () => FIELD_THICKNESS,
        () => 0,
        () => 20000,
        () => 2e4 * rand(),
        () => Math.round(500 * rand()),
      ])(),
    });
    for (let i = 0; i < 2000; i++) {
      // A few distinct layers, repeated in blocks so the printer has runs to fold.
      const distinct = Array.from({ length: 1 + Math.floor(rand() * 4) }, layer);
      const x: FilmLayer[] = [];
      const size = 1 + Math.floor(rand() * 64);
      while (x.length < size) {
        const block = Array.from({ length: 1 + Math.floor(rand() * 3) }, () => pick(distinct));
        for (let r = 1 + Math.floor(rand() * 5); r > 0 && x.length + block.length <= size; r--) x.push(...block);
        if (x.length < size && x.length + block.length > size) x.push(pick(distinct));
      }
      const text = layersText(x);
      expect(layers(text), text).toEqual(x);
      expect(layersText(layers(text))).toBe(text);
      expect(text.length).toBeLessThanOrEqual(x.map((l) => layersText([l])).join('/').length);
    }
  });

  /** Each refusal's text and the words of the rule it breaks. */
  const REFUSALS: readonly [string, string][] = [
    ['', 'no layers'],
    ['   ', 'no layers'],
    ['(1.5:1)*64/1.5:1', 'more than 64 layers after repetition'],
    ['((1.5:1/1.6:2)*8)*5', 'more than 64 layers after repetition'],
    ['(((((((1.5:1)*64)*64)*64)*64)*64)*64)*64', 'more than 64 layers after repetition'],
    [Array.from({ length: 65 }, () => '1.5:1').join('/'), 'more than 64 layers after repetition'],
    ['1.5:-1', 'thickness "-1" is not a number in [0, 20000] nm or d'],
    ['1.5:20000.5', 'is not a number in [0, 20000] nm or d'],
    ['1.5:abc', 'is not a number in [0, 20000] nm or d'],
    ['1.5:', 'is not a number in [0, 20000] nm or d'],
    ['1.5:D', 'is not a number in [0, 20000] nm or d'],
    ['1.5:NaN', 'is not a number in [0, 20000] nm or d'],
    ['unobtainium:100', 'the index "unobtainium": not a medium a film takes'],
    [':100', 'not a medium a film takes'],
    ['9:100', 'n is 9, above 4'],
    ['complex:1.5,-1:100', 'k < 0'],
    ['1.5', 'the entry "1.5" has no :NM'],
    ['(1.5:1)*0', '*N with N "0", not an integer in [1, 64]'],
    ['(1.5:1)*-2', 'not an integer in [1, 64]'],
    ['(1.5:1)*65', 'not an integer in [1, 64]'],
    ['(1.5:1)*2.5', 'not an integer in [1, 64]'],
    ['(1.5:1)*', 'not an integer in [1, 64]'],
    ['(1.5:1)*x', 'not an integer in [1, 64]'],
    ['(1.5:1)*2 1.6:1', 'not an integer in [1, 64]'],
    ['(1.5:1', 'unbalanced parentheses: a "(" without its ")"'],
    ['((1.5:1)*2', 'unbalanced parentheses: a "(" without its ")"'],
    ['1.5:1)*2', 'unbalanced parentheses: a ")" without its "("'],
    ['(1.5:1)*2)*3', 'unbalanced parentheses: a ")" without its "("'],
    ['(1.5:1)', 'a group (…) must be followed by *N'],
    ['(1.5:1)/1.6:1', 'a group (…) must be followed by *N'],
    ['1.5:1*3', '*N may only follow a group in parentheses'],
    ['*3', '*N may only follow a group in parentheses'],
    ['1.5:1//1.6:1', 'an empty entry'],
    ['/1.5:1', 'an empty entry'],
    ['1.5:1/', 'an empty entry'],
    ['1.5:1/ /1.6:1', 'an empty entry'],
    ['()*2', 'an empty entry'],
    ['(1.5:1/)*2', 'an empty entry'],
    ['(1.5:1)*2(1.6:1)*2', 'entries must be separated by /'],
    ['1.5:1(1.6:1)*2', 'entries must be separated by /'],
  ];

  it.each(REFUSALS)('refuses %j, naming layers and the rule (%s)', (text, rule) => {
    const reading = readLayers(text);
    expect(Object.keys(reading)).toEqual(['problem']);
    expect((reading as { problem: string }).problem).toContain(rule);
    let error: unknown;
    try {
      parseLayers('layers', text);
    } catch (e) {
      error = e;
    }
    expect(error).toBeInstanceOf(ParameterError);
    expect((error as ParameterError).parameter).toBe('layers');
    expect((error as ParameterError).message).toMatch(/^layers: ".*"(… \(\d+ characters\))? is not allowed \(/);
    expect((error as ParameterError).message).toContain(rule);
    expect((error as ParameterError).message).toContain(`expected ${LAYERS_EXPECTED}`);
  });
});

/** A medium as its text reads (the named ones stay names, numbers become numbers). */
function asMedium(text: string): Medium {
  const n = Number(text);
  return Number.isFinite(n) ? n : (text as Medium);
}
