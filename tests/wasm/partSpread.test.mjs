// A part far from the rest (core/mesh/part_spread.h) is refused by name when the page opens the
// mesh, and the mesh already loaded stays, as with every bad input.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { json, loadModule, meshes, solve } from './module.mjs';

const ff = await loadModule();

test('a triangle 1e8 away from epcot is refused by name; the loaded mesh stays', () => {
  const text = readFileSync(path.join(meshes, 'epcot.off'), 'utf8');
  const tokens = text.split(/\s+/).filter(Boolean);
  const [nv, nf] = [Number(tokens[1]), Number(tokens[2])];
  const rows = [];
  for (let i = 0; i < nv; ++i) rows.push(tokens.slice(4 + 3 * i, 7 + 3 * i).join(' '));
  rows.push('1e8 0 0', '100000000.01 0 0', '1e8 0.01 0');
  for (let f = 0, at = 4 + 3 * nv; f < nf; ++f, at += 1 + Number(tokens[at])) rows.push(tokens.slice(at, at + 1 + Number(tokens[at])).join(' '));
  rows.push(`3 ${nv} ${nv + 1} ${nv + 2}`);
  const far = new TextEncoder().encode(`OFF\n${nv + 3} ${nf + 1} 0\n${rows.join('\n')}\n`);
  const s = new ff.Session();
  try {
    assert.equal(json(s.loadMesh('epcot.off', new TextEncoder().encode(text))).ok, true);
    const refused = json(s.loadMesh('far.off', far));
    assert.equal(refused.ok, false);
    assert.match(refused.message, /a part of 1 triangle near \(1e\+08, 0\.005, 0\) lies .* times the largest part's size .* delete the far-off part/);
    assert.equal(json(s.setParams(JSON.stringify({ panels: 30, seed: 1 }))).ok, true);
    solve(s);
    const report = json(s.reportJson());
    assert.equal(report.triangles, 1536, 'epcot is still the loaded mesh');
    assert.equal(report.panels, 30);
  } finally {
    s.delete();
  }
});
