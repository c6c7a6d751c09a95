// Loads the CommonJS wasm build (build/wasm/node, from scripts/build_wasm.sh) for Node tests,
// and small helpers the tests share: run a solve to the end, parse an OBJ, measure planarity.
import { createRequire } from 'node:module';
import { existsSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import path from 'node:path';

export const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
export const meshes = process.env.FF_SHARED_MESHES ?? path.resolve(root, '../shared/meshes');
const js = path.join(root, 'build/wasm/node/flatfacet_node.cjs');

export async function loadModule() {
  if (!existsSync(js)) throw new Error(`${js} is missing: run scripts/build_wasm.sh first`);
  const create = createRequire(import.meta.url)(js);
  // Node's global fetch cannot load the .wasm from a path (toolchain.md 6): hand it the bytes.
  return create({ wasmBinary: readFileSync(js.replace(/\.cjs$/, '.wasm')) });
}

export function json(text) {
  return JSON.parse(text);
}

// Steps to the end; returns the last progress. Fails on an error status or a runaway loop.
export function solve(session, maxSteps = 10000) {
  for (let i = 0; i < maxSteps; ++i) {
    const p = json(session.step());
    if (!p.ok) throw new Error(`step failed: ${p.message}`);
    if (p.done) return p;
  }
  throw new Error(`not done after ${maxSteps} steps`);
}

// v and f lines of an OBJ (comments dropped).
export function parseObj(text) {
  const vertices = [];
  const faces = [];
  for (const line of text.split('\n')) {
    const t = line.trim().split(/\s+/);
    if (t[0] === 'v') vertices.push(t.slice(1, 4).map(Number));
    else if (t[0] === 'f') faces.push(t.slice(1).map((s) => Number(s) - 1));
  }
  return { vertices, faces };
}

export function objBody(text) {
  return text
    .split('\n')
    .filter((l) => !l.startsWith('#'))
    .join('\n');
}

// Max over faces of (max distance of its vertices to the plane through the centroid with the
// Newell normal) / (face diameter): the report's planarity, computed independently here.
export function maxPlanarity({ vertices, faces }) {
  let worst = 0;
  for (const f of faces) {
    const p = f.map((i) => vertices[i]);
    const c = [0, 1, 2].map((k) => p.reduce((s, q) => s + q[k], 0) / p.length);
    const n = [0, 0, 0];
    for (let i = 0; i < p.length; ++i) {
      const a = p[i];
      const b = p[(i + 1) % p.length];
      n[0] += (a[1] - b[1]) * (a[2] + b[2]);
      n[1] += (a[2] - b[2]) * (a[0] + b[0]);
      n[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    const len = Math.hypot(...n);
    let diameter = 0;
    for (const a of p) for (const b of p) diameter = Math.max(diameter, Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
    for (const q of p) {
      const d = Math.abs(n.reduce((s, nk, k) => s + (nk / len) * (q[k] - c[k]), 0));
      worst = Math.max(worst, d / diameter);
    }
  }
  return worst;
}
