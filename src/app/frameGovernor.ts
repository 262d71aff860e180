import { flowParameterRow } from '../settings/filmParameters.ts';
import { shownPixelRatio } from '../settings/pixelRatio.ts';
import {
  type BudgetChoice,
  type BudgetLimits,
  type BudgetState,
  GOVERNED_GRIDS,
  GOVERNED_MAX_STEPS,
  governedPixelRatios,
} from './budgetTerms.ts';
import { initialBudget, nextBudget } from './frameBudget.ts';

/** Full quality's grid, the ladder's top: the flowing film's default (FLOW_PARAMETERS); a finer one is a user's choice. */
const FULL_QUALITY_GRID = flowParameterRow('gridN').defaultValue;
/** The grids the governor chooses among. */
const LADDER_GRIDS = GOVERNED_GRIDS.filter((n) => n <= FULL_QUALITY_GRID);

/** What a governed view gives the governor: what its user fixed, and how its flowing film steps. */
export interface GovernedView {
  /** The grid and pixel ratio its user gave (honoured exactly), or undefined (the governor's). */
  readonly gridN: number | undefined;
  readonly pixelRatio: number | undefined;
  /** Whether its user gave the simulation's speed (its frames then take every step the time asks for). */
  readonly simSpeedGiven: boolean;
  /** Whether its field is the flowing film (else it has no grid or steps to govern). */
  readonly flows: boolean;
  /** Its steps per frame as its own quality has them (what a frame that holds the budget takes at least). */
  readonly baseStepsPerFrame: number;
  /** The governor's choice changed: the view applies it to the knobs its user left. */
  readonly apply: (choice: BudgetChoice) => void;
}

/** The film seconds a step takes at a grid, from a step measured at another: the step is bounded by the cell's size (∝ 1/N). */
const stepSecondsFrom =
  (at: { readonly gridN: number; readonly stepSeconds: number } | null) =>
  (gridN: number): number =>
    at ? (at.stepSeconds * at.gridN) / gridN : Infinity;

/** The samples dropped after a change (FrameGovernor.skip). */
const SKIPPED_AFTER_CHANGE = 4;

const governors = new WeakMap<Document, FrameGovernor>();

/**
 * The frame budget of a document (docs/governor.md): one for every bubble animating on the page,
 * which share it. Each animating frame of a view reports its simulation's time and steps; the
 * frames of one animation frame (one `now`) make one sample, its interval the time to the next.
 * The decision is frameBudget.ts's; a change of the choice goes to every view governed.
 */
export class FrameGovernor {
  private readonly views = new Set<GovernedView>();
  private state: BudgetState | null = null;
  private limitsKey = '';
  private limits: BudgetLimits | null = null;
  /**
   * The animation frame being gathered: its time, its views' simulation ms and steps, their draws'
   * GPU ms (null where one has no timer), and whether a view's film was settling in it.
   */
  private frame: { now: number; simMs: number; steps: number; drawMs: number | null; settling: boolean } | null = null;
  /** A flowing film's grid and step as last measured (for the step at other grids). */
  private step: { readonly gridN: number; readonly stepSeconds: number } | null = null;
  /**
   * Samples still to drop after a change: the frame it was made in (the old choice's), and the few
   * after (a new grid's simulation made and its programs compiled, a resized buffer allocated, and
   * the frame after a waited one reusing its measure: FrameCost).
   */
  private skip = 0;

  /** The document's governor. */
  static of(doc: Document): FrameGovernor {
    let governor = governors.get(doc);
    if (!governor) {
      governor = new FrameGovernor();
      governors.set(doc, governor);
      // A hidden page draws nothing: the time until it is shown again is not a frame's.
      doc.addEventListener('visibilitychange', () => (governor!.frame = null));
    }
    return governor;
  }

  /** The choice now (the views governed apply it to the knobs their users left). */
  get choice(): BudgetChoice | null {
    return this.state?.choice ?? null;
  }

  /** A view starts animating (or what its user fixed changed): it is governed, and given the choice. */
  join(view: GovernedView): void {
    this.views.add(view);
    this.update();
    view.apply(this.state!.choice);
  }

  /** A view stops animating (frozen, hidden, removed): the budget is the others'. */
  leave(view: GovernedView): void {
    if (!this.views.delete(view)) return;
    if (this.views.size === 0) {
      this.state = null;
      this.limitsKey = '';
      this.frame = null;
    } else this.update();
  }

  /**
   * A governed view drew a frame of the animation frame at `now` (rAF's time), its simulation taking
   * `simMs` for `steps` steps at `flowGrid`; `settling` says its film was shown before its
   * simulation, made, or compiled its programs in it (the frame is not measured); `follows` says whether its frame
   * before was the one just before (else the time between is not a frame's).
   */
  drawn(
    now: number,
    cost: { readonly simMs: number; readonly drawMs: number | null; readonly steps: number; readonly settling: boolean },
    flowGrid: { readonly gridN: number; readonly stepSeconds: number } | null,
    follows: boolean,
  ): void {
    if (flowGrid) this.step = flowGrid;
    const f = this.frame;
    if (f && f.now === now) {
      f.simMs += cost.simMs;
      f.steps += cost.steps;
      f.drawMs = f.drawMs === null || cost.drawMs === null ? null : f.drawMs + cost.drawMs;
      f.settling ||= cost.settling;
      return;
    }
    this.frame = { now, simMs: cost.simMs, steps: cost.steps, drawMs: cost.drawMs, settling: cost.settling };
    if (!f || !follows || f.settling || !this.state || !this.limits) return;
    if (this.skip > 0) {
      this.skip--;
      return;
    }
    const before = this.state.choice;
    this.state = nextBudget(
      this.state,
      { intervalMs: now - f.now, simMs: f.simMs, steps: f.steps, drawMs: f.drawMs ?? undefined },
      { ...this.limits, stepSeconds: stepSecondsFrom(this.step) },
    );
    if (this.state.choice === before) return;
    this.skip = SKIPPED_AFTER_CHANGE;
    for (const v of this.views) v.apply(this.state.choice);
  }

  /** The limits the views give; the decision starts anew when what the governor may choose changed. */
  private update(): void {
    const views = [...this.views];
    const flowing = views.filter((v) => v.flows);
    const governedGrid = flowing.filter((v) => v.gridN === undefined);
    const fixedGrid = flowing.find((v) => v.gridN !== undefined)?.gridN;
    const fixedRatio = views.every((v) => v.pixelRatio !== undefined) ? views[0]?.pixelRatio : undefined;
    const limits: BudgetLimits = {
      grids: governedGrid.length > 0 ? LADDER_GRIDS : [fixedGrid ?? FULL_QUALITY_GRID],
      pixelRatios: fixedRatio !== undefined ? [fixedRatio] : governedPixelRatios(shownPixelRatio()),
      maxStepsPerFrame: GOVERNED_MAX_STEPS,
      baseStepsPerFrame: Math.min(...views.map((v) => v.baseStepsPerFrame)),
      fixedStepsPerFrame: flowing.some((v) => !v.simSpeedGiven) ? null : 1,
      stepSeconds: stepSecondsFrom(this.step),
      simSpeed: 1,
      views: Math.max(1, flowing.filter((v) => !v.simSpeedGiven).length),
    };
    const key = JSON.stringify([limits.grids, limits.pixelRatios, limits.fixedStepsPerFrame]);
    this.limits = limits;
    if (key === this.limitsKey && this.state) return;
    this.limitsKey = key;
    this.state = initialBudget(limits);
    this.frame = null;
    // The first frame compiles the programs it draws with.
    this.skip = 1;
    for (const v of this.views) v.apply(this.state.choice);
  }
}
