// Unit tests of web/src/preparation.ts (compiled to build/web-tests by `npm run test:web`):
// when the page prepares the design's mesh again for its panel count (issue 7), and how the
// carried paint levels and panel edits come back into the parameters; and the strict check of
// a preparation (with a target edge length) in links and the stored session (share.ts).
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { DEFAULT_PARAMS } from '../../build/web-tests/params.js';
import { carriedParams, editFaces, HUGE_TRIANGLES, levelsOf, MAX_PAGE_REFINE_TRIANGLES, MIN_TRIANGLES_PER_PANEL, preparationNeeded, prepareOf, REFINE_ROUNDS, REFINE_TRIANGLES_PER_PANEL, refusedPreparation, remapEdits, samePrepare } from '../../build/web-tests/preparation.js';
import { checkPrepare, hashToState, LEGACY_REFINE_BELOW, LEGACY_REFINE_ROUNDS, stateToHash } from '../../build/web-tests/share.js';

const opened = { panels: 150, subdivide: 0 }; // Yas Island as opened: 1,952 triangles refined

test('raising the panel count past 30 triangles per panel prepares the mesh again; lowering it does not', () => {
  const triangles = 7400; // about 50 per panel for 150
  const auto = { subdivide: 0 };
  assert.equal(preparationNeeded(opened, triangles, 150, auto), null, 'the count it was prepared for');
  assert.equal(preparationNeeded(opened, 7500, 7500 / REFINE_TRIANGLES_PER_PANEL, auto), null, 'exactly 30 per panel serves');
  assert.deepEqual(preparationNeeded(opened, 7500, 7500 / REFINE_TRIANGLES_PER_PANEL + 1, auto), { panels: 251, subdivide: 0, refineBelow: 30, refineRounds: 5 });
  assert.deepEqual(preparationNeeded(opened, triangles, Math.floor(triangles / MIN_TRIANGLES_PER_PANEL) + 1, auto), { panels: 371, subdivide: 0, refineBelow: 30, refineRounds: 5 });
  assert.deepEqual(preparationNeeded(opened, triangles, 1200, auto), { panels: 1200, subdivide: 0, refineBelow: 30, refineRounds: 5 });
  assert.equal(preparationNeeded(opened, triangles, 10, auto), null, 'lowering keeps the finer mesh');
  // ...unless the mesh is huge for the count (the core would coarsen it).
  assert.equal(preparationNeeded(opened, HUGE_TRIANGLES, 100, auto), null);
  assert.deepEqual(preparationNeeded(opened, HUGE_TRIANGLES + 1000, 100, auto), { panels: 100, subdivide: 0, refineBelow: 30, refineRounds: 5 });
  // From 20 to 30 per panel only where 50 per panel are within the page's refinement cap:
  // beyond it the mesh serves as it is (below 20 it would be refused by name, next test).
  const big = 200_000;
  assert.equal(MAX_PAGE_REFINE_TRIANGLES, 400_000);
  assert.equal(preparationNeeded(opened, big, 10_000, auto), null, '20 per panel: 500,000 wanted, past the cap');
  assert.deepEqual(preparationNeeded(opened, big, 8000, auto), { panels: 8000, subdivide: 0, refineBelow: 30, refineRounds: 5 }, '25 per panel: 400,000 wanted');
  // A design saved before the 30 (no refineBelow) keeps its mesh at the count it was saved
  // with, and at lower ones (its edits and paint name that mesh); a higher count gets the rule now.
  const older = { panels: 12, subdivide: 0 };
  assert.equal(preparationNeeded(older, 288, 12, auto), null, '24 per panel, the count it was saved with');
  assert.equal(preparationNeeded(older, 288, 10, auto), null);
  assert.deepEqual(preparationNeeded(older, 288, 13, auto), { panels: 13, subdivide: 0, refineBelow: 30, refineRounds: 5 });
  // The same preparation again is never needed (the same mesh).
  const made = { panels: 300, subdivide: 0, refineBelow: 30, refineRounds: 5 };
  assert.equal(preparationNeeded(made, 5000, 300, auto), null, 'even below 20 per panel');
  assert.deepEqual(preparationNeeded({ ...made, refineRounds: 10 }, 5000, 300, auto), made, 'other rounds: another preparation');
  // A count whose 50 per panel pass the page's cap is prepared with the rule before.
  assert.equal(preparationNeeded(opened, 1000, 9000, auto).refineBelow, MIN_TRIANGLES_PER_PANEL);
  // A design from a link made before preparations were recorded: the same rule.
  assert.deepEqual(preparationNeeded(undefined, 1952, 150, auto), { panels: 150, subdivide: 0, refineBelow: 30, refineRounds: 5 });
});

test('a refinement beyond what a browser tab should make is refused by name; an edge length opts in', () => {
  assert.equal(refusedPreparation({ panels: 8000, subdivide: 0 }, 8000), null, '400,000 triangles: made');
  assert.match(refusedPreparation({ panels: 8001, subdivide: 0 }, 8000), /^8,001 panels need the mesh refined to about 400,050 triangles, more than the page makes \(400,000\); ask for at most 8,000 panels, or set a Target edge length$/);
  assert.equal(refusedPreparation({ panels: 99999, subdivide: 0, edgeLength: 0.01 }, 8000), null, 'the core checks an edge length itself');
  assert.equal(refusedPreparation({ panels: 9000, subdivide: 1 }, 500_000), null, 'not a refinement for the count');
});

test('a new subdivision or edge length prepares again; with an edge length the count does not', () => {
  assert.deepEqual(preparationNeeded(opened, 7400, 150, { subdivide: 1 }), { panels: 150, subdivide: 1, refineBelow: 30, refineRounds: 5 });
  assert.deepEqual(preparationNeeded(opened, 7400, 150, { subdivide: 0, edgeLength: 0.5 }), { panels: 150, subdivide: 0, edgeLength: 0.5, refineBelow: 30, refineRounds: 5 });
  const fixed = { panels: 150, subdivide: 0, edgeLength: 0.5 };
  assert.equal(preparationNeeded(fixed, 7400, 5000, { subdivide: 0, edgeLength: 0.5 }), null, 'the designer\'s resolution stays');
  assert.deepEqual(preparationNeeded(fixed, 7400, 150, { subdivide: 0 }), { panels: 150, subdivide: 0, refineBelow: 30, refineRounds: 5 }, 'back to automatic');
  assert.ok(samePrepare(fixed, { ...fixed }));
  assert.ok(!samePrepare(fixed, opened));
  assert.ok(samePrepare(undefined, undefined));
  assert.ok(!samePrepare(undefined, opened));
});

test('edits are remapped in order; a merge whose triangles land on one is dropped and counted', () => {
  const edits = [{ op: 'split', face: 4 }, { op: 'merge', face: 10, with: 11 }, { op: 'lock', face: 7 }, { op: 'merge', face: 1, with: 2 }];
  assert.deepEqual([...editFaces(edits)], [4, 10, 11, 7, 1, 2]);
  const { edits: out, dropped } = remapEdits(edits, [40, 100, 100, 70, 12, 25]);
  assert.equal(dropped, 1);
  assert.deepEqual(out, [{ op: 'split', face: 40 }, { op: 'lock', face: 70 }, { op: 'merge', face: 12, with: 25 }]);
  assert.throws(() => remapEdits(edits, [1, 2]), /one face per named triangle/);
  const params = { ...DEFAULT_PARAMS, panels: 1200, paint: 'aaaaaaaaaaaaaaaa', edits };
  const carried = carriedParams(params, 'bbbbbbbbbbbbbbbb', [40, 100, 101, 70, 12, 25]);
  assert.equal(carried.dropped, 0);
  assert.equal(carried.params.panels, 1200);
  assert.equal(carried.params.paint, 'bbbbbbbbbbbbbbbb');
  assert.deepEqual(carried.params.edits[1], { op: 'merge', face: 100, with: 101 });
});

test('carried density values come back as the page\'s levels: rounded, clamped, never -0', () => {
  assert.deepEqual([...levelsOf([0, 0.4, 0.6, -0.4, 63.7, 80, -200, -16.5])], [0, 0, 1, 0, 64, 64, -64, -16]);
  assert.ok(!Object.is(levelsOf([-0.2])[0], -0));
});

test('a preparation with an edge length travels in links and is checked strictly', () => {
  const state = { mesh: { kind: 'example', id: 'YasIsland', prepare: { panels: 1200, subdivide: 0, edgeLength: 0.75 } }, params: { ...DEFAULT_PARAMS, panels: 1200 }, history: [] };
  const decoded = hashToState(stateToHash(state));
  assert.ok(decoded.ok, decoded.message);
  assert.deepEqual(decoded.value.mesh.prepare, { panels: 1200, subdivide: 0, edgeLength: 0.75 });
  const noEdge = hashToState(stateToHash({ ...state, mesh: { kind: 'example', id: 'YasIsland', prepare: { panels: 150, subdivide: 0 } } }));
  assert.ok(noEdge.ok);
  assert.ok(!('edgeLength' in noEdge.value.mesh.prepare), 'automatic: no edgeLength key at all');
  for (const where of ['in the link', 'in the stored session']) {
    for (const bad of [0, -1, '0.5', null, Number.NaN, Infinity, 1e13, [1]]) {
      const checked = checkPrepare({ panels: 150, subdivide: 0, edgeLength: bad }, where);
      assert.equal(checked.ok, false, `edgeLength ${String(bad)}`);
      assert.match(checked.message, new RegExp(`^${where}: the target edge length must be a positive number`));
    }
    assert.deepEqual(checkPrepare({ panels: 150, subdivide: 2, edgeLength: 1e-6 }, where).value, { panels: 150, subdivide: 2, edgeLength: 1e-6 });
    assert.match(checkPrepare({ panels: 150, subdivide: 0, edge: 1 }, where).message, /unknown field "edge"/);
  }
});

// Designs saved before the rule went from 20 to 30 triangles per panel carry no refineBelow:
// they are prepared with 20 again (worker.ts), so their edits and paint keep naming the
// triangles and vertices of their mesh; new preparations record 30.
test('the refinement rule a preparation was made with travels in links and is checked strictly', () => {
  const where = 'in the link';
  const made = prepareOf(160, { subdivide: 0 });
  assert.deepEqual(made, { panels: 160, subdivide: 0, refineBelow: REFINE_TRIANGLES_PER_PANEL, refineRounds: REFINE_ROUNDS });
  const state = { mesh: { kind: 'example', id: 'inspired_mesh', prepare: made }, params: { ...DEFAULT_PARAMS, panels: 160 }, history: [] };
  const decoded = hashToState(stateToHash(state));
  assert.ok(decoded.ok, decoded.message);
  assert.deepEqual(decoded.value.mesh.prepare, made);
  const older = hashToState(stateToHash({ ...state, mesh: { kind: 'example', id: 'inspired_mesh', prepare: { panels: 160, subdivide: 0 } } }));
  assert.ok(older.ok, older.message);
  assert.ok(!('refineBelow' in older.value.mesh.prepare), 'a design saved before keeps no rule, so the worker uses 20');
  assert.equal(LEGACY_REFINE_BELOW, 20);
  assert.ok(!samePrepare(older.value.mesh.prepare, made), 'the two rules are different preparations');
  for (const bad of [19, 51, 25.5, '30', null]) {
    const checked = checkPrepare({ panels: 150, subdivide: 0, refineBelow: bad }, where);
    assert.equal(checked.ok, false, `refineBelow ${String(bad)}`);
    assert.equal(checked.message, "in the link: the mesh's preparation must refine below 20 to 50 triangles per panel");
  }
  assert.deepEqual(checkPrepare({ panels: 150, subdivide: 1, edgeLength: 2, refineBelow: 20 }, where).value, { panels: 150, subdivide: 1, edgeLength: 2, refineBelow: 20 });
});

// Designs saved before a refinement went from 10 remeshing rounds to 5 carry no refineRounds:
// the worker prepares them with 10 again (worker.ts), so their mesh is the one their edits and
// paint name, at the count they were saved with; a raised count gets the rounds now.
test('the remeshing rounds a preparation was made with travel in links and are checked strictly', () => {
  const where = 'in the link';
  assert.equal(LEGACY_REFINE_ROUNDS, 10);
  assert.equal(REFINE_ROUNDS, 5);
  const made = prepareOf(300, { subdivide: 0 });
  assert.equal(made.refineRounds, REFINE_ROUNDS);
  const state = { mesh: { kind: 'example', id: 'inspired_mesh', prepare: made }, params: { ...DEFAULT_PARAMS, panels: 300 }, history: [] };
  assert.deepEqual(hashToState(stateToHash(state)).value.mesh.prepare, made);
  // Saved with the 30 and 10 rounds (no refineRounds): kept at its count and below.
  const older = { panels: 300, subdivide: 0, refineBelow: 30 };
  assert.ok(!samePrepare(older, made), 'the two rounds are different preparations');
  assert.equal(preparationNeeded(older, 15_000, 300, { subdivide: 0 }), null, 'its own count: its mesh stays');
  assert.equal(preparationNeeded(older, 15_000, 200, { subdivide: 0 }), null);
  assert.deepEqual(preparationNeeded(older, 15_000, 1000, { subdivide: 0 }), { panels: 1000, subdivide: 0, refineBelow: 30, refineRounds: 5 });
  const decodedOlder = hashToState(stateToHash({ ...state, mesh: { kind: 'example', id: 'inspired_mesh', prepare: older } }));
  assert.ok(decodedOlder.ok, decodedOlder.message);
  assert.ok(!('refineRounds' in decodedOlder.value.mesh.prepare), 'no rounds recorded: the worker uses 10');
  for (const bad of [0, 11, 4.5, '5', null]) {
    const checked = checkPrepare({ panels: 150, subdivide: 0, refineRounds: bad }, where);
    assert.equal(checked.ok, false, `refineRounds ${String(bad)}`);
    assert.equal(checked.message, "in the link: the mesh's preparation must refine in 1 to 10 remeshing rounds");
  }
  const ordered = checkPrepare({ refineRounds: 10, edgeLength: 2, panels: 150, subdivide: 1, refineBelow: 20 }, where).value;
  assert.equal(JSON.stringify(ordered), '{"panels":150,"subdivide":1,"edgeLength":2,"refineBelow":20,"refineRounds":10}', 'keys in one order');
});
