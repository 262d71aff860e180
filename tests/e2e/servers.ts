/**
 * The browser tests' server: the built site with the tests' pages (`vite build --mode e2e`, plus the
 * element) served statically by `vite preview`. E2E_PORT lets two checkouts run their suites side by side.
 */
export const BUILT_PORT = Number(process.env.E2E_PORT ?? 5180);
export const BUILT_URL = `http://127.0.0.1:${BUILT_PORT}`;
