// Browser benchmark: hyperboloid_s4.off (50k triangles) into 500 panels in the real page
// (headless Debian Chromium, the wasm core in its worker), timed in the worker from the first
// step to the result, over a few cold solves; then the native CLI on the same mesh, count and
// seed in the same run: its solve (cluster + panels + quality, the same work as the worker's)
// and its whole process. Needs the built site (`npm run build`) and the native build.
//   node bench/browser_bench.mjs [--panels N] [--runs R]
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { launchBrowser, openPage, remesh, setPanels, solveAfter, startServer, waitForDone } from '../tests/browser/harness.mjs';
import { meshes, root } from '../tests/wasm/module.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const index = args.indexOf(name);
  return index >= 0 && args[index + 1] ? Number(args[index + 1]) : fallback;
};
const panels = option('--panels', 500);
const runs = option('--runs', 3);

const server = await startServer();
const browser = await launchBrowser();
try {
  const { page, errors } = await openPage(browser, server.url); // opens hyperboloid_s4 by default
  await waitForDone(page);
  if ((await page.getByLabel('Example', { exact: true }).inputValue()) !== 'hyperboloid_s4') throw new Error('the default example is not hyperboloid_s4');
  await setPanels(page, panels);
  await solveAfter(page, () => remesh(page), 300_000); // warm-up: a warm start, and wasm tier-up
  const worker = [];
  const core = [];
  for (let run = 0; run < runs; run++) {
    // Identical parameters solve afresh (Session.resetSolve), so every run is a cold solve.
    const made = await solveAfter(page, () => remesh(page), 300_000);
    if (made !== panels) throw new Error(`asked for ${panels} panels, got ${made}`);
    const times = await page.locator('#stats').evaluate((element) => ({ worker: Number(element.dataset.solveSeconds), core: Number(element.dataset.coreSeconds) }));
    worker.push(times.worker);
    core.push(times.core);
  }
  if (errors.length) throw new Error(errors.join('\n'));
  const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];
  console.log(`browser: hyperboloid_s4.off -> ${panels} panels, ${runs} cold solves in the page's worker after one warm-up`);
  console.log(`browser: worker solve ${median(worker).toFixed(3)} s median (runs: ${worker.map((t) => t.toFixed(3)).join(', ')}); core timings_s.total ${median(core).toFixed(3)} s median`);
  const native = nativeRuns(panels, runs);
  const solve = median(native.map((r) => r.solve));
  console.log(`native: flatfacet remesh solve ${solve.toFixed(3)} s median (cluster + panels + quality), whole process ${median(native.map((r) => r.wall)).toFixed(3)} s median`);
  console.log(`browser / native (solve): ${(median(worker) / solve).toFixed(2)} (target <= 2)`);
} finally {
  await browser.close();
  await server.close();
}

// The native CLI, same mesh, panel count and default seed: per run the report's solve time
// and the wall time of the whole process (read, clean, solve, quality, write).
function nativeRuns(panels, runs) {
  const cli = path.join(root, 'build/release/cli/flatfacet');
  const dir = mkdtempSync(path.join(os.tmpdir(), 'ff-browser-bench-'));
  const out = [];
  for (let run = 0; run < runs; run++) {
    const t0 = performance.now();
    try {
      execFileSync(cli, ['remesh', path.join(meshes, 'hyperboloid_s4.off'), '--panels', String(panels), '--report', path.join(dir, 'r.json')]);
    } catch (e) {
      if (e.status !== 3) throw e;
    }
    const wall = (performance.now() - t0) / 1000;
    const t = JSON.parse(readFileSync(path.join(dir, 'r.json'), 'utf8')).timings_s;
    out.push({ wall, solve: t.cluster + t.panels + t.quality });
  }
  return out;
}
