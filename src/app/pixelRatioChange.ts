/**
 * Calls `changed` whenever the device's pixels per CSS pixel change (the window moved to another
 * screen, the page zoomed): a media query for the present ratio stops matching, and one for the
 * new ratio is listened to. Returns what stops listening.
 */
export function onPixelRatioChange(changed: () => void): () => void {
  let query: MediaQueryList | null = null;
  const listen = () => {
    query = matchMedia(`(resolution: ${globalThis.devicePixelRatio}dppx)`);
    query.addEventListener('change', onChange, { once: true });
  };
  const onChange = () => {
    listen();
    changed();
  };
  listen();
  return () => query?.removeEventListener('change', onChange);
}
