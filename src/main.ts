import { parseSettings } from './scene/params.ts';
import { BubbleView } from './scene/bubbleView.ts';

const canvas = document.querySelector<HTMLCanvasElement>('#bubble');
const messages = document.querySelector<HTMLElement>('#messages');
if (!canvas || !messages) throw new Error('index.html must hold #bubble and #messages');

const { settings, errors } = parseSettings(location.search);
for (const e of errors) {
  const line = document.createElement('p');
  line.textContent = e; // never innerHTML: the text comes from the URL
  messages.append(line);
}

const gl = canvas.getContext('webgl2');
document.body.dataset.webgl2 = gl ? 'yes' : 'no';
const view = new BubbleView(canvas, settings);
const fit = () => view.resize(canvas.clientWidth, canvas.clientHeight, Math.min(2, devicePixelRatio));
fit();
new ResizeObserver(() => {
  fit();
  view.render();
}).observe(canvas);

const started = performance.now();
function frame(now: number) {
  if (view.current.animate && view.current.field === 'swirl') {
    view.apply({ ...view.current, timeSeconds: settings.timeSeconds + (now - started) / 1000 });
    view.render();
    requestAnimationFrame(frame);
  }
}
view.render();
document.body.dataset.frames = 'ready';
requestAnimationFrame(frame);
Object.assign(window, { bubbleView: view });
