// Session.setRepair, the page's mesh repair (issue 7): a mesh with a non-manifold edge is
// refused naming the edge and how large its largest manifold part is; with largestPart it
// loads that part and solves to valid panels; holes are filled only when asked and small
// enough; bad options are refused and change nothing. A surface that passes through itself is
// told on load (not repaired).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { cubeOff, twoCubesObj } from '../fixtures/meshes.mjs';
import { json, loadModule, maxPlanarity, meshes, parseObj, solve } from './module.mjs';

const ff = await loadModule();

test('a non-manifold edge is named, with the size of the largest manifold part', () => {
  const s = new ff.Session();
  const refused = json(s.loadMesh('twocubes.obj', twoCubesObj()));
  assert.equal(refused.ok, false);
  assert.match(refused.message, /non-manifold edge between vertices \d+ and \d+ at \(1, 1, 0\.5\): shared by 4 faces/);
  assert.deepEqual(refused.largestPart, { faces: 12, of: 24 });
  s.delete();
});

test('with largestPart the load keeps one closed cube, says what it dropped, and solves', () => {
  const s = new ff.Session();
  assert.equal(json(s.setRepair(0, true)).ok, true);
  const info = json(s.loadMesh('twocubes.obj', twoCubesObj()));
  assert.equal(info.ok, true, info.message);
  assert.equal(info.triangles, 12);
  assert.equal(info.vertices, 8);
  assert.equal(info.components, 1);
  assert.equal(info.boundaryLoops, 0);
  assert.equal(info.euler, 2);
  assert.deepEqual(info.repair, { fillHoles: 0, largestPart: true, slivers: 0, holesFilled: 0, holeFaces: 0, nonmanifoldEdgesCut: 1, facesDropped: 12, partsDropped: 1 });
  assert.ok(info.cleanup.some((line) => line.startsWith('kept the largest manifold part (12 of 24 faces)')), info.cleanup.join(' | '));
  assert.equal(json(s.prepare(6, 0, 0, 0, 0)).ok, true);
  assert.equal(json(s.setParams(JSON.stringify({ panels: 6 }))).ok, true);
  solve(s);
  const report = json(s.reportJson());
  assert.equal(report.invalid_panels, 0);
  assert.equal(report.topology_preserved, true);
  assert.ok(maxPlanarity(parseObj(s.objText())) <= 1e-9);
  s.delete();
});

test('holes are filled only when asked and no larger than asked', () => {
  const s = new ff.Session();
  const holed = cubeOff([0, 1]); // the bottom square: one hole of 4 edges
  const open = json(s.loadMesh('holed.off', holed));
  assert.equal(open.ok, true, open.message);
  assert.equal(open.boundaryLoops, 1);
  assert.equal(open.repair.holesFilled, 0);
  assert.equal(json(s.setRepair(3, false)).ok, true);
  assert.equal(json(s.loadMesh('holed.off', holed)).boundaryLoops, 1, '4 edges > 3');
  assert.equal(json(s.setRepair(4, false)).ok, true);
  const closed = json(s.loadMesh('holed.off', holed));
  assert.equal(closed.boundaryLoops, 0);
  assert.equal(closed.euler, 2);
  assert.equal(closed.triangles, 12);
  assert.equal(closed.repair.holesFilled, 1);
  assert.equal(closed.repair.holeFaces, 2);
  s.delete();
});

test('bad repair options are refused and the next load is as before', () => {
  const s = new ff.Session();
  for (const edges of [-1, 501]) {
    const status = json(s.setRepair(edges, false));
    assert.equal(status.ok, false);
    assert.match(status.message, /holes to fill must have 0 \(off\) to 500 edges/);
  }
  assert.equal(json(s.loadMesh('twocubes.obj', twoCubesObj())).ok, false, 'still refused: largestPart unchanged');
  s.delete();
});

// Points (flat x y z) grouped by single linkage at `reach`: how many groups.
function groupsOf(flat, reach) {
  const n = flat.length / 3;
  const group = Array.from({ length: n }, (_, i) => i);
  const root = (i) => (group[i] === i ? i : (group[i] = root(group[i])));
  for (let i = 0; i < n; i++) {
    for (let j = i + 1; j < n; j++) {
      const d = Math.hypot(flat[3 * i] - flat[3 * j], flat[3 * i + 1] - flat[3 * j + 1], flat[3 * i + 2] - flat[3 * j + 2]);
      if (d < reach) group[root(i)] = root(j);
    }
  }
  return new Set(group.map((_, i) => root(i))).size;
}

// Not repaired, but told on load: the cow's tail goes into its rump (83 pairs of its triangles
// cross there), and panels made from it would pass through each other at any count.
test('a surface that passes through itself is told on load, with where', () => {
  const s = new ff.Session();
  const cow = json(s.loadMesh('cow.off', readFileSync(path.join(meshes, 'cow.off'))));
  assert.equal(cow.ok, true, cow.message);
  assert.equal(cow.selfCrossings, 83);
  assert.equal(cow.selfCrossingPoint.length, 3);
  assert.ok(cow.selfCrossingPoint[0] < -0.3, `the tail is at the back: ${cow.selfCrossingPoint}`);
  // Every pair's point, for the page's markers: the first is the one above, all at the back.
  assert.equal(cow.selfCrossingPoints.length, 83 * 3);
  assert.deepEqual(cow.selfCrossingPoints.slice(0, 3), cow.selfCrossingPoint);
  for (let i = 0; i < cow.selfCrossingPoints.length; i += 3) assert.ok(cow.selfCrossingPoints[i] < -0.3, `pair ${i / 3} is at the back`);
  // In 4 places (pairs joined through shared triangles and corners). Seen from the points
  // alone: grouped by distance (any two closer than 2% of the cow's size joined), they make the
  // same number of groups.
  assert.equal(cow.selfCrossingPlaces, 4);
  assert.equal(groupsOf(cow.selfCrossingPoints, 0.02 * cow.bboxDiagonal), 4);
  const bunny = json(s.loadMesh('bunny.off', readFileSync(path.join(meshes, 'bunny.off'))));
  assert.equal(bunny.selfCrossings, 0);
  assert.deepEqual(bunny.selfCrossingPoint, [0, 0, 0]);
  assert.deepEqual(bunny.selfCrossingPoints, []);
  assert.equal(bunny.selfCrossingPlaces, 0);
  s.delete();
});

// Each solve's report takes the crossings found on load while the mesh is the one loaded (not
// checked again), and checks a prepared mesh itself: subdivided, the cow crosses itself at more
// pairs of its finer triangles.
test("the report's input crossings are the loaded mesh's, or the prepared mesh's own", () => {
  const s = new ff.Session();
  const cow = json(s.loadMesh('cow.off', readFileSync(path.join(meshes, 'cow.off'))));
  assert.equal(json(s.prepareAsLoaded()).ok, true);
  assert.equal(json(s.setParams(JSON.stringify({ panels: 30 }))).ok, true);
  solve(s);
  const loaded = json(s.reportJson());
  assert.equal(loaded.input_crossings, cow.selfCrossings);
  assert.deepEqual(loaded.input_crossing_point, cow.selfCrossingPoint);
  assert.equal(loaded.input_crossing_places, cow.selfCrossingPlaces);
  const subdivided = json(s.prepare(30, 1, 0, 0, 0));
  assert.equal(subdivided.ok, true, subdivided.message);
  assert.equal(json(s.setParams(JSON.stringify({ panels: 30 }))).ok, true);
  solve(s);
  assert.ok(json(s.reportJson()).input_crossings > cow.selfCrossings, 'the finer mesh checked itself');
  assert.equal(json(s.prepareAsLoaded()).ok, true);
  solve(s);
  assert.equal(json(s.reportJson()).input_crossings, cow.selfCrossings, 'as loaded again');
  s.delete();
});
