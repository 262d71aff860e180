import { describe, expect, it } from 'vitest';
import { HDR_ENVIRONMENTS, TONE_MAPPINGS, toneMappingOf } from '../../../src/settings/filmSettings.ts';

describe('the tone mapping a view uses', () => {
  it('auto: none for none, the sky and a uniform colour (no curve bends the reflection of one known light), AgX for every HDR map', () => {
    for (const env of ['none', 'sky', { color: [4, 4, 4] }, { color: [0, 0.2, 1] }] as const)
      expect(toneMappingOf({ tonemap: 'auto', env }), JSON.stringify(env)).toBe('none');
    for (const env of HDR_ENVIRONMENTS) expect(toneMappingOf({ tonemap: 'auto', env }), env).toBe('agx');
  });

  it('a given one as given, in every environment', () => {
    for (const tonemap of TONE_MAPPINGS.filter((t) => t !== 'auto'))
      for (const env of ['none', 'park', { color: [1, 0.2, 0.2] }] as const) expect(toneMappingOf({ tonemap, env })).toBe(tonemap);
  });
});
