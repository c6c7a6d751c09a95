// A vertex far from all the others (core/mesh/vertex_spread.h) is refused by name when the page
// opens the mesh, and the mesh already loaded stays. Keeping the largest part would not help
// (the vertex is in it), so no part is offered.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { json, loadModule, meshes, solve } from './module.mjs';
import { offWithStrayVertex } from '../fixtures/meshes.mjs';

const ff = await loadModule();

test('a vertex of epcot typed as 4294967296 is refused by name; the loaded mesh stays', () => {
  const text = readFileSync(path.join(meshes, 'epcot.off'), 'utf8');
  const s = new ff.Session();
  try {
    assert.equal(json(s.loadMesh('epcot.off', new TextEncoder().encode(text))).ok, true);
    const refused = json(s.loadMesh('stray.off', offWithStrayVertex(text, 7, 1, '4294967296')));
    assert.equal(refused.ok, false);
    assert.match(refused.message, /^vertex 7 at \(1\.011, 4\.29497e\+09, 0\.274\) lies 4\.09e\+09 times farther .* fix or delete it$/);
    assert.equal(refused.largestPart, undefined);
    assert.equal(json(s.setParams(JSON.stringify({ panels: 30, seed: 1 }))).ok, true);
    solve(s);
    const report = json(s.reportJson());
    assert.equal(report.triangles, 1536, 'epcot is still the loaded mesh');
    assert.equal(report.invalid_panels, 0);
  } finally {
    s.delete();
  }
});
