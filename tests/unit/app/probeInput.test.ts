import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { type ProbeInput, listenToProbeInput } from '../../../src/app/probeInput.ts';

/** The surface's box in CSS pixels. */
const BOX = { left: 100, top: 50, width: 200, height: 100 };

/** An element as the probe input uses one: events, attributes, a box and pointer capture. */
class FakeElement extends EventTarget {
  tabIndex = -1;
  readonly classList = new Set<string>();
  readonly attributes = new Map<string, string>();
  readonly captured = new Set<number>();
  setAttribute(name: string, value: string): void {
    this.attributes.set(name, value);
  }
  getBoundingClientRect() {
    return BOX;
  }
  setPointerCapture(id: number): void {
    this.captured.add(id);
  }
  hasPointerCapture(id: number): boolean {
    return this.captured.has(id);
  }
}

const key = (name: string, mods: Partial<Record<'shiftKey' | 'altKey' | 'ctrlKey' | 'metaKey', boolean>> = {}) =>
  Object.assign(new Event('keydown', { cancelable: true }), {
    key: name,
    shiftKey: false,
    altKey: false,
    ctrlKey: false,
    metaKey: false,
    ...mods,
  });

const pointer = (type: string, clientX: number, clientY: number, timeStamp = 0, button = 0) => {
  const e = Object.assign(new Event(type), { isPrimary: true, button, pointerId: 1, clientX, clientY });
  return Object.defineProperty(e, 'timeStamp', { value: timeStamp });
};

/** The probe input over fake elements, recording what it asks for. */
function setUp(start: readonly [number, number] = [0.5, 0.5], controls: { contains: (n: unknown) => boolean } | null = null) {
  const surface = new FakeElement();
  const calls = {
    probe: [...start] as readonly [number, number],
    moves: 0,
    blows: [] as number[][],
    blowsAtProbe: 0,
    bursts: [] as number[][],
    burstsAtProbe: 0,
  };
  const input: ProbeInput = {
    surface: surface as unknown as HTMLElement,
    focusable: surface as unknown as HTMLElement,
    label: 'the bubble',
    controls: controls as unknown as HTMLElement | null,
    probe: () => calls.probe,
    moveProbe: (p) => {
      calls.probe = p;
      calls.moves++;
    },
    blow: (...args) => calls.blows.push(args),
    blowAtProbe: () => calls.blowsAtProbe++,
    burst: (...args) => calls.bursts.push(args),
    burstAtProbe: () => calls.burstsAtProbe++,
  };
  const stop = listenToProbeInput(input);
  return { surface, calls, stop };
}

describe('the probe input', () => {
  // A press's target is checked against the panel with `instanceof Node`, which Node.js lacks.
  beforeEach(() => vi.stubGlobal('Node', EventTarget));
  afterEach(() => vi.unstubAllGlobals());

  it('makes the focusable element a labelled application that takes focus', () => {
    const { surface } = setUp();
    expect(surface.tabIndex).toBe(0);
    expect([...surface.classList]).toEqual(['tfb-focusable']);
    expect(Object.fromEntries(surface.attributes)).toEqual({ role: 'application', 'aria-label': 'the bubble' });
  });

  it('moves the probe 1 % of the view per arrow key, 5 % with Shift, within the view, and keeps the page from scrolling', () => {
    const { surface, calls } = setUp([0.5, 0.005]);
    const right = key('ArrowRight');
    surface.dispatchEvent(right);
    expect(calls.probe).toEqual([0.51, 0.005]);
    expect(right.defaultPrevented).toBe(true);
    surface.dispatchEvent(key('ArrowLeft', { shiftKey: true }));
    expect(calls.probe).toEqual([0.46, 0.005]);
    surface.dispatchEvent(key('ArrowUp'));
    expect(calls.probe).toEqual([0.46, 0]);
  });

  it('leaves arrows with Alt, Ctrl or Meta and other keys to the page; B blows at the probe, Ctrl+B does not', () => {
    const { surface, calls } = setUp();
    for (const mod of ['altKey', 'ctrlKey', 'metaKey'] as const) {
      const e = key('ArrowDown', { [mod]: true });
      surface.dispatchEvent(e);
      expect(e.defaultPrevented).toBe(false);
    }
    surface.dispatchEvent(key('x'));
    expect(calls.moves).toBe(0);
    surface.dispatchEvent(key('b'));
    surface.dispatchEvent(key('B', { shiftKey: true }));
    surface.dispatchEvent(key('b', { ctrlKey: true }));
    expect(calls.blowsAtProbe).toBe(2);
  });

  it('bursts at the probe with P or p, not with Ctrl+P, nor with another key', () => {
    const { surface, calls } = setUp();
    surface.dispatchEvent(key('p'));
    surface.dispatchEvent(key('P', { shiftKey: true }));
    surface.dispatchEvent(key('p', { ctrlKey: true }));
    surface.dispatchEvent(key('o'));
    expect(calls.burstsAtProbe).toBe(2);
    expect(calls.blowsAtProbe).toBe(0);
  });

  it('bursts where a double-click or double-tap lands on the view, not off it, nor on the panel, nor with another button', () => {
    const { surface, calls } = setUp();
    surface.dispatchEvent(pointer('dblclick', 150, 75));
    expect(calls.bursts).toEqual([[0.25, 0.25]]);
    surface.dispatchEvent(pointer('dblclick', 301, 75));
    surface.dispatchEvent(pointer('dblclick', 150, 75, 0, 2));
    expect(calls.bursts).toHaveLength(1);
    const onPanel = setUp([0.5, 0.5], { contains: () => true });
    onPanel.surface.dispatchEvent(pointer('dblclick', 150, 75));
    expect(onPanel.calls.bursts).toEqual([]);
  });

  it('moves the probe where a press lands on the view, not off it, nor on the panel', () => {
    const { surface, calls } = setUp();
    surface.dispatchEvent(pointer('pointerdown', 150, 75));
    expect(calls.probe).toEqual([0.25, 0.25]);
    surface.dispatchEvent(pointer('pointerdown', 99, 75));
    expect(calls.moves).toBe(1);
    const onPanel = setUp([0.5, 0.5], { contains: () => true });
    onPanel.surface.dispatchEvent(pointer('pointerdown', 150, 75));
    expect(onPanel.calls.moves).toBe(0);
  });

  it('follows a captured drag, blowing as fast as it moves (CSS pixels a second), until the press ends', () => {
    const { surface, calls } = setUp();
    surface.dispatchEvent(pointer('pointermove', 150, 75, 0));
    expect(calls.moves).toBe(0); // no press: not captured
    surface.dispatchEvent(pointer('pointerdown', 150, 75, 0));
    surface.dispatchEvent(pointer('pointermove', 200, 100, 1000));
    expect(calls.blows).toEqual([]); // the drag's first point: no speed yet
    surface.dispatchEvent(pointer('pointermove', 220, 90, 1100));
    expect(calls.probe).toEqual([0.6, 0.4]);
    expect(calls.blows).toEqual([[0.6, 0.4, 200, -100]]);
    surface.dispatchEvent(pointer('pointerup', 220, 90, 1200));
    surface.dispatchEvent(pointer('pointermove', 240, 90, 1300));
    expect(calls.blows).toHaveLength(1);
  });

  it('stops listening when told', () => {
    const { surface, calls, stop } = setUp();
    stop();
    surface.dispatchEvent(key('ArrowRight'));
    surface.dispatchEvent(key('b'));
    surface.dispatchEvent(key('p'));
    surface.dispatchEvent(pointer('pointerdown', 150, 75));
    surface.dispatchEvent(pointer('dblclick', 150, 75));
    expect(calls).toMatchObject({ moves: 0, blowsAtProbe: 0, bursts: [], burstsAtProbe: 0 });
  });
});
