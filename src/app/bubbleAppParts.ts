import type { Catalogue } from '../i18n/en.ts';
import type { BubbleView } from '../view/bubbleView.ts';
import type { ViewSettings } from '../settings/viewParameters.ts';

/** What a BubbleApp is made of: its view, the page's elements it uses, and the page's callbacks. */
export interface BubbleAppParts {
  readonly view: BubbleView;
  /**
   * The element the bubble is shown in: its CSS box sizes the view; a press on it (mouse, pen or
   * touch; not on the panel) moves the probe there, and the probe follows while the press drags.
   */
  readonly surface: HTMLElement;
  /** Called after each frame is drawn (e.g. to copy a shared renderer's canvas to the page). */
  readonly present?: () => void;
  /**
   * Where the lil-gui panel goes, if any. It starts closed where the page's CSS says so
   * (startsClosed, read from this element).
   */
  readonly controls?: HTMLElement;
  /** Where the plots go, if any; they are redrawn when this element's box changes (e.g. a drawer opens). */
  readonly plots?: HTMLElement;
  /**
   * Where a line on the HDR environment goes while it loads, or if it failed, and the line saying
   * that the method asked for is drawn with another (the frame's notices) (role status; text only).
   */
  readonly messages?: HTMLElement;
  /** Called when the panel or a press on the bubble changes the settings. */
  readonly onChange?: (s: ViewSettings) => void;
  /** Called after every frame; `complete` is false for a frame drawn from a coarse table (another follows). */
  readonly onFrame?: (complete: boolean) => void;
  /**
   * The element that shows the bubble to the user (default `surface`): it takes focus, is labelled
   * (role application), and its arrow keys move the probe.
   */
  readonly focusable?: HTMLElement;
  /** The language of every text the app shows (default English). */
  readonly catalogue?: Catalogue;
}
