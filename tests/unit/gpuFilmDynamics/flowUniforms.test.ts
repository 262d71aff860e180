/**
 * The flow's uniforms by name: every pass's material sets exactly the uniforms its assembled GLSL
 * declares, each set's factory exactly those its file declares, and each uniform is declared in one
 * file of shaders/gpuFilmDynamics/ only. Uniforms parsed from the GLSL are the independent side: a name the
 * shader declares that no factory sets would read 0 on the GPU, silently.
 */
import { readFileSync, readdirSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { declaredUniforms } from '../gpu/glslUniforms.ts';
import { cubeSphereGrid } from '../../../src/physics/filmDynamics/cubeSphereGrid.ts';
import { cubeSphereHalo } from '../../../src/physics/filmDynamics/cubeSphereSampler.ts';
import { flowNumbers } from '../../../src/physics/filmDynamics/flowNumbers.ts';
import { validateFlowParameters } from '../../../src/physics/filmDynamics/flowParameters.ts';
import { flowGridTextures } from '../../../src/gpuFilmDynamics/flowGridTextures.ts';
import { PASSES, passMaterials } from '../../../src/gpuFilmDynamics/flowPasses.ts';
import { FLOW_UNIFORM_SETS, type FlowUniformInputs, flowUniformSets } from '../../../src/gpuFilmDynamics/flowUniforms.ts';

const flowDir = new URL('../../../shaders/gpuFilmDynamics/', import.meta.url);
const flowFiles = readdirSync(flowDir).filter((f) => f.endsWith('.glsl'));
const ownText = (file: string): string => readFileSync(new URL(file, flowDir), 'utf8');

const parameters = validateFlowParameters({ gridN: 4 });
const grid = cubeSphereGrid(parameters.gridN);
const inputs: FlowUniformInputs = {
  parameters,
  numbers: flowNumbers(parameters),
  grid,
  dt: 1e-3,
  transportSubsteps: 2,
  renewSteps: 0,
  textures: flowGridTextures(grid, cubeSphereHalo(grid)),
};

describe('flow uniforms', () => {
  it('the parse finds a declaration with a precision and an array, and not a comment', () => {
    expect(declaredUniforms('uniform highp float uA;\n  uniform mat3 uB[6];\n// uniform float uC;\n * uniform float uD;')).toEqual([
      'uA',
      'uB',
    ]);
  });

  it("each pass's material sets exactly the uniforms its shader declares, includes and all", () => {
    const materials = passMaterials(flowUniformSets(inputs));
    expect(Object.keys(materials).sort()).toEqual(Object.keys(PASSES).sort());
    for (const [pass, material] of Object.entries(materials)) {
      const declared = [...new Set(declaredUniforms(material.fragmentShader))].sort();
      expect(declared.length, pass).toBeGreaterThan(0);
      expect(Object.keys(material.uniforms).sort(), pass).toEqual(declared);
    }
  });

  it('the passes share each uniform: a value set for one pass is the value every other pass reads', () => {
    const { predict, flux, emptyHoles, burstSteps } = passMaterials(flowUniformSets(inputs));
    expect(predict.uniforms.uDt).toBe(flux.uniforms.uDt);
    expect(predict.uniforms.uFilm).toBe(emptyHoles.uniforms.uFilm);
    expect(emptyHoles.uniforms.uHoles).toBe(burstSteps.uniforms.uHoles);
  });

  it("each set's factory makes exactly the uniforms its own file declares", () => {
    for (const [file, make] of Object.entries(FLOW_UNIFORM_SETS)) {
      expect(Object.keys(make(inputs)).sort(), file).toEqual(declaredUniforms(ownText(file)).sort());
    }
  });

  it('each uniform of shaders/gpuFilmDynamics/ is declared in one file, and every file that declares one is a set', () => {
    const declaring = new Map<string, string[]>();
    for (const file of flowFiles)
      for (const name of declaredUniforms(ownText(file))) declaring.set(name, [...(declaring.get(name) ?? []), file]);
    expect(declaring.size).toBeGreaterThan(30);
    expect([...declaring].filter(([, files]) => files.length > 1)).toEqual([]);
    const setFiles = Object.keys(FLOW_UNIFORM_SETS);
    expect([...new Set([...declaring.values()].flat())].filter((f) => !setFiles.includes(f))).toEqual([]);
  });
});
