import type { FrameOffers } from './drawnFrame.ts';
import type { EvolvingFilmReading } from './evolvingFilm.ts';
import type { FrameCostReading } from './frameCost.ts';

/** What a view offers its frames (drawnFrame.ts): the rest (the governor's choice, the device's pixel ratio) is the page's. */
export type ViewOffers = Omit<FrameOffers, 'choice' | 'devicePixelRatio'>;

/**
 * How BubbleView.render draws a frame: `paced`, a frame of the page's loop, which keeps the frame
 * shown while the next one's programs compile, builds a changed table coarsely first, keeps the
 * light shown while a new one's transform is computed, and is measured for the frame governor;
 * `complete`, everything the frame asks at once (tests, screenshots, the render command).
 */
export type FramePace = 'paced' | 'complete';

/** What a frame drew (BubbleView.render): the app's frame loop and its frame governor follow it. */
export interface FrameReport {
  /** Whether it drew (not while the context is lost, nor in a paced frame that keeps the frame shown while the next one's programs compile). */
  readonly drawn: boolean;
  /** Whether it was drawn from a coarse table, in the light shown before, or kept for programs compiling: more frames follow until one is full. */
  readonly coarse: boolean;
  /** The evolving film as drawn, or null for a field whose film does not evolve. */
  readonly film: EvolvingFilmReading | null;
  /** What a paced frame cost (FrameCost), and whether it was the film's settling (not the film's pace); null for another frame. */
  readonly cost: (FrameCostReading & { readonly settling: boolean }) | null;
}

/** A frame not drawn: more follow. */
export const NOT_DRAWN: FrameReport = { drawn: false, coarse: true, film: null, cost: null };
