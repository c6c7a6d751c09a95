// Copies the architectural example meshes from ../shared/meshes (beside the clone, or
// $FF_SHARED_MESHES) into web/public/examples/, where the page fetches them by relative URL,
// and writes examples/index.json, the list of those present: the page offers only those, and
// without them starts on a generated example. The copies are not committed.
import { copyFileSync, existsSync, mkdirSync, statSync, writeFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const repo = resolve(here, '..', '..');
const source = process.env.FF_SHARED_MESHES ?? resolve(repo, '..', 'shared', 'meshes');
const target = join(repo, 'web', 'public', 'examples');
// Keep in step with the file examples in web/src/examples.ts.
const files = ['hyperboloid_s4.off', 'inspired_mesh.obj', 'YasIsland.off', 'epcot.off'];

mkdirSync(target, { recursive: true });
const present = [];
let copied = 0;
for (const file of files) {
  const from = join(source, file);
  const to = join(target, file);
  if (existsSync(from)) {
    if (!(existsSync(to) && statSync(to).size === statSync(from).size && statSync(to).mtimeMs >= statSync(from).mtimeMs)) {
      copyFileSync(from, to);
      copied += 1;
    }
    present.push(file);
  } else if (existsSync(to)) {
    present.push(file); // copied by an earlier build
  }
}
writeFileSync(join(target, 'index.json'), `${JSON.stringify({ files: present })}\n`);
const missing = files.filter((file) => !present.includes(file));
if (missing.length === 0) {
  console.log(`examples: ${files.length} meshes in web/public/examples (${copied} copied)`);
} else {
  console.warn('');
  console.warn(`examples: WARNING: ${missing.join(', ')} not found in ${source} (set FF_SHARED_MESHES to the folder).`);
  console.warn('examples: the page hides those examples' + (missing.includes('hyperboloid_s4.off') ? ' and starts on the generated freeform roof instead of the hyperboloid tower.' : '.'));
  console.warn('');
}
