/** The test servers' addresses. E2E_PORT lets two checkouts run their suites side by side. */
export const DEV_PORT = Number(process.env.E2E_PORT ?? 5180);
/** The built site (`vite build` + the element build) served statically by `vite preview`. */
export const BUILT_PORT = DEV_PORT + 1;
export const BUILT_URL = `http://127.0.0.1:${BUILT_PORT}`;
