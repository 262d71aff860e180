import { defineConfig } from 'vite';

// GLSL files are imported as text with Vite's `?raw` suffix; no plugin is needed.
export default defineConfig({
  server: { port: 5173, strictPort: true },
  preview: { port: 4173, strictPort: true },
});
