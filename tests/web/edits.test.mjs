// Unit tests of the page's per-panel edits (web/src/edits/panelEdits.ts and their place in
// params.ts, history.ts, designMachine.ts and share.ts; compiled to build/web-tests by
// `npm run test:web`): the edit list's strict validation (hostile lists refused with a clear
// message), the JSON sent to the core, locked panels and neighbours from a result, chains of
// edit-only steps folded, edits as undoable history steps, and edits in share links.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { DesignMachine } from '../../build/web-tests/designMachine.js';
import { checkEdits, checkEditsFit, clusterCount, compactChain, countAfterEdits, lockedPanels, MAX_EDITS, neighbourPanels, newSeedNotice, sameButEdits, targetOfTyped } from '../../build/web-tests/edits/panelEdits.js';
import { PanelSelection, panelsOfClusters, selectedIn } from '../../build/web-tests/panelSelection.js';
import { History } from '../../build/web-tests/history.js';
import { DEFAULT_PARAMS, sameParams, toRemeshParams, validateParams } from '../../build/web-tests/params.js';
import { hashToState, stateToHash } from '../../build/web-tests/share.js';

const params = (changes = {}) => ({ ...DEFAULT_PARAMS, ...changes });

test('edits: a valid list passes, rebuilt with its keys in one order', () => {
  const list = [{ face: 3, op: 'split' }, { with: 9, op: 'merge', face: 4 }, { op: 'lock', face: 0 }, { op: 'unlock', face: 0 }];
  const checked = checkEdits(list);
  assert.ok(checked.ok, checked.message);
  assert.deepEqual(checked.value, [{ op: 'split', face: 3 }, { op: 'merge', face: 4, with: 9 }, { op: 'lock', face: 0 }, { op: 'unlock', face: 0 }]);
  assert.equal(JSON.stringify(checked.value[1]), '{"op":"merge","face":4,"with":9}');
  assert.deepEqual(checkEdits([]), { ok: true, value: [] });
});

test('edits: hostile lists are refused, each with a message naming the problem', () => {
  const cases = [
    [{ op: 'split', face: 1 }, /must be a list/],
    ['split', /must be a list/],
    [null, /must be a list/],
    [[null], /edit 1 must be an object/],
    [[[1, 2]], /edit 1 must be an object/],
    [[{ op: 'explode', face: 1 }], /split, merge, lock or unlock/],
    [[{ op: 'SPLIT', face: 1 }], /split, merge, lock or unlock/],
    [[{ face: 1 }], /split, merge, lock or unlock/],
    [[{ op: 'split' }], /face must be a triangle number/],
    [[{ op: 'split', face: -1 }], /face must be a triangle number/],
    [[{ op: 'split', face: 1.5 }], /face must be a triangle number/],
    [[{ op: 'split', face: '3' }], /face must be a triangle number/],
    [[{ op: 'split', face: Number.NaN }], /face must be a triangle number/],
    [[{ op: 'split', face: 2 ** 31 }], /face must be a triangle number/],
    [[{ op: 'split', face: 1e300 }], /face must be a triangle number/],
    [[{ op: 'split', face: 1, with: 2 }], /unknown field "with"/],
    [[{ op: 'lock', face: 1, extra: true }], /unknown field "extra"/],
    [[{ op: 'merge', face: 1 }], /with must be a triangle number/],
    [[{ op: 'merge', face: 1, with: 1 }], /merged with itself/],
    [[{ op: 'split', face: 1 }, { op: 'lock', face: -2 }], /edit 2: face/],
    [JSON.parse('[{"op":"split","face":1,"__proto__":{"x":1}}]'), /unknown field "__proto__"/],
    [Array.from({ length: MAX_EDITS + 1 }, () => ({ op: 'split', face: 0 })), /at most 10,000 edits/],
  ];
  for (const [value, message] of cases) {
    const checked = checkEdits(value);
    assert.equal(checked.ok, false, `refused: ${JSON.stringify(value)?.slice(0, 80)}`);
    assert.match(checked.message, message);
  }
  assert.ok(checkEdits(Array.from({ length: MAX_EDITS }, (_, i) => ({ op: 'lock', face: i }))).ok, 'the limit itself passes');
});

test('edits: part of the parameters; absent in older links; sent to the core only when there are some', () => {
  assert.deepEqual(DEFAULT_PARAMS.edits, []);
  const { edits: _drop, ...older } = DEFAULT_PARAMS;
  const old = validateParams(older);
  assert.ok(old.ok, old.message);
  assert.deepEqual(old.value.edits, []);
  assert.equal('edits' in toRemeshParams(old.value), false, "today's core JSON without edits stays the same");
  const withEdits = validateParams({ ...DEFAULT_PARAMS, edits: [{ op: 'split', face: 7 }] });
  assert.ok(withEdits.ok, withEdits.message);
  assert.deepEqual(toRemeshParams(withEdits.value).edits, [{ op: 'split', face: 7 }]);
  const bad = validateParams({ ...DEFAULT_PARAMS, edits: [{ op: 'split', face: -7 }] });
  assert.equal(bad.ok, false);
  assert.match(bad.message, /Panel edit 1: face/);
  assert.equal(validateParams({ ...DEFAULT_PARAMS, edits: 'split' }).ok, false);
});

test('edits: the triangles they name must exist in the mesh opened', () => {
  const edits = [{ op: 'split', face: 10 }, { op: 'merge', face: 3, with: 12 }];
  assert.ok(checkEditsFit(edits, 13).ok);
  const misfit = checkEditsFit(edits, 12);
  assert.equal(misfit.ok, false);
  assert.match(misfit.message, /edit 2 names triangle 12, but the mesh has 12 triangles/);
  assert.ok(checkEditsFit([], 0).ok);
});

test('edits: locked panels follow lock and unlock by the panel of the named triangle', () => {
  const clusterIds = Int32Array.from([0, 0, 1, 1, 2, 2, -1]);
  assert.deepEqual([...lockedPanels([{ op: 'lock', face: 1 }, { op: 'lock', face: 4 }], clusterIds)].sort(), [0, 2]);
  // Unlocked through another triangle of the same panel.
  assert.deepEqual([...lockedPanels([{ op: 'lock', face: 1 }, { op: 'lock', face: 4 }, { op: 'unlock', face: 5 }], clusterIds)], [0]);
  assert.deepEqual([...lockedPanels([{ op: 'lock', face: 6 }, { op: 'lock', face: 99 }, { op: 'split', face: 0 }], clusterIds)], [], 'unassigned or missing triangles lock nothing');
});

test('edits: neighbours are the panels across a mesh edge, not across a corner', () => {
  // A strip of four triangles over vertices 0..5 (edge-adjacent in order) and a triangle
  // touching the strip's first triangle at vertex 0 only.
  const indices = Uint32Array.from([0, 1, 2, 1, 3, 2, 2, 3, 4, 3, 5, 4, 0, 6, 7]);
  const clusterIds = Int32Array.from([0, 1, 1, 2, 3]);
  assert.deepEqual([...neighbourPanels(0, clusterIds, indices)], [1]);
  assert.deepEqual([...neighbourPanels(1, clusterIds, indices)].sort(), [0, 2]);
  assert.deepEqual([...neighbourPanels(3, clusterIds, indices)], []);
});

test('edits: chain steps that only change the edits fold into the next one', () => {
  const p = params({ panels: 60 });
  const e1 = { ...p, edits: [{ op: 'split', face: 1 }] };
  const e12 = { ...p, edits: [{ op: 'split', face: 1 }, { op: 'lock', face: 5 }] };
  const q = { ...e12, panels: 70 };
  const q3 = { ...q, edits: [...q.edits, { op: 'split', face: 9 }] };
  assert.ok(sameButEdits(p, e12));
  assert.ok(!sameButEdits(e12, q));
  assert.deepEqual(compactChain([p, e1, e12]), [p, e12], 'the solve without edits stays');
  assert.deepEqual(compactChain([p, e1, e12, q, q3]), [p, e12, q, q3], 'a parameter change after edits stays, and its edits with it');
  assert.deepEqual(compactChain([p, e1, p]), [p, e1, p], 'a step that drops every edit stays');
  assert.deepEqual(compactChain([p, params({ panels: 70 })]), [p, params({ panels: 70 })]);
  // Twenty edits in a row: the chain stays two solves long.
  let chain = [p];
  for (let i = 0; i < 20; i++) chain = compactChain([...chain, { ...p, edits: [...chain[chain.length - 1].edits, { op: 'split', face: i }] }]);
  assert.equal(chain.length, 2);
  assert.equal(chain[1].edits.length, 20);
});

test('edits: each edit is one history step; undo and redo walk them; a new edit drops the redo branch', () => {
  const history = new History(100);
  const p = params({ panels: 60 });
  history.reset({ kind: 'open', params: p, chain: [p] });
  const split = { ...p, edits: [{ op: 'split', face: 4 }] };
  const locked = { ...p, edits: [...split.edits, { op: 'lock', face: 8 }] };
  history.push({ kind: 'edit', params: split, chain: null });
  history.push({ kind: 'edit', params: locked, chain: null });
  assert.equal(history.size, 3);
  assert.deepEqual(history.undo().params.edits, split.edits);
  assert.deepEqual(history.undo().params.edits, []);
  assert.equal(history.undo(), null);
  assert.deepEqual(history.redo().params.edits, split.edits);
  const merged = { ...p, edits: [...split.edits, { op: 'merge', face: 4, with: 30 }] };
  history.push({ kind: 'edit', params: merged, chain: null });
  assert.equal(history.canRedo, false, 'the lock is gone from the redo branch');
  assert.ok(sameParams(history.current.params, merged));
  assert.ok(!sameParams(split, locked), 'designs differing in edits differ');
  // An edit the core refused is dropped, with whatever was ahead of it.
  history.push({ kind: 'edit', params: { ...merged, edits: [...merged.edits, { op: 'merge', face: 1, with: 2 }] }, chain: null });
  assert.ok(sameParams(history.discardCurrent().params, merged));
  assert.equal(history.canRedo, false);
  assert.ok(sameParams(history.current.params, merged));
  const single = new History(10);
  single.reset('only');
  assert.equal(single.discardCurrent(), null, 'the first state stays');
  assert.equal(single.current, 'only');
});

test('edits: a warm-started edit extends the chain of the result on show, folded', () => {
  const machine = new DesignMachine(8);
  const token = machine.beginOpen({ name: 'a' });
  machine.openSent(token, 1);
  machine.loaded(1, (info) => info.name);
  const p = params({ panels: 60 });
  let job = 1;
  let plan = machine.planRemesh(p);
  machine.startSolve(++job, p, plan.chain, plan.lost);
  machine.finishSolve(job, 'r');
  for (let i = 1; i <= 12; i++) {
    const next = { ...p, edits: Array.from({ length: i }, (_, k) => ({ op: 'split', face: k })) };
    plan = machine.planRemesh(next);
    assert.equal(plan.kind, 'solve');
    assert.equal(plan.fresh, false, 'an edit warm-starts from the design on show');
    assert.deepEqual(plan.run, [next]);
    machine.startSolve(++job, next, plan.chain, plan.lost);
    machine.finishSolve(job, 'r');
  }
  assert.equal(machine.solved.chain.length, 2, 'twelve edits: still reproducible, more than MAX_HISTORY');
  assert.equal(machine.solved.chain[1].edits.length, 12);
});

test('edits: travel in share links inside the parameters and their history', () => {
  const p = params({ panels: 60 });
  const edited = { ...p, edits: [{ op: 'split', face: 11 }, { op: 'merge', face: 2, with: 40 }, { op: 'lock', face: 100 }] };
  const state = { mesh: { kind: 'example', id: 'saddle' }, params: { ...edited, panels: 70 }, history: [p, edited] };
  const decoded = hashToState(stateToHash(state));
  assert.ok(decoded.ok, decoded.message);
  assert.deepEqual(decoded.value, state);
  const hostile = { ...state, params: { ...state.params, edits: [{ op: 'split', face: 1, evil: 1 }] } };
  const refused = hashToState(stateToHash(hostile));
  assert.equal(refused.ok, false);
  assert.match(refused.message, /unknown field "evil"/);
  const hostileHistory = { ...state, history: [{ ...p, edits: [{ op: 'lock', face: -1 }] }] };
  assert.equal(hashToState(stateToHash(hostileHistory)).ok, false);
});

test('panels count: "Panels" shows the count after the edits, and reading it back gives the target', () => {
  const split = { op: 'split', face: 3 };
  const merge = { op: 'merge', face: 4, with: 9 };
  const lock = { op: 'lock', face: 0 };
  assert.equal(countAfterEdits(60, []), 60);
  assert.equal(countAfterEdits(60, [split]), 61);
  assert.equal(countAfterEdits(60, [split, split, lock, merge]), 61);
  assert.equal(countAfterEdits(60, [merge, lock, { op: 'unlock', face: 0 }]), 59);
  // The count shown (61 after a split of 60) is no change: the target goes to the core.
  assert.equal(targetOfTyped(61, 61, 60, true), 60);
  // Any other number is a new count, even the old target typed back.
  assert.equal(targetOfTyped(70, 61, 60, true), 70);
  assert.equal(targetOfTyped(60, 61, 60, true), 60);
  // Without edits the number is the count, as it always was.
  assert.equal(targetOfTyped(61, 61, 60, false), 61);
  assert.equal(clusterCount(Int32Array.from([0, 2, 1, 2, -1])), 3);
  assert.equal(clusterCount(new Int32Array(0)), 0);
  // The stored parameters keep the target with the edits, so a link solves 60 then splits.
  const stored = validateParams(JSON.parse(JSON.stringify(params({ panels: 60, edits: [split] }))));
  assert.ok(stored.ok);
  assert.equal(stored.value.panels, 60);
  assert.equal(countAfterEdits(stored.value.panels, stored.value.edits), 61);
});

test('panel selection: one selected triangle names the panel for the edits and the thickness alike', () => {
  // Triangles 0-1 in cluster 0 (panel 0), 2-3 in cluster 1 cut into glass pieces 1 and 2,
  // 4 in cluster 2 whose polygon was not built (no panel).
  const result = { clusterIds: Int32Array.from([0, 0, 1, 1, 2]), facePanels: Int32Array.from([0, 0, 1, 2, -1]) };
  const selection = new PanelSelection();
  let heard = 0;
  selection.onChange(() => (heard += 1));
  assert.equal(selection.in(result), null);
  selection.select(3);
  selection.select(3); // the same: no change to hear of
  assert.equal(heard, 1);
  assert.deepEqual(selection.in(result), { face: 3, cluster: 1, panel: 2 });
  assert.equal(selection.in(null), null, 'nothing on show: nothing selected there');
  assert.equal(selectedIn(4, result), null, 'a triangle in no panel');
  assert.equal(selectedIn(9, result), null, 'a triangle the result does not have');
  selection.select(null);
  assert.equal(heard, 2);
  assert.equal(selection.face, null);
  assert.deepEqual([...panelsOfClusters(new Set([1]), result)].sort(), [1, 2], 'a locked cluster is all its pieces');
  assert.deepEqual([...panelsOfClusters(new Set([2]), result)], []);
});

// A new seed starts the clusters over; the edits name triangles, so they land on the panels
// now there: said with the solve, not left to be found.
test('a new seed says that the edits apply to the panels now at their triangles', () => {
  assert.equal(newSeedNotice([]), null);
  assert.equal(newSeedNotice([{ op: 'lock', face: 3 }]), 'A new seed starts the panels over: the panel edit applies to the panel now at its triangle, which may not be the one edited.');
  assert.equal(
    newSeedNotice([{ op: 'lock', face: 3 }, { op: 'split', face: 9 }, { op: 'merge', face: 1, with: 40 }]),
    'A new seed starts the panels over: the 3 panel edits apply to the panels now at their triangles, which may not be the ones edited.',
  );
});
