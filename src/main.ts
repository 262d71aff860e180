import { createControlPanel } from './scene/controlPanel.ts';
import { parseSettings, settingsToQuery } from './scene/params.ts';
import { BubbleView } from './scene/bubbleView.ts';
import { type FilmSettings } from './render/filmSettings.ts';

const canvas = document.querySelector<HTMLCanvasElement>('#bubble');
const messages = document.querySelector<HTMLElement>('#messages');
if (!canvas || !messages) throw new Error('index.html must hold #bubble and #messages');

const { settings, errors } = parseSettings(location.search);
function say(text: string) {
  const line = document.createElement('p');
  line.textContent = text; // never innerHTML: the text may come from the URL
  messages!.append(line);
}
errors.forEach(say);

const view = new BubbleView(canvas, settings);
document.body.dataset.webgl2 = view.renderer.getContext() instanceof WebGL2RenderingContext ? 'yes' : 'no';
if (settings.space !== 'srgb' && !view.displayIsP3) say('This browser has no Display P3 canvas: showing sRGB.');
const fit = () => view.resize(canvas.clientWidth, canvas.clientHeight, Math.min(2, devicePixelRatio));
fit();
new ResizeObserver(() => {
  if (canvas.clientWidth === 0) return; // hidden (display: none): nothing to draw
  fit();
  view.render();
}).observe(canvas);

// Render on demand: one frame per change; the loop runs only while the swirl animates and the
// page and the canvas are visible.
let clockOrigin = performance.now() - settings.timeSeconds * 1000;
let looping = false;
let canvasOnScreen = true;
const loopWanted = (s: FilmSettings) => s.animate && s.field === 'swirl' && !document.hidden && canvasOnScreen;
function frame(now: number) {
  looping = loopWanted(view.current);
  if (!looping) return;
  view.apply({ ...view.current, timeSeconds: (now - clockOrigin) / 1000 });
  view.render();
  requestAnimationFrame(frame);
}
function startLoop() {
  if (!looping && loopWanted(view.current)) {
    clockOrigin = performance.now() - view.current.timeSeconds * 1000;
    looping = true;
    requestAnimationFrame(frame);
  }
}
document.addEventListener('visibilitychange', startLoop);
new IntersectionObserver((entries) => {
  canvasOnScreen = entries.some((e) => e.isIntersecting);
  startLoop();
}).observe(canvas);

let urlTimer = 0;
createControlPanel(settings, (next) => {
  view.apply({ ...next, timeSeconds: view.current.timeSeconds });
  view.render();
  startLoop();
  // The URL follows the controls without a history entry per slider step.
  clearTimeout(urlTimer);
  urlTimer = window.setTimeout(() => {
    const query = settingsToQuery({ ...view.current, timeSeconds: view.current.animate ? 0 : view.current.timeSeconds });
    history.replaceState(null, '', query ? `?${query}` : location.pathname);
  }, 250);
});

view.render();
document.body.dataset.frames = 'ready';
startLoop();
Object.assign(window, { bubbleView: view });
