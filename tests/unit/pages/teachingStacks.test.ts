import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { layersText, readLayers } from '../../../src/physics/stackText.ts';
import { braggMirrorLayers } from '../../../src/physics/stackPresets.ts';

/** The `layers` attributes of a page's bubbles. */
const layersOf = (path: string): string[] => [...readFileSync(path, 'utf8').matchAll(/\slayers="([^"]*)"/g)].map((m) => m[1]!);

/** The named mirror with `periods` pairs, its thicknesses to 0.1 nm as the page writes them. */
const mirrorText = (periods: number): string =>
  layersText(braggMirrorLayers(periods).map((l) => ({ ...l, thicknessNm: Math.round((l.thicknessNm as number) * 10) / 10 })));

describe('the teaching pages’ stacks', () => {
  for (const page of ['public/teaching.html', 'public/teaching.ja.html'])
    it(`${page} shows the named mirror (stackPresets.ts) with 1, 2, 4 and 8 pairs, each a valid layers text`, () => {
      const texts = layersOf(page);
      for (const text of texts) expect(readLayers(text), text).toHaveProperty('films');
      expect(new Set(texts)).toEqual(new Set([1, 2, 4, 8].map(mirrorText)));
    });
});
