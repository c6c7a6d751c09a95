// Per-panel edits through the wasm Session as the page drives them (issue 6): edits arrive in
// setParams' JSON, undo / redo are a shorter / longer list, the result matches the native CLI
// given the same list (`flatfacet remesh --edits`), and a bad edit leaves the previous design.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { json, loadModule, meshes, parseObj, root, solve } from './module.mjs';

const ff = await loadModule();

// Two triangles across an edge on different panels.
function neighbourFaces(s) {
  const ids = s.clusterIds();
  const tri = s.inputIndices();
  const seen = new Map();
  for (let f = 0; f < ids.length; ++f) {
    for (let k = 0; k < 3; ++k) {
      const a = tri[3 * f + k];
      const b = tri[3 * f + ((k + 1) % 3)];
      const key = a < b ? `${a},${b}` : `${b},${a}`;
      const g = seen.get(key);
      if (g !== undefined && ids[g] !== ids[f]) return [g, f];
      seen.set(key, f);
    }
  }
  throw new Error('no two panels share an edge');
}

function largestPanel(s) {
  const counts = new Map();
  for (const c of s.clusterIds()) counts.set(c, (counts.get(c) ?? 0) + 1);
  return [...counts.entries()].sort((x, y) => y[1] - x[1] || x[0] - y[0])[0][0];
}

test('edits in setParams: counts, locks, undo / redo, the native result, bad edits', () => {
  const file = 'inspired_mesh.obj';
  const input = path.join(meshes, file);
  const s = new ff.Session();
  assert.equal(json(s.loadMesh(file, readFileSync(input))).ok, true);
  const base = { panels: 42, seed: 5 };
  assert.equal(json(s.setParams(JSON.stringify(base))).ok, true);
  solve(s);
  assert.equal(s.panelCount(), 42);
  assert.equal(s.lockedPanels().length, 0);

  const big = largestPanel(s);
  const splitFace = s.panelFace(big);
  assert.equal(s.panelOfFace(splitFace), big);
  assert.equal(s.panelFace(42), -1);
  assert.equal(s.panelOfFace(-1), -1);
  const edits = [{ op: 'split', face: splitFace }];
  assert.equal(json(s.setParams(JSON.stringify({ ...base, edits }))).ok, true);
  assert.equal(s.done(), true);
  assert.equal(s.panelCount(), 43);
  const afterSplit = s.objText();
  assert.equal(parseObj(afterSplit).faces.length, 43);

  const [a, b] = neighbourFaces(s);
  edits.push({ op: 'merge', face: a, with: b });
  assert.equal(json(s.setParams(JSON.stringify({ ...base, edits }))).ok, true);
  assert.equal(s.panelCount(), 42);
  assert.equal(s.panelOfFace(a), s.panelOfFace(b));
  const lockFace = s.panelFace(0);
  edits.push({ op: 'lock', face: lockFace });
  assert.equal(json(s.setParams(JSON.stringify({ ...base, edits }))).ok, true);
  assert.deepEqual([...s.lockedPanels()], [s.panelOfFace(lockFace)]);
  const full = s.objText();
  assert.equal(json(s.reportJson()).panels, 42);

  // The native CLI replays the same list on a fresh solve: the same polygons.
  const flatfacet = path.join(root, 'build/release/cli/flatfacet');
  assert.ok(existsSync(flatfacet), `${flatfacet} missing: build the native CLI first`);
  const dir = mkdtempSync(path.join(os.tmpdir(), 'ff-edits-'));
  writeFileSync(path.join(dir, 'edits.json'), JSON.stringify(edits));
  const out = path.join(dir, 'panels.obj');
  try {
    execFileSync(flatfacet, ['remesh', input, '--panels', '42', '--seed', '5', '--edits', path.join(dir, 'edits.json'), '--out', out]);
  } catch (e) {
    if (e.status !== 3) throw e; // 3: written with invalid panels, still comparable
  }
  const native = parseObj(readFileSync(out, 'utf8'));
  const wasm = parseObj(full);
  assert.deepEqual(wasm.faces, native.faces, 'the same polygons on the same vertices');
  const scale = Math.max(...native.vertices.flat().map(Math.abs));
  let worst = 0;
  native.vertices.forEach((v, i) => v.forEach((x, k) => (worst = Math.max(worst, Math.abs(x - wasm.vertices[i][k])))));
  assert.ok(worst <= 1e-6 * scale, `vertices differ by ${worst} (model size ${scale})`); // see session.test.mjs

  // Bad edits: an error naming the problem, and the design as it was.
  const bad = [
    [{ op: 'merge', face: a, with: a }, /same panel/],
    [{ op: 'split', face: 1e6 }, /out of range/],
    [{ op: 'unlock', face: splitFace === lockFace ? a : splitFace }, /not locked/],
    [{ op: 'twist', face: 1 }, /op/],
    [{ op: 'split', face: 1, with: 2 }, /with/],
  ];
  for (const [edit, message] of bad) {
    const status = json(s.setParams(JSON.stringify({ ...base, edits: [...edits, edit] })));
    assert.equal(status.ok, false, JSON.stringify(edit));
    assert.match(status.message, message);
    assert.equal(s.objText(), full);
    assert.equal(s.panelCount(), 42);
    assert.equal(s.lockedPanels().length, 1);
  }

  // Undo to the split alone, then redo: the same designs again.
  assert.equal(json(s.setParams(JSON.stringify({ ...base, edits: edits.slice(0, 1) }))).ok, true);
  assert.equal(s.objText(), afterSplit);
  assert.equal(s.lockedPanels().length, 0);
  assert.equal(json(s.setParams(JSON.stringify({ ...base, edits }))).ok, true);
  assert.equal(s.objText(), full);
  s.delete();
});

test('the count after edits is no change: the same panels, no solve; panels per triangle for the page', () => {
  const file = 'inspired_mesh.obj';
  const s = new ff.Session();
  assert.equal(json(s.loadMesh(file, readFileSync(path.join(meshes, file)))).ok, true);
  const base = { panels: 42, seed: 5 };
  assert.equal(json(s.setParams(JSON.stringify(base))).ok, true);
  solve(s);
  const edits = [{ op: 'split', face: s.panelFace(largestPanel(s)) }];
  assert.equal(json(s.setParams(JSON.stringify({ ...base, edits }))).ok, true);
  assert.equal(s.panelCount(), 43);
  const split = s.objText();
  // The page shows 43 and may send it back: no change (done, the same bytes); so is 42.
  for (const panels of [43, 42]) {
    assert.equal(json(s.setParams(JSON.stringify({ ...base, panels, edits }))).ok, true);
    assert.equal(s.done(), true, `${panels}: no re-solve`);
    assert.equal(s.objText(), split, `${panels}: the same panels`);
  }
  // More edits with the count now are edited in place, as with the target.
  const [a, b] = neighbourFaces(s);
  const merged = [...edits, { op: 'merge', face: a, with: b }];
  assert.equal(json(s.setParams(JSON.stringify({ ...base, panels: 43, edits: merged }))).ok, true);
  assert.equal(s.done(), true, 'edited in place');
  assert.equal(s.panelCount(), 42);
  // Undo (the shorter list, the target): the split design back, byte for byte.
  assert.equal(json(s.setParams(JSON.stringify({ ...base, edits }))).ok, true);
  assert.equal(s.objText(), split);
  // Per triangle, its panel in the panel mesh: here (no glass) the cluster's panel.
  const facePanels = s.facePanels();
  const clusters = s.clusterIds();
  assert.equal(facePanels.length, clusters.length);
  const panelOf = new Map();
  for (let f = 0; f < clusters.length; f++) {
    assert.ok(facePanels[f] >= 0 && facePanels[f] < 43);
    if (panelOf.has(clusters[f])) assert.equal(panelOf.get(clusters[f]), facePanels[f], 'one panel per cluster');
    panelOf.set(clusters[f], facePanels[f]);
  }
  assert.equal(panelOf.size, 43);
  s.delete();
});
