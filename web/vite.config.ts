// Vite config of the designer's page. Relative base so web/dist works from any static server
// and any sub-path; module workers (the solver worker imports the Emscripten ES module).
import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vite';

const generated = fileURLToPath(new URL('./src/generated/', import.meta.url));

export default defineConfig({
  root: fileURLToPath(new URL('.', import.meta.url)),
  base: './',
  publicDir: 'public',
  resolve: {
    alias: [
      // Written by `npm run build:wasm` (scripts/build_wasm.sh); typed by wasm/flatfacet.d.ts.
      { find: /^@flatfacet\/wasm$/, replacement: `${generated}flatfacet.mjs` },
      { find: /^@flatfacet\/wasm-binary\?url$/, replacement: `${generated}flatfacet.wasm?url` },
    ],
  },
  worker: { format: 'es' },
  build: {
    outDir: 'dist',
    emptyOutDir: true,
    target: 'es2022',
    chunkSizeWarningLimit: 1200,
  },
  server: { port: 5173, strictPort: true },
  preview: { port: 5173, strictPort: true },
});
