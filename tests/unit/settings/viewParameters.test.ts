import { describe, expect, it } from 'vitest';
import { DEFAULT_VIEW_SETTINGS, VIEW_PARAMETERS } from '../../../src/settings/viewParameters.ts';

describe('the parameter schema', () => {
  it('names each parameter once in the URL, as an attribute and as a flag of the command-line tools', () => {
    for (const names of [VIEW_PARAMETERS.map((r) => r.url), VIEW_PARAMETERS.map((r) => r.attribute), VIEW_PARAMETERS.map((r) => r.flag)]) {
      expect(new Set(names).size).toBe(names.length);
    }
    // HTML lower-cases attribute names, so an observed attribute must be written in lower case.
    for (const row of VIEW_PARAMETERS) expect(row.attribute).toBe(row.attribute.toLowerCase());
  });

  it('spells each flag as its URL name in kebab case: lower-case words joined by hyphens, camel case back', () => {
    const byUrl = Object.fromEntries(VIEW_PARAMETERS.map((r) => [r.url, r.flag]));
    expect(byUrl).toMatchObject({ thickness: 'thickness', thicknessRange: 'thickness-range', nFilm: 'n-film', windTurn: 'wind-turn' });
    for (const row of VIEW_PARAMETERS) {
      expect(row.flag, row.url).toMatch(/^[a-z0-9]+(-[a-z0-9]+)*$/);
      expect(
        row.flag.replace(/-([a-z])/g, (_, c: string) => c.toUpperCase()),
        row.url,
      ).toBe(row.url);
    }
  });

  it('reads each default back from the text the URL writes for it', () => {
    for (const row of VIEW_PARAMETERS) {
      expect(row.read(row.defaultText), row.url).toEqual({ [row.key]: DEFAULT_VIEW_SETTINGS[row.key] });
      expect(row.write(DEFAULT_VIEW_SETTINGS), row.url).toBe(row.defaultText);
    }
  });

  it('gives every slider the range the URL accepts: both ends read, one step beyond is refused', () => {
    const sliders = VIEW_PARAMETERS.filter((r) => r.control?.kind === 'slider');
    expect(sliders.length).toBeGreaterThan(5);
    for (const row of sliders) {
      const c = row.control as { min: number; max: number; step: number };
      expect(row.read(String(c.min)), row.url).not.toBeNull();
      expect(row.read(String(c.max)), row.url).not.toBeNull();
      expect(row.read(String(c.max + Math.max(c.step, 1))), row.url).toBeNull();
      expect(row.read(String(c.min - Math.max(c.step, 1))), row.url).toBeNull();
    }
  });

  it('offers in each choice control exactly the values the URL accepts', () => {
    for (const row of VIEW_PARAMETERS) {
      if (row.control?.kind !== 'choice') continue;
      for (const choice of row.control.choices) expect(row.read(choice), row.url).toEqual({ [row.key]: choice });
      expect(row.expected).toBe(`one of ${row.control.choices.join(', ')}`);
    }
  });
});
