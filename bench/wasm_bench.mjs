// WebAssembly against native, in one run on one machine (issue 4 benchmark):
//  1. hyperboloid_s4.off into 500 panels: the wasm module in Node vs `flatfacet remesh`
//     (the page's time comes from bench/browser_bench.mjs, same mesh and count);
//  2. wasm memory at 1M triangles (a generated freeform roof into 1000 panels).
// Usage: node bench/wasm_bench.mjs [--skip-1m]   (after scripts/build_wasm.sh and the native build)
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { json, loadModule, meshes, root, solve } from '../tests/wasm/module.mjs';

const cli = path.join(root, 'build/release/cli/flatfacet');
const ff = await loadModule();
const repeat = Number(process.env.FF_BENCH_REPEAT ?? 3);

function wasmSolve(load, params) {
  const s = new ff.Session();
  const t0 = performance.now();
  const info = json(load(s));
  if (!info.ok) throw new Error(info.message);
  json(s.setParams(JSON.stringify(params)));
  solve(s);
  const report = json(s.reportJson()); // includes the quality measurement, as the CLI's total does
  const seconds = (performance.now() - t0) / 1000;
  s.delete();
  return { seconds, report };
}

function nativeSolve(file, panels) {
  const dir = mkdtempSync(path.join(os.tmpdir(), 'ff-bench-'));
  const t0 = performance.now();
  try {
    execFileSync(cli, ['remesh', file, '--panels', String(panels), '--report', path.join(dir, 'r.json')]);
  } catch (e) {
    if (e.status !== 3) throw e;
  }
  const seconds = (performance.now() - t0) / 1000;
  return { seconds, report: JSON.parse(readFileSync(path.join(dir, 'r.json'), 'utf8')) };
}

const best = (runs) => runs.reduce((a, b) => (b.seconds < a.seconds ? b : a));
const file = path.join(meshes, 'hyperboloid_s4.off');
const bytes = readFileSync(file);
const native = best(Array.from({ length: repeat }, () => nativeSolve(file, 500)));
const wasm = best(
  Array.from({ length: repeat }, () => wasmSolve((s) => s.loadMesh('hyperboloid_s4.off', bytes), { panels: 500 })),
);
const row = (name, r) =>
  `| ${name} | ${r.seconds.toFixed(3)} | ${r.report.panels} | ${r.report.status} | ${r.report.iterations.panel_rounds} | ${r.report.hausdorff.toExponential(3)} |`;
console.log('hyperboloid_s4.off (50,454 triangles) into 500 panels, best of', repeat, '(whole process: read to report)');
console.log('| build | seconds | panels | status | panel rounds | hausdorff |');
console.log('|---|---|---|---|---|---|');
console.log(row('native CLI', native));
console.log(row('wasm (Node)', wasm));
console.log(`wasm / native: ${(wasm.seconds / native.seconds).toFixed(2)}`);

if (!process.argv.includes('--skip-1m')) {
  const m = wasmSolve((s) => s.loadShape('freeform_roof', 1_000_000), { panels: 1000 });
  const mib = ff.HEAPU8.length / 2 ** 20;
  console.log(
    `1M triangles (freeform_roof, ${m.report.triangles} triangles) into 1000 panels: ${m.seconds.toFixed(1)} s, ` +
      `${m.report.status}, wasm memory ${mib.toFixed(0)} MiB (target <= 1024)`,
  );
}
