/** docs/flow.md's cost of the flowing film is what the code draws now (npm run docs writes it). */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { gridCost, flowCostMarkdown } from '../../../scripts/docs/flowCost.ts';
import { withBlock } from '../../../scripts/docs/withBlock.ts';
import { faceAtlasSize } from '../../../src/flow/flowAtlas.ts';
import { HALO_TAP_TEXELS } from '../../../src/flow/flowGridTextures.ts';

const flowDoc = readFileSync(new URL('../../../docs/flow.md', import.meta.url), 'utf8');

describe("docs/flow.md's cost of a step", () => {
  it('holds the tables counted from the passes as the app draws them (npm run docs writes them)', { timeout: 120_000 }, () => {
    expect(withBlock(flowDoc, 'flow-cost', flowCostMarkdown())).toBe(flowDoc);
  });

  it('counts a frame as its whole steps and one halo pass for the bubble, three fetches per halo tap texel', { timeout: 60_000 }, () => {
    const n = 16;
    const cost = gridCost(n);
    const padded = faceAtlasSize(n + 2);
    const haloTexels = padded.width * padded.height;
    expect(Number.isInteger(cost.stepsPerFrame)).toBe(true);
    expect(cost.frame.draws).toBe(cost.stepsPerFrame * cost.step.draws + 1);
    expect(cost.frame.fragments).toBe(cost.stepsPerFrame * cost.step.fragments + haloTexels);
    // A halo texel reads its HALO_TAP_TEXELS tap texels and the two cells each names.
    expect(cost.frame.fetches).toBe(cost.stepsPerFrame * cost.step.fetches + haloTexels * 3 * HALO_TAP_TEXELS);
  });
});
