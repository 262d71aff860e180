/**
 * The spectral material as a three.js user drives it, drawn (tests/e2e/material.spec.ts): a
 * material chained through two other onBeforeCompile users; an option change and back between two
 * frames; its clone and its JSON loaded back by three's MaterialLoader; an out-of-range value set
 * on the loaded one. Only public API: what the users' hooks were handed, `version`, `dispose`
 * events, `renderer.info`, the pixels.
 */
import { MaterialLoader, type MeshPhysicalMaterial } from 'three';
import { spectralIridescence } from '../../../src/meshMaterial/spectralIridescence.ts';
import { ThinFilmMaterial } from '../../../src/meshMaterial/thinFilmMaterial.ts';
import { type FilmCase, disposeAll, filmMaterial, filmScene } from './filmCaseScene.ts';
import { centre, draw, renderer } from './materialScene.ts';

/**
 * The pixels and what was seen of film case `c` in table mode; `ior.given` is set out of the
 * film's range, `ior.drawn` the end of the range it is to be drawn with.
 */
export function threeJsUserPixels(c: FilmCase, ior: { readonly given: number; readonly drawn: number }) {
  const ran: string[] = [];
  let uniforms: Record<string, { value: unknown }> = {};
  const m = filmMaterial(c);
  m.onBeforeCompile = (shader) => {
    ran.push('first');
    shader.defines = { ...shader.defines, TFC_FIRST_USER: 1 };
  };
  const film = spectralIridescence(m, { mode: 'table' });
  // three's chaining idiom: the hook read is called on the material.
  // eslint-disable-next-line @typescript-eslint/unbound-method
  const previous = film.onBeforeCompile;
  film.onBeforeCompile = (shader, r) => {
    previous.call(film, shader, r);
    ran.push('second');
    // The uniforms three hands every onBeforeCompile: the film's, its table among them, are added to them after the users' edits.
    uniforms = shader.uniforms;
    shader.fragmentShader = `// the second user's edit\n${shader.fragmentShader}`;
  };
  const { scene, camera, box } = filmScene(c, film);
  const chained = centre(draw(scene, camera));
  const filmTable = (): unknown => uniforms.uFilmTable?.value ?? null;
  const table = filmTable();

  // An option change and back between frames: two new versions, the same program and table, no dispose event.
  const disposed: string[] = [];
  film.addEventListener('dispose', () => disposed.push('material'));
  const [version, programs] = [film.version, renderer.info.programs?.length ?? 0];
  film.mode = 'fourier';
  film.mode = 'table';
  const changed = centre(draw(scene, camera));
  const change = {
    versions: film.version - version,
    programs: (renderer.info.programs?.length ?? 0) - programs,
    sameTable: table !== null && filmTable() === table,
    disposed: [...disposed],
  };

  // Its clone, and its JSON (written as text) loaded back by three's MaterialLoader.
  MaterialLoader.registerMaterial(ThinFilmMaterial.type, ThinFilmMaterial);
  const clone = film.clone();
  box.material = clone;
  const cloned = centre(draw(scene, camera));
  const loaded = new MaterialLoader().parse(JSON.parse(JSON.stringify(film.toJSON())) as never) as MeshPhysicalMaterial;
  box.material = loaded;
  const load = { isThinFilmMaterial: loaded instanceof ThinFilmMaterial, pixel: centre(draw(scene, camera)) };

  // Out of range, set on the loaded material and drawn twice: one warning, the domain's end drawn, nothing thrown.
  loaded.iridescenceIOR = ior.drawn;
  const atDomainEnd = centre(draw(scene, camera));
  loaded.iridescenceIOR = ior.given;
  let thrown = '';
  let outOfRange: number[] = [];
  try {
    draw(scene, camera);
    outOfRange = centre(draw(scene, camera));
  } catch (e) {
    thrown = String(e);
  }
  film.dispose();
  clone.dispose();
  disposeAll(scene);
  return { ran, chained, change, changed, cloned, load, atDomainEnd, outOfRange, thrown };
}
