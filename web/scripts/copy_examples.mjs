// Copies the architectural example meshes from ../shared/meshes (beside the clone, or
// $FF_SHARED_MESHES) into web/public/examples/, where the page fetches them by relative URL.
// The copies are not committed. Without the shared folder the file examples are left out with
// a warning; the generated examples still work.
import { copyFileSync, existsSync, mkdirSync, statSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const repo = resolve(here, '..', '..');
const source = process.env.FF_SHARED_MESHES ?? resolve(repo, '..', 'shared', 'meshes');
const target = join(repo, 'web', 'public', 'examples');
// Keep in step with the file examples in web/src/examples.ts.
const files = ['hyperboloid_s4.off', 'inspired_mesh.obj', 'YasIsland.off', 'epcot.off'];

if (!existsSync(source)) {
  console.warn(`examples: ${source} not found; the file examples will be missing from the page`);
  process.exit(0);
}
mkdirSync(target, { recursive: true });
let copied = 0;
for (const file of files) {
  const from = join(source, file);
  const to = join(target, file);
  if (!existsSync(from)) {
    console.warn(`examples: ${from} not found; skipped`);
    continue;
  }
  if (existsSync(to) && statSync(to).size === statSync(from).size && statSync(to).mtimeMs >= statSync(from).mtimeMs) continue;
  copyFileSync(from, to);
  copied += 1;
}
console.log(`examples: ${files.length} meshes in web/public/examples (${copied} copied)`);
