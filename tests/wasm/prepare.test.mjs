// Session.prepare, the page's preparation of an opened mesh (issue 7): a coarse quad mesh is
// refined for its panel count and solves to valid panels; subdivision of the file's quads;
// a mesh fine enough stays exactly as loaded; bad requests come back as messages and leave
// the loaded mesh as it was.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { json, loadModule, maxPlanarity, meshes, parseObj, solve } from './module.mjs';

const ff = await loadModule();
const yas = readFileSync(path.join(meshes, 'YasIsland.off'));

function loaded(file = 'YasIsland.off', bytes = yas) {
  const s = new ff.Session();
  const info = json(s.loadMesh(file, bytes));
  assert.equal(info.ok, true, info.message);
  return { s, info };
}

test('a coarse quad mesh is refined for its panels, says so, and solves to valid planar panels', () => {
  const { s, info } = loaded();
  assert.equal(info.triangles, 1952);
  const prepared = json(s.prepare(300, 0));
  assert.equal(prepared.ok, true, prepared.message);
  assert.ok(prepared.triangles >= 300 * 20, `${prepared.triangles} triangles for 300 panels`);
  assert.ok(prepared.prepared.some((line) => /^refined 1,952 triangles to [\d,]+ .*300 panels/.test(line)), prepared.prepared.join(' | '));
  assert.equal(prepared.euler, info.euler, 'topology kept');
  assert.equal(prepared.boundaryLoops, info.boundaryLoops);
  assert.equal(s.inputIndices().length, prepared.triangles * 3, 'the page is shown the prepared mesh');
  assert.equal(json(s.setParams(JSON.stringify({ panels: 300 }))).ok, true);
  assert.equal(solve(s).stage, 'Done');
  const report = json(s.reportJson());
  assert.equal(report.invalid_panels, 0);
  assert.equal(report.topology_preserved, true);
  assert.ok(maxPlanarity(parseObj(s.objText())) <= 1e-9);
  s.delete();
});

test('subdivision levels use the file\'s quads (Catmull-Clark) and name what they did', () => {
  const { s } = loaded();
  const prepared = json(s.prepare(150, 1));
  assert.equal(prepared.ok, true, prepared.message);
  assert.equal(prepared.triangles, 976 * 4 * 2, 'each quad into 4 quads, each quad into 2 triangles');
  assert.match(prepared.prepared.join(' | '), /subdivided 976 polygons 1 level \(catmull-clark\) into 7,808 triangles/);
  s.delete();
});

test('a mesh fine enough for its panels stays exactly as loaded', () => {
  const inspired = readFileSync(path.join(meshes, 'inspired_mesh.obj'));
  const { s, info } = loaded('inspired_mesh.obj', inspired);
  const before = s.inputPositions();
  const prepared = json(s.prepare(42, 0));
  assert.deepEqual(prepared, info, 'the same mesh info, no notes added');
  assert.deepEqual(s.inputPositions(), before);
  s.delete();
});

test('bad requests are refused by name and the loaded mesh stays', () => {
  const { s, info } = loaded();
  for (const [panels, levels, pattern] of [
    [150, 5, /subdivision levels must be 0 to 4/],
    [150, -1, /subdivision levels must be 0 to 4/],
    [0, 0, /panel count must be at least 1/],
    [5_000_000, 0, /at most/],
  ]) {
    const status = json(s.prepare(panels, levels));
    assert.equal(status.ok, false, `prepare(${panels}, ${levels})`);
    assert.match(status.message, pattern);
    assert.equal(s.inputIndices().length, info.triangles * 3, 'still the loaded mesh');
  }
  assert.equal(json(s.prepare(300, 0)).ok, true);
  assert.match(json(s.prepare(300, 0)).message, /already prepared/);
  const empty = new ff.Session();
  assert.match(json(empty.prepare(10, 0)).message, /no mesh loaded/);
  empty.delete();
  s.delete();
});
