/** docs/flow.md's cost of the flowing film is what the code draws now (npm run docs writes it). */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { gridCost, flowCostMarkdown } from '../../../scripts/docs/flowCost.ts';
import { withBlock } from '../../../scripts/docs/withBlock.ts';
import { faceAtlasSize } from '../../../src/gpuFilmDynamics/flowAtlas.ts';
import { HALO_TAP_TEXELS } from '../../../src/gpuFilmDynamics/flowGridTextures.ts';

const flowDoc = readFileSync(new URL('../../../docs/flow.md', import.meta.url), 'utf8');

describe("docs/flow.md's cost of a step", () => {
  it('holds the tables counted from the passes as the app draws them (npm run docs writes them)', { timeout: 120_000 }, () => {
    expect(withBlock(flowDoc, 'flow-cost', flowCostMarkdown())).toBe(flowDoc);
  });

  it(
    'counts a frame as its steps (a mean over the frames) and one halo pass for the bubble, three fetches per halo tap texel',
    { timeout: 60_000 },
    () => {
      // A grid at which every frame takes steps (about 2 at 60 Hz): a frame that takes none draws no halo either.
      const n = 64;
      const cost = gridCost(n);
      expect(cost.stepsPerFrame).toBeGreaterThan(1);
      const padded = faceAtlasSize(n + 2);
      const haloTexels = padded.width * padded.height;
      // Whole steps over the frames: a multiple of 1/60 (the frames counted, one second at 60 Hz).
      expect(Math.abs(cost.stepsPerFrame * 60 - Math.round(cost.stepsPerFrame * 60))).toBeLessThan(1e-9);
      const [draws, fragments, fetches] = [
        cost.stepsPerFrame * cost.step.draws + 1,
        cost.stepsPerFrame * cost.step.fragments + haloTexels,
        // A halo texel reads its HALO_TAP_TEXELS tap texels and the two cells each names.
        cost.stepsPerFrame * cost.step.fetches + haloTexels * 3 * HALO_TAP_TEXELS,
      ];
      expect(Math.abs(cost.frame.draws / draws - 1)).toBeLessThan(1e-12);
      expect(Math.abs(cost.frame.fragments / fragments - 1)).toBeLessThan(1e-12);
      expect(Math.abs(cost.frame.fetches / fetches - 1)).toBeLessThan(1e-12);
    },
  );
});
