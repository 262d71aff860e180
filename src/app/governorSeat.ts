import { THICKNESS_FIELDS } from '../fields/fields.ts';
import type { Catalogue } from '../i18n/en.ts';
import { message } from '../i18n/messages.ts';
import type { FrameReport } from '../view/frameReport.ts';
import { AUTO } from '../settings/parameterRow.ts';
import type { ViewSettings } from '../settings/viewParameters.ts';
import type { BudgetChoice } from './budgetTerms.ts';
import { FilmRate } from './filmRate.ts';
import { type GovernedView, FrameGovernor } from './frameGovernor.ts';

/**
 * An app's place in its document's frame governor (docs/governor.md): taken while its film
 * animates, with the knobs its user fixed, and left otherwise (a frozen view draws the same pixels
 * on every machine); the governor's choice for the knobs left (an offer to the app's frames:
 * src/app/drawnFrame.ts), what its frames cost, and the film's rate they show.
 */
export class GovernorSeat {
  private readonly governor: FrameGovernor;
  private governed: GovernedView | null = null;
  private chosen: BudgetChoice | null = null;
  private readonly filmRate = new FilmRate();
  /** The flowing film's grid the last frame drew, for the rate's line. */
  private gridN: number | null = null;

  /** `changed` is called when the choice changes (null: none, the app left). */
  constructor(
    doc: Document,
    private readonly changed: (choice: BudgetChoice | null) => void,
  ) {
    this.governor = FrameGovernor.of(doc);
  }

  /** The governor's choice for the knobs the user left, or null while the app is not governed. */
  get choice(): BudgetChoice | null {
    return this.chosen;
  }

  /** Whether the app is governed. */
  get seated(): boolean {
    return this.governed !== null;
  }

  /** Takes the seat while `asked` animates (with what the user fixed), leaves it otherwise; the same knobs fixed keep it. */
  follow(asked: ViewSettings, animating: boolean, baseStepsPerFrame: number): void {
    const { gridN, pixelRatio, simSpeed, field } = asked;
    const wanted = animating
      ? {
          gridN: gridN === AUTO ? undefined : gridN,
          pixelRatio: pixelRatio === AUTO ? undefined : pixelRatio,
          simSpeedGiven: simSpeed !== AUTO,
          flows: THICKNESS_FIELDS[field].evolves === true,
          baseStepsPerFrame,
        }
      : null;
    const g = this.governed;
    // The same knobs fixed as before (JSON leaves out `apply`): it stays where it is.
    if (g && wanted && JSON.stringify(g) === JSON.stringify(wanted)) return;
    if (g) this.governor.leave(g);
    this.governed = wanted && { ...wanted, apply: (choice) => this.take(choice) };
    if (this.governed) this.governor.join(this.governed);
    else this.take(null);
  }

  /** The app's animating frame at `now` (rAF's time) drew `report`, at simulation speed `simSpeed`; `follows`: its frame before was the one just before. */
  drawn(now: number, report: FrameReport, simSpeed: number, follows: boolean): void {
    if (!this.governed || !report.cost) return;
    const flow = report.film?.flow ?? null;
    this.governor.drawn(now, report.cost, flow, follows);
    if (report.film) this.filmRate.frame(now, report.film.timeSeconds * simSpeed);
    this.gridN = flow?.gridN ?? null;
  }

  /** The film's rate is to be measured anew (its settings changed). */
  restartRate(): void {
    this.filmRate.reset();
  }

  /** The film's rate and grid as a text of the catalogue (`key`), or null while it is not governed or not yet measured. */
  filmTimeText(cat: Catalogue, key: 'governor.line' | 'governor.sentence'): string | null {
    const rate = this.filmRate.rate;
    if (!this.governed || rate === null || this.gridN === null) return null;
    return message(cat, key, { rate: +rate.toPrecision(2), grid: this.gridN });
  }

  /** Leaves the governor (the app is disposed). */
  leave(): void {
    if (this.governed) this.governor.leave(this.governed);
    this.governed = null;
  }

  private take(choice: BudgetChoice | null): void {
    if (choice?.gridN !== this.chosen?.gridN) this.filmRate.reset();
    this.chosen = choice;
    this.changed(choice);
  }
}
