/**
 * The burst on the GPU: a pricked film opens a hole whose rim runs at the Taylor–Culick speed
 * √(2γ/(ρh)) × the rim-speed factor (γ = γ_a − R̄TΓ0, h the film's thickness, computed here from the
 * published constants), the same cells empty as in the float64 twin, and with `renew` a new bubble
 * follows. The hole's radius is read from the area the film has lost, A = 2π(1 − cos r) for a cap
 * of angular radius r, as the twin's test does. The user's burst in the demo (a double-click, P, the
 * panel's button) empties the cells the twin pricked at the same point and step empties.
 */
import type { Page } from '@playwright/test';
import { expect, test } from './fixtures.ts';
import { createFilmSimulation, punctureFilm, stepFilm } from '../../src/physics/filmDynamics/filmSimulation.ts';
import { nearestCell } from '../../src/physics/filmDynamics/cubeSphereSampler.ts';
import type { ViewSettings } from '../../src/settings/viewParameters.ts';
import { FLOW_BURST_DIFFERING_CELLS, FLOW_BURST_RAY_TOL, RIM_SPEED_REL_TOL } from '../tolerances.ts';
import { type Demo, type FilmReader, installFilmReader, paddedFilmCells } from './demoFlowFilm.ts';
import { openPanel } from './panel.ts';

/**
 * A surfactant-rich film (its settled profile varies by e^(±0.043): it hardly drains while the rim
 * runs) and a slowed rim (0.1 × Taylor–Culick, 0.25 rad a step at this film's 5.9 ms step), so the
 * burst spans steps.
 */
const [radiusMm, thicknessNm, surfactantMolM2, rimSpeedFactor] = [40, 500, 1e-6, 0.1];
const PRICKED = { gridN: 24, radiusMm, thicknessNm, surfactantMolM2, rimSpeedFactor };
const TOP: [number, number, number] = [0, 0, 1];
/** Steps after the prick at which the radius is read: past the first cells (0.5 rad), short of the bottom (2.2 rad). */
const [EARLY, LATE] = [2, 9];

type Run = Awaited<ReturnType<NonNullable<Window['runFlow']>>>;

const prickedRun = (page: Page, steps: number): Promise<Run> =>
  page.evaluate(([p, n, at]) => window.runFlow!(p, n, null, at), [PRICKED, steps, TOP] as const);

/** The angular radius of the cap with the area of the cells that have lost their film. */
function holeRadius(intact: ArrayLike<number>, area: Float64Array): number {
  let lost = 0;
  for (let c = 0; c < area.length; c++) lost += intact[c] === 0 ? area[c]! : 0;
  return Math.acos(Math.max(-1, 1 - lost / (2 * Math.PI)));
}

test('a pricked GPU film bursts at √(2γ/(ρh)) × the rim-speed factor, and empties the cells the twin empties', async ({
  parityPage: page,
}) => {
  const [early, late] = [await prickedRun(page, EARLY), await prickedRun(page, LATE)];
  const twin = createFilmSimulation(PRICKED);
  punctureFilm(twin, ...TOP);
  for (let k = 0; k < LATE; k++) stepFilm(twin);
  const { area } = twin.grid;
  const surfaceTension = 0.07275 - 8.3144598 * 298.15 * surfactantMolM2;
  const expected = rimSpeedFactor * Math.sqrt((2 * surfaceTension) / (997 * thicknessNm * 1e-9));
  const [r1, r2] = [holeRadius(early.intact, area), holeRadius(late.intact, area)];
  const speed = ((r2 - r1) * radiusMm * 1e-3) / ((LATE - EARLY) * twin.stepSeconds);
  // The rays themselves, all at one radius on a uniform film.
  const rays = late.holes[0]!.radius;
  const raySpeed = ((rays.reduce((s, r) => s + r, 0) / rays.length) * radiusMm * 1e-3) / (LATE * twin.stepSeconds);
  // Cells where the GPU and the twin differ lie within a cell (π/(2N) rad, 1.5 for the diagonal) of the twin's rim.
  const twinRim = twin.state.holes[0]!.radius[0]!;
  const cellRad = Math.PI / (2 * PRICKED.gridN);
  const differing = [...late.intact.keys()].filter((c) => late.intact[c] !== twin.state.intact[c]);
  const offRim = differing.filter((c) => Math.abs(Math.acos(Math.min(1, twin.grid.center[3 * c + 2]!)) - twinRim) > 1.5 * cellRad);
  const rayError = rays.reduce((w, r, k) => Math.max(w, Math.abs(r - twin.state.holes[0]!.radius[k]!)), 0);
  console.log(
    `GPU rim ${speed.toFixed(3)} m/s from the lost area, ${raySpeed.toFixed(3)} m/s from the rays, formula ${expected.toFixed(3)} m/s; ` +
      `against the twin: ${differing.length} of ${area.length} cells differ, rays by ${rayError.toExponential(2)} rad`,
  );
  expect(late.holes).toHaveLength(1);
  expect(r1).toBeGreaterThan(0.3);
  expect(r2).toBeLessThan(2.5);
  expect(Math.abs(speed / expected - 1)).toBeLessThan(RIM_SPEED_REL_TOL);
  expect(Math.abs(raySpeed / expected - 1)).toBeLessThan(RIM_SPEED_REL_TOL);
  late.intact.forEach((v, c) => {
    if (v === 0) expect([late.eta[c], late.gamma[c]]).toEqual([0, 0]);
  });
  expect(offRim).toEqual([]);
  expect(differing.length).toBeLessThanOrEqual(FLOW_BURST_DIFFERING_CELLS);
  expect(rayError).toBeLessThan(FLOW_BURST_RAY_TOL);
});

test('a GPU film thinned to the rupture thickness opens the holes the twin opens, where the twin opens them', async ({
  parityPage: page,
}) => {
  // Evaporation thins the whole film to the rupture thickness at once: many cells give way in one step.
  const thinning = { gridN: 6, thicknessNm: 40, ruptureThicknessNm: 39, evaporationNmS: 100 };
  const twin = createFilmSimulation(thinning);
  while (twin.state.holes.length === 0) stepFilm(twin);
  stepFilm(twin);
  const gpu = await page.evaluate(([p, n]) => window.runFlow!(p, n), [thinning, twin.state.steps] as const);
  const centreError = gpu.holes.reduce(
    (w, h, s) => Math.max(w, ...h.center.map((v, k) => Math.abs(v - twin.state.holes[s]!.center[k]!))),
    0,
  );
  console.log(`rupture after ${twin.state.steps} steps: ${twin.state.holes.length} holes in the twin, ${gpu.holes.length} on the GPU`);
  expect(twin.state.holes.length).toBeGreaterThan(1);
  expect(gpu.holes).toHaveLength(twin.state.holes.length);
  expect(centreError).toBeLessThan(1e-6);
  expect(gpu.intact).toEqual([...twin.state.intact]);
});

test('with renew a new bubble follows the burst: every cell whole again, holding the film it started with', async ({
  parityPage: page,
}) => {
  // Full speed: the rims sweep the sphere in one step; the film renews RENEW_DELAY_S (8 steps of 32 ms) later.
  const burst = { gridN: 16 };
  const steps = 12;
  const [gone, renewed] = await page.evaluate(
    ([p, n, at]) => [window.runFlow!(p, n, null, at, false), window.runFlow!(p, n, null, at, true)],
    [burst, steps, TOP] as const,
  );
  const { area } = createFilmSimulation(burst).grid;
  // The start is the uniform film (seed 0, η = 1): its volume ∫η dA = 4π, which transport keeps.
  const volume = renewed.eta.reduce((s, eta, c) => s + eta * area[c]!, 0);
  console.log(`renew: ∫η dA ${volume.toFixed(6)} against 4π = ${(4 * Math.PI).toFixed(6)}`);
  expect(gone.intact.every((v) => v === 0)).toBe(true);
  expect(gone.holes).toHaveLength(1);
  expect(renewed.intact.every((v) => v === 1)).toBe(true);
  expect(renewed.holes).toEqual([]);
  expect(Math.abs(volume / (4 * Math.PI) - 1)).toBeLessThan(1e-5);
});

/**
 * The user's burst, in the demo: a frozen film of a large, thick bubble in still air, whose rim
 * (√(2γ/(ρh)) ≈ 8 m/s at 2000 nm over a 100 mm radius) runs about 1.3 rad in a step of grid 16, so
 * one step after a prick the hole is a cap round it, short of the far side.
 */
const USER_BURST = { gridN: 16, seed: 5, windMps: 0, radiusMm: 100, thicknessNm: 2000 } as const;
const USER_BURST_VIEW: Partial<ViewSettings> = { ...USER_BURST, field: 'flow', simSpeed: 1, timeSeconds: 0.06, animate: false };
/** The bubble's front, the view's (0, 0, 1) under its centre, in the simulation's frame (z up: flowDirection). */
const FRONT: [number, number, number] = [0, -1, 0];

test("a double-click on the bubble's centre, P at the probe there, or the panel's burst button bursts the flowing film there, as the twin pricked there bursts", async ({
  demoPage: page,
}) => {
  await page.evaluate(installFilmReader);
  await page.evaluate((settings) => {
    const { bubbleApp } = window as unknown as Demo;
    document.body.dataset.frames = 'changed';
    bubbleApp.set({ ...bubbleApp.current, ...settings }, true);
  }, USER_BURST_VIEW);
  await expect(page.locator('body')).toHaveAttribute('data-frames', 'ready');
  const flow = await page.evaluate(() => (window as unknown as Demo).bubbleView.lastFrame.film!.flow!);
  const bubble = page.locator('#bubble');
  const box = (await bubble.boundingBox())!;
  await openPanel(page);
  const burstBy = {
    none: () => Promise.resolve(),
    'double-click': () => bubble.dblclick({ position: { x: box.width / 2, y: box.height / 2 } }),
    P: () => page.locator('[role=application]').press('p'),
    button: () => page.getByRole('button', { name: 'burst (P)' }).press('Enter'),
  };
  /** Whether each cell is whole one step after the burst (or none); the film is then started again at the frozen time. */
  const intactAfter = async (how: keyof typeof burstBy) => {
    await burstBy[how]();
    const texels = await page.evaluate((dt) => {
      const { bubbleView, bubbleApp } = window as unknown as Demo;
      const start = bubbleApp.current.timeSeconds;
      bubbleApp.set({ ...bubbleApp.current, timeSeconds: start + dt });
      bubbleView.render();
      const film = (window as unknown as FilmReader).flowFilmTexels();
      bubbleApp.set({ ...bubbleApp.current, timeSeconds: start });
      bubbleView.render();
      return film;
    }, flow.stepSeconds);
    return [...paddedFilmCells(texels, USER_BURST.gridN).intact];
  };
  const calm = await intactAfter('none');
  const [byDoubleClick, byKey, byButton] = [await intactAfter('double-click'), await intactAfter('P'), await intactAfter('button')];

  const twin = createFilmSimulation(USER_BURST);
  for (let k = 0; k < flow.steps; k++) stepFilm(twin);
  punctureFilm(twin, ...FRONT);
  stepFilm(twin);
  const twinIntact = [...twin.state.intact];
  const differing = byDoubleClick.filter((v, c) => v !== twinIntact[c]).length;
  const whole = (cells: number[]) => cells.reduce((s, v) => s + v, 0);
  console.log(
    `user's burst after ${flow.steps} steps: ${whole(byDoubleClick)} of ${calm.length} cells whole a step later, ` +
      `${whole(twinIntact)} in the twin; ${differing} differ`,
  );
  // The same film as the twin's: the view's settings are its parameters, at its step.
  expect(flow.stepSeconds).toBe(twin.stepSeconds);
  expect(flow.steps).toBe(Math.floor(0.06 / twin.stepSeconds));
  // Unpricked, the film is whole: the hole is the user's.
  expect(whole(calm)).toBe(calm.length);
  // A cap round the front: the front gone, the back whole.
  expect(byDoubleClick[nearestCell(twin.grid, ...FRONT)]).toBe(0);
  expect(byDoubleClick[nearestCell(twin.grid, 0, 1, 0)]).toBe(1);
  expect(whole(twinIntact)).toBeGreaterThan(0);
  expect(whole(twinIntact)).toBeLessThan(calm.length);
  expect(differing).toBeLessThanOrEqual(FLOW_BURST_DIFFERING_CELLS);
  // P and the button burst at the probe, which the double-click's presses put at the centre.
  expect(byKey).toEqual(byDoubleClick);
  expect(byButton).toEqual(byDoubleClick);
});
