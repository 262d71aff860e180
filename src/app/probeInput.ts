import { arrowKeyStep } from './arrowKeyStep.ts';

/** An arrow key moves the probe this far (a fraction of the view; farther with Shift: arrowKeyStep). */
const PROBE_STEP = 0.01;

/** A point on the view, as fractions of its box (x to the right, y down; 0 to 1 on it). */
type ViewPoint = readonly [number, number];

export interface ProbeInput {
  /**
   * The element the bubble is shown in: a press on it (mouse, pen or touch; not on the panel)
   * moves the probe there, and the probe follows while the press drags.
   */
  readonly surface: HTMLElement;
  /** The element that shows the bubble to the user: it takes focus, and its arrow keys move the probe. */
  readonly focusable: HTMLElement;
  /** Its label for a screen reader (role application). */
  readonly label: string;
  /** The panel, if any: a press on it is not on the bubble. */
  readonly controls: HTMLElement | null;
  /** Where the probe is. */
  readonly probe: () => ViewPoint;
  /** Moves the probe (the user changed the view). */
  readonly moveProbe: (probe: ViewPoint) => void;
  /** Blows on a flowing film at a point, with a velocity in CSS pixels per second (BubbleView.blow). */
  readonly blow: (fx: number, fy: number, vxPx: number, vyPx: number) => void;
  /** Blows at the probe (the key B). */
  readonly blowAtProbe: () => void;
  /** Bursts a flowing film at a point (BubbleView.burst): a double-click or double-tap there. */
  readonly burst: (fx: number, fy: number) => void;
  /** Bursts it at the probe (the key P). */
  readonly burstAtProbe: () => void;
}

/** Listens to the pointer on the surface and the keys on the focusable element; returns what stops listening. */
export function listenToProbeInput(input: ProbeInput): () => void {
  const stops = [listenToPointer(input), listenToDoubleClick(input), listenToKeys(input)];
  return () => stops.forEach((stop) => stop());
}

/** Where a mouse or pointer event is over `surface`, as fractions of its box. */
function pointOf(e: MouseEvent, surface: HTMLElement): ViewPoint {
  const box = surface.getBoundingClientRect();
  return [(e.clientX - box.left) / box.width, (e.clientY - box.top) / box.height];
}

/** Whether a point is on the view. */
const inView = (point: ViewPoint): boolean => point.every((v) => v >= 0 && v <= 1);

/** Whether an event is on the panel (not on the bubble). */
const onPanel = (e: Event, controls: HTMLElement | null): boolean => e.target instanceof Node && (controls?.contains(e.target) ?? false);

/** A primary press moves the probe and captures the pointer; a drag moves it along and blows on a flowing film as fast as it moves. */
function listenToPointer({ surface, controls, moveProbe, blow }: ProbeInput): () => void {
  const probeAt = (e: PointerEvent) => {
    const probe = pointOf(e, surface);
    if (inView(probe)) moveProbe(probe);
  };
  const onPress = (e: PointerEvent) => {
    if (!e.isPrimary || e.button !== 0 || onPanel(e, controls)) return;
    surface.setPointerCapture(e.pointerId);
    probeAt(e);
  };
  /** The last point of a drag (CSS pixels, ms). */
  let dragged: { x: number; y: number; t: number } | null = null;
  const onDrag = (e: PointerEvent) => {
    if (!surface.hasPointerCapture(e.pointerId)) return;
    probeAt(e);
    const dt = dragged ? (e.timeStamp - dragged.t) / 1000 : 0;
    if (dragged && dt > 0) blow(...pointOf(e, surface), (e.clientX - dragged.x) / dt, (e.clientY - dragged.y) / dt);
    dragged = { x: e.clientX, y: e.clientY, t: e.timeStamp };
  };
  const onRelease = () => (dragged = null);
  surface.addEventListener('pointerdown', onPress);
  surface.addEventListener('pointermove', onDrag);
  surface.addEventListener('pointerup', onRelease);
  return () => {
    surface.removeEventListener('pointerdown', onPress);
    surface.removeEventListener('pointermove', onDrag);
    surface.removeEventListener('pointerup', onRelease);
  };
}

/** A double-click or double-tap with the primary button bursts a flowing film there (its presses have moved the probe there). */
function listenToDoubleClick({ surface, controls, burst }: ProbeInput): () => void {
  const onDoubleClick = (e: MouseEvent) => {
    const point = pointOf(e, surface);
    if (e.button === 0 && !onPanel(e, controls) && inView(point)) burst(...point);
  };
  surface.addEventListener('dblclick', onDoubleClick);
  return () => surface.removeEventListener('dblclick', onDoubleClick);
}

/** The keys that act on a flowing film at the probe, each with what it does. */
const FILM_KEYS = new Map<string, 'blowAtProbe' | 'burstAtProbe'>([
  ['b', 'blowAtProbe'],
  ['p', 'burstAtProbe'],
]);

/**
 * Makes the focusable element a labelled application whose arrow keys move the probe (within the
 * view), whose B blows at it and whose P bursts the film there (FILM_KEYS; either case, no modifier).
 */
function listenToKeys(input: ProbeInput): () => void {
  const { focusable, label, probe, moveProbe } = input;
  focusable.tabIndex = 0;
  focusable.classList.add('tfb-focusable');
  focusable.setAttribute('role', 'application');
  focusable.setAttribute('aria-label', label);
  const clamp = (v: number) => Math.min(1, Math.max(0, +v.toFixed(4)));
  const onKey = (e: KeyboardEvent) => {
    const modified = e.altKey || e.ctrlKey || e.metaKey;
    const act = FILM_KEYS.get(e.key.toLowerCase());
    if (act && !modified) {
      input[act]();
      return;
    }
    const move = arrowKeyStep(e, PROBE_STEP);
    if (!move || modified) return;
    e.preventDefault(); // the arrows move the probe, not the page
    const [x, y] = probe();
    moveProbe([clamp(x + move[0]), clamp(y + move[1])]);
  };
  focusable.addEventListener('keydown', onKey);
  return () => focusable.removeEventListener('keydown', onKey);
}
