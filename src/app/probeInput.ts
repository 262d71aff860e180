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
}

/** Listens to the pointer on the surface and the keys on the focusable element; returns what stops listening. */
export function listenToProbeInput(input: ProbeInput): () => void {
  const stopPointer = listenToPointer(input);
  const stopKeys = listenToKeys(input);
  return () => {
    stopPointer();
    stopKeys();
  };
}

/** Where a pointer event is over `surface`, as fractions of its box. */
function pointOf(e: PointerEvent, surface: HTMLElement): ViewPoint {
  const box = surface.getBoundingClientRect();
  return [(e.clientX - box.left) / box.width, (e.clientY - box.top) / box.height];
}

/** A primary press moves the probe and captures the pointer; a drag moves it along and blows on a flowing film as fast as it moves. */
function listenToPointer({ surface, controls, moveProbe, blow }: ProbeInput): () => void {
  const probeAt = (e: PointerEvent) => {
    const probe = pointOf(e, surface);
    if (probe.every((v) => v >= 0 && v <= 1)) moveProbe(probe);
  };
  const onPress = (e: PointerEvent) => {
    if (!e.isPrimary || e.button !== 0 || (e.target instanceof Node && controls?.contains(e.target))) return;
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

/** Makes the focusable element a labelled application whose arrow keys move the probe (within the view) and whose B blows at it. */
function listenToKeys({ focusable, label, probe, moveProbe, blowAtProbe }: ProbeInput): () => void {
  focusable.tabIndex = 0;
  focusable.classList.add('tfb-focusable');
  focusable.setAttribute('role', 'application');
  focusable.setAttribute('aria-label', label);
  const clamp = (v: number) => Math.min(1, Math.max(0, +v.toFixed(4)));
  const onKey = (e: KeyboardEvent) => {
    const modified = e.altKey || e.ctrlKey || e.metaKey;
    if ((e.key === 'b' || e.key === 'B') && !modified) {
      blowAtProbe();
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
