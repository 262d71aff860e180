import { BubbleApp } from '../app/bubbleApp.ts';
import { hasWebGL2, showCpuFallback } from '../app/cpuFallback.ts';
import { parseSettings, refusalText, settingsToQuery } from '../settings/settingsQuery.ts';
import { FRAME_MARKS } from './frameMarks.ts';
import { startsClosed } from '../app/startsClosed.ts';
import { pageLanguage, prefersReducedMotion } from '../app/pagePreferences.ts';
import { type ViewSettings, filmSettingsOf } from '../settings/viewParameters.ts';
import { DEMO_VIEW_SETTINGS } from '../settings/demoView.ts';
import { BubbleView } from '../view/bubbleView.ts';
import { createBubbleRenderer } from '../view/bubbleRenderer.ts';

const canvas = document.querySelector<HTMLCanvasElement>('#bubble');
const messages = document.querySelector<HTMLElement>('#messages');
const plots = document.querySelector<HTMLElement>('#plots');
const panel = document.querySelector<HTMLElement>('#panel');
const heading = document.querySelector<HTMLElement>('#heading');
if (!canvas || !messages || !plots || !panel || !heading)
  throw new Error('index.html must hold #bubble, #messages, #plots, #panel and #heading');

const query = new URLSearchParams(location.search);
const { lang, cat, error: langError } = pageLanguage(query, document.documentElement.lang);
document.documentElement.lang = lang;
document.title = cat['app.title'];
heading.textContent = cat['app.heading'];
// What the URL leaves out is the demo's default view (a bubble's life, demoView.ts), read and written alike.
const parsed = parseSettings(location.search, DEMO_VIEW_SETTINGS);
// Less motion asked for: the film stands still unless the URL says animate=1.
const settings = prefersReducedMotion() && !query.has('animate') ? { ...parsed.settings, animate: false } : parsed.settings;
function say(text: string) {
  const line = document.createElement('p');
  line.textContent = text; // never innerHTML: the text may come from the URL
  messages!.append(line);
}
messages.setAttribute('aria-label', cat['app.messages']);
if (langError) say(langError);
parsed.refusals.forEach((r) => say(refusalText(r, cat)));
const summary = plots.closest('details')?.querySelector('summary');
if (summary) summary.textContent = cat['app.plotsSummary'];

// The URL follows the controls without a history entry per slider step.
let urlTimer = 0;
function followInUrl(s: ViewSettings) {
  clearTimeout(urlTimer);
  urlTimer = window.setTimeout(() => {
    const shown = new URLSearchParams(settingsToQuery({ ...s, timeSeconds: s.animate ? 0 : s.timeSeconds }, DEMO_VIEW_SETTINGS));
    if (query.has('lang')) shown.set('lang', lang); // the page's own parameter stays
    const text = shown.toString();
    history.replaceState(null, '', text ? `?${text}` : location.pathname);
  }, 250);
}

/** The live bubble with its panel and plots. */
function startLiveView(canvas: HTMLCanvasElement, plots: HTMLElement, messages: HTMLElement, panel: HTMLElement): void {
  const drawer = plots.closest('details');
  if (drawer) drawer.open = !startsClosed(drawer, 'plots'); // a small view starts with the drawer closed (index.html's CSS)
  const view = new BubbleView(createBubbleRenderer(canvas));
  document.body.dataset.webgl2 = view.renderer.getContext() instanceof WebGL2RenderingContext ? 'yes' : 'no';
  // Whether a frame, and a frame in full, have been drawn: the User Timing marks of the first of each.
  let drawn = false;
  let drawnInFull = false;
  const app = new BubbleApp(
    {
      view,
      surface: canvas,
      catalogue: cat,
      controls: panel,
      plots,
      messages,
      onChange: followInUrl,
      onFrame: (complete) => {
        if (!drawn) performance.mark(FRAME_MARKS.first);
        drawn = true;
        if (!complete || document.body.dataset.frames === 'ready') return;
        if (!drawnInFull) performance.mark(FRAME_MARKS.firstComplete);
        drawnInFull = true;
        document.body.dataset.frames = 'ready';
      },
    },
    settings,
  );
  Object.assign(window, { bubbleView: view, bubbleApp: app });
}

if (hasWebGL2()) startLiveView(canvas, plots, messages, panel);
else {
  // Without WebGL2 the page still teaches: a still image computed on the CPU, no plots.
  plots.closest('details')?.remove();
  document.body.dataset.webgl2 = 'no';
  showCpuFallback(canvas, filmSettingsOf(settings), () => (document.body.dataset.frames = 'fallback'), cat);
}
