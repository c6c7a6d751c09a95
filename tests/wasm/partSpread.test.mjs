// A part far from the rest (core/mesh/part_spread.h) is refused by name when the page opens the
// mesh, and the mesh already loaded stays, as with every bad input. The refusal carries the
// largest part's size, so the page offers it as for non-manifold edges (Session.setRepair).
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { json, loadModule, meshes, solve } from './module.mjs';
import { offWithFarTriangle } from '../fixtures/meshes.mjs';

const ff = await loadModule();

// epcot.off, and epcot.off with one triangle 1e8 away.
function epcotWithFarTriangle() {
  const text = readFileSync(path.join(meshes, 'epcot.off'), 'utf8');
  return { text, far: offWithFarTriangle(text) };
}

test('a triangle 1e8 away from epcot is refused by name; the loaded mesh stays', () => {
  const { text, far } = epcotWithFarTriangle();
  const s = new ff.Session();
  try {
    assert.equal(json(s.loadMesh('epcot.off', new TextEncoder().encode(text))).ok, true);
    const refused = json(s.loadMesh('far.off', far));
    assert.equal(refused.ok, false);
    assert.match(refused.message, /a part of 1 triangle near \(1e\+08, 0\.005, 0\) lies .* times the main part's size .* delete the far-off part/);
    assert.deepEqual(refused.largestPart, { faces: 1536, of: 1537 });
    assert.equal(json(s.setParams(JSON.stringify({ panels: 30, seed: 1 }))).ok, true);
    solve(s);
    const report = json(s.reportJson());
    assert.equal(report.triangles, 1536, 'epcot is still the loaded mesh');
    assert.equal(report.panels, 30);
  } finally {
    s.delete();
  }
});

test('with largestPart the far-off triangle is dropped and epcot solves', () => {
  const { far } = epcotWithFarTriangle();
  const s = new ff.Session();
  try {
    assert.equal(json(s.setRepair(0, true)).ok, true);
    const info = json(s.loadMesh('far.off', far));
    assert.equal(info.ok, true, info.message);
    assert.equal(info.triangles, 1536);
    assert.equal(info.components, 1);
    assert.deepEqual(info.repair, { fillHoles: 0, largestPart: true, slivers: 0, holesFilled: 0, holeFaces: 0, nonmanifoldEdgesCut: 0, facesDropped: 1, partsDropped: 1 });
    assert.deepEqual(info.cleanup, ['kept the largest part (1536 of 1537 faces): dropped 1 face in 1 other part']);
    assert.equal(json(s.setParams(JSON.stringify({ panels: 30, seed: 1 }))).ok, true);
    solve(s);
    const report = json(s.reportJson());
    assert.equal(report.panels, 30);
    assert.equal(report.invalid_panels, 0);
    assert.ok(report.max_planarity <= 1e-9, String(report.max_planarity));
  } finally {
    s.delete();
  }
});
