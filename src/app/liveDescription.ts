import { latestThrottle } from './latestThrottle.ts';

/** The live description is said at most this often (the latest state wins). */
const DESCRIPTION_INTERVAL_MS = 1000;

/**
 * A sentence on the film at the probe for screen readers: a paragraph placed after the surface,
 * aria-live polite and visually hidden (class `tfb-live`: accessStyles). It stays silent until
 * `start` (the user has changed the view), then says the latest text at most once per
 * DESCRIPTION_INTERVAL_MS (latestThrottle), so a screen reader is not flooded while a slider moves.
 */
export class LiveDescription {
  private readonly element: HTMLElement;
  private readonly throttle: ReturnType<typeof latestThrottle<string>>;
  private speaking = false;

  constructor(surface: HTMLElement) {
    this.element = Object.assign(surface.ownerDocument.createElement('p'), { className: 'tfb-live' });
    this.element.setAttribute('aria-live', 'polite');
    surface.after(this.element);
    this.throttle = latestThrottle((text: string) => (this.element.textContent = text), DESCRIPTION_INTERVAL_MS);
  }

  /** Whether the user has changed the view (the description is said only after that). */
  get started(): boolean {
    return this.speaking;
  }

  start(): void {
    this.speaking = true;
  }

  /** Says `text` (as text, never HTML), now or at the end of the interval if nothing newer comes. */
  say(text: string): void {
    this.throttle.push(text);
  }

  remove(): void {
    this.throttle.cancel();
    this.element.remove();
  }
}
