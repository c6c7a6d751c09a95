// Unit tests of the page's design state machine (web/src/designMachine.ts, compiled to
// build/web-tests by `npm run test:web`): what may run while a mesh opens, which worker answer
// belongs to which request, warm starts, what a crash leaves, and the panels the worker keeps
// for fabrication (kept, restored after a crash).
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { DesignMachine } from '../../build/web-tests/designMachine.js';
import { DEFAULT_PARAMS } from '../../build/web-tests/params.js';

const params = (changes = {}) => ({ ...DEFAULT_PARAMS, ...changes });

// A machine with mesh "a" loaded (job 1) and, if `solved`, one finished solve (job 2).
function loadedMachine({ solved = false } = {}) {
  const machine = new DesignMachine(8);
  const token = machine.beginOpen({ name: 'a' });
  assert.equal(machine.openSent(token, 1), true);
  assert.deepEqual(machine.loaded(1, (info) => info.name), { info: { name: 'a' }, mesh: 'a', newest: true });
  if (solved) {
    const plan = machine.planRemesh(params());
    machine.startSolve(2, params(), plan.chain, plan.lost);
    assert.ok(machine.finishSolve(2, 'result a'));
  }
  return machine;
}

test('nothing can be remeshed or shared before a mesh is loaded', () => {
  const machine = new DesignMachine(8);
  assert.equal(machine.canRemesh, false);
  assert.equal(machine.canShare, false);
  assert.deepEqual(machine.planRemesh(params()), { kind: 'refused', reason: 'no-mesh' });
});

test('while a new mesh opens, Remesh and Share are refused, and the old mesh stays until it loads', () => {
  const machine = loadedMachine({ solved: true });
  const token = machine.beginOpen({ name: 'b' });
  assert.equal(machine.canRemesh, false, 'refused while the payload is prepared');
  assert.equal(machine.canShare, false);
  assert.deepEqual(machine.planRemesh(params({ panels: 50 })), { kind: 'refused', reason: 'opening' });
  machine.openSent(token, 3);
  assert.equal(machine.canRemesh, false, 'refused while the worker loads it');
  assert.equal(machine.mesh, 'a', 'the old mesh is still the design');
  assert.equal(machine.canExport, true, 'the old result can still be exported');
  assert.equal(machine.loaded(99, () => 'x'), null, 'an answer to another job changes nothing');
  assert.deepEqual(machine.loaded(3, (info) => info.name).mesh, 'b');
  assert.equal(machine.mesh, 'b');
  assert.equal(machine.solved, null, 'the old result belongs to the old mesh');
  assert.equal(machine.canRemesh, true);
  assert.equal(machine.sessionPristine, true);
});

test('a later open wins over an earlier one; an open that fails on the page leaves the mesh', () => {
  const machine = loadedMachine();
  const first = machine.beginOpen({ name: 'b' });
  const second = machine.beginOpen({ name: 'c' });
  assert.equal(machine.isCurrentOpen(first), false);
  assert.equal(machine.openSent(first, 5), false, 'the earlier open is not sent');
  assert.equal(machine.abandonOpen(second), true);
  assert.equal(machine.opening, null);
  assert.equal(machine.mesh, 'a');
  assert.equal(machine.canRemesh, true);
});

test('a load a later open overtook still becomes the mesh: the page shows what the worker holds', () => {
  const machine = loadedMachine({ solved: true });
  const b = machine.beginOpen({ name: 'b' });
  machine.openSent(b, 3);
  const c = machine.beginOpen({ name: 'c' }); // read on the page while the worker loads b
  assert.deepEqual(machine.loaded(3, (info) => info.name), { info: { name: 'b' }, mesh: 'b', newest: false });
  assert.equal(machine.canRemesh, false, 'c is still opening');
  machine.abandonOpen(c); // c cannot be read
  assert.equal(machine.mesh, 'b', 'b, which the worker holds, not a');
  assert.equal(machine.canRemesh, true);
  // Two loads in the worker: the first loads, the second is refused; the first stays.
  const d = machine.beginOpen({ name: 'd' });
  machine.openSent(d, 4);
  const e = machine.beginOpen({ name: 'e' });
  machine.openSent(e, 5);
  assert.equal(machine.loaded(4, (info) => info.name).newest, false);
  assert.deepEqual(machine.sentOpening(5), { name: 'e' }, 'what the refused load was opening');
  assert.equal(machine.sentOpening(4), null, 'answered already');
  assert.equal(machine.failed(5), 'open');
  assert.equal(machine.sentOpening(5), null);
  assert.equal(machine.opening, null);
  assert.equal(machine.mesh, 'd');
  // An answer for a load the worker skipped past clears it too (answers come in order).
  const f = machine.beginOpen({ name: 'f' });
  machine.openSent(f, 6);
  const g = machine.beginOpen({ name: 'g' });
  machine.openSent(g, 7);
  assert.equal(machine.loaded(7, (info) => info.name).newest, true);
  assert.equal(machine.opening, null);
  assert.equal(machine.loaded(6, () => 'late'), null);
});

test('warm start only from the finished result with the same seed, and the chain that reproduces it', () => {
  const machine = loadedMachine({ solved: true });
  assert.equal(machine.sessionHoldsSolved, true);
  const warm = machine.planRemesh(params({ panels: 90 }));
  assert.deepEqual(warm, { kind: 'solve', run: [params({ panels: 90 })], fresh: false, chain: [params(), params({ panels: 90 })], lost: null });
  const same = machine.planRemesh(params());
  assert.equal(same.fresh, true, 'identical parameters solve afresh');
  const reseeded = machine.planRemesh(params({ seed: 2 }));
  assert.equal(reseeded.fresh, true, 'a new seed starts over');
  assert.deepEqual(reseeded.chain, [params({ seed: 2 })]);
});

test('a chain longer than a link carries is lost, and so is one changed mid-solve', () => {
  const machine = loadedMachine({ solved: true });
  let job = 10;
  for (let panels = 100; panels > 100 - 9; panels--) {
    const plan = machine.planRemesh(params({ panels }));
    machine.startSolve(++job, params({ panels }), plan.chain, plan.lost);
    machine.finishSolve(job, 'r');
  }
  assert.equal(machine.solved.chain, null);
  assert.equal(machine.solved.lost, 'long-chain');
  const plan = machine.planRemesh(params({ panels: 40 }));
  machine.startSolve(++job, params({ panels: 40 }), plan.chain, plan.lost);
  assert.equal(machine.update(params({ panels: 40 })), null, 'no change, no update');
  assert.equal(machine.update(params({ panels: 30 })), job);
  machine.finishSolve(job, 'r');
  assert.equal(machine.solved.params.panels, 30);
  assert.equal(machine.solved.lost, 'changed-mid-solve');
});

test('answers to dropped solves change nothing', () => {
  const machine = loadedMachine({ solved: true });
  machine.startSolve(7, params({ panels: 60 }), [params({ panels: 60 })], null);
  assert.equal(machine.dropSolve(), 7);
  assert.equal(machine.dropSolve(), null);
  assert.equal(machine.finishSolve(7, 'late'), null);
  assert.equal(machine.failed(7), null);
  assert.equal(machine.solved.result, 'result a');
  assert.equal(machine.sessionHoldsSolved, false, 'the session no longer holds the shown result');
});

test('a refused solve or mesh leaves the design; the next solve is a cold one', () => {
  const machine = loadedMachine({ solved: true });
  machine.startSolve(7, params({ panels: 60 }), [params({ panels: 60 })], null);
  assert.equal(machine.failed(7), 'solve');
  assert.equal(machine.solving, null);
  assert.equal(machine.solved.result, 'result a');
  const token = machine.beginOpen({ name: 'bad' });
  machine.openSent(token, 8);
  assert.equal(machine.failed(8), 'open');
  assert.equal(machine.mesh, 'a');
  assert.equal(machine.planRemesh(params({ panels: 70 })).fresh, true);
});

test('a crash drops what was under way, keeps the last result, and loses the mesh only if it was not reloaded', () => {
  const machine = loadedMachine({ solved: true });
  machine.startSolve(7, params({ panels: 60 }), [params({ panels: 60 })], null);
  assert.deepEqual(machine.crashed(true), { lostOpening: null, lostSolve: true, lostRestore: false });
  assert.equal(machine.solving, null);
  assert.equal(machine.solved.result, 'result a');
  assert.equal(machine.sessionHoldsSolved, false);
  assert.equal(machine.canRemesh, true);
  assert.equal(machine.planRemesh(params({ panels: 60 })).fresh, true, 'the solve after a crash is a cold one');
  const token = machine.beginOpen({ name: 'b' });
  machine.openSent(token, 9);
  assert.deepEqual(machine.crashed(false), { lostOpening: { name: 'b' }, lostSolve: false, lostRestore: false });
  assert.equal(machine.opening, null);
  assert.equal(machine.mesh, null);
  assert.equal(machine.canRemesh, false);
  assert.equal(machine.canExport, false);
});

test('a solver that could not start: nothing more is asked of it, the design on show stays exportable', () => {
  const machine = loadedMachine({ solved: true });
  machine.startSolve(7, params({ panels: 60 }), [params({ panels: 60 })], null);
  const token = machine.beginOpen({ name: 'b' });
  assert.deepEqual(machine.solverDied(), { name: 'b' }, 'the open lost');
  assert.equal(machine.solverDead, true);
  assert.equal(machine.solving, null);
  assert.equal(machine.opening, null, 'the open being read is dropped');
  assert.equal(machine.isCurrentOpen(token), false);
  assert.equal(machine.mesh, 'a');
  assert.equal(machine.solved.result, 'result a');
  assert.equal(machine.canRemesh, false);
  assert.equal(machine.canExport, true);
  assert.equal(machine.canShare, true);
});

test('an open still being prepared on the page survives a crash', () => {
  const machine = loadedMachine();
  const token = machine.beginOpen({ name: 'b' });
  machine.crashed(true);
  assert.equal(machine.isCurrentOpen(token), true);
  assert.equal(machine.openSent(token, 4), true);
});

test('a result solved again by a new worker warm-starts again, unless the design moved on', () => {
  const machine = loadedMachine({ solved: true });
  const solved = machine.solved;
  assert.equal(solved.job, 2);
  machine.crashed(true);
  assert.equal(machine.planRemesh(params({ panels: 50 })).fresh, true, 'the new worker holds no result');
  assert.equal(machine.heldAgain(solved), true);
  assert.equal(machine.sessionHoldsSolved, true);
  assert.equal(machine.planRemesh(params({ panels: 50 })).fresh, false, 'a warm start from the result on show');
  // Moved on: another solve under way, another result, or another mesh sent to the worker
  // (one still read on the page is not there yet).
  machine.crashed(true);
  machine.startSolve(3, params({ panels: 50 }), [params({ panels: 50 })], null);
  assert.equal(machine.heldAgain(solved), false);
  assert.ok(machine.finishSolve(3, 'result b'));
  assert.equal(machine.heldAgain(solved), false);
  const again = machine.solved;
  machine.crashed(true);
  const token = machine.beginOpen({ name: 'b' });
  assert.equal(machine.loadingInWorker, false);
  assert.equal(machine.heldAgain(again), true);
  machine.crashed(true);
  assert.equal(machine.openSent(token, 4), true);
  assert.equal(machine.loadingInWorker, true);
  assert.equal(machine.heldAgain(again), false);
});

test('the panels the worker keeps: kept once shown, lost with the worker, restored quietly once', () => {
  const machine = loadedMachine({ solved: true });
  const solved = machine.solved;
  assert.equal(machine.workerPanels(), 'lost', 'not kept until the page says it shows them');
  machine.keep(2);
  assert.equal(machine.workerPanels(), 'kept');
  assert.equal(machine.restoreTarget(), null, 'kept: nothing to restore');
  machine.workerReplaced();
  assert.equal(machine.workerPanels(), 'lost');
  assert.equal(machine.restoreTarget(), solved);
  machine.startRestore(5, solved);
  assert.equal(machine.workerPanels(), 'pending', 'a fabrication request waits for the restore');
  assert.equal(machine.restoreOf(5), solved);
  assert.equal(machine.restoreOf(4), null);
  assert.equal(machine.restoreTarget(), null, 'one at a time');
  assert.equal(machine.restored(5, true), solved, 'the very panels: kept as the result on show');
  assert.equal(machine.keptJob, 2);
  assert.equal(machine.workerPanels(), 'kept');
  assert.equal(machine.planRemesh(params({ panels: 50 })).fresh, false, 'and warm-started from');
  // A crash during a restore: said (lostRestore), so the page does not restore again.
  machine.workerReplaced();
  machine.startRestore(6, solved);
  assert.deepEqual(machine.crashed(true), { lostOpening: null, lostSolve: false, lostRestore: true });
  assert.equal(machine.restoring, false);
  // Other panels (never seen: the OBJ differs): not kept, not tried again.
  machine.startRestore(7, solved);
  assert.equal(machine.restored(7, false), null);
  assert.equal(machine.restoreTarget(), null);
  assert.equal(machine.workerPanels(), 'lost');
});

test('a restore is dropped by a solve, refused without a mark, and not kept when the design moved on', () => {
  const machine = loadedMachine({ solved: true });
  const solved = machine.solved;
  machine.startRestore(5, solved);
  machine.dropRestore();
  assert.equal(machine.restoring, false);
  assert.equal(machine.restored(5, true), null, 'an answer to a dropped restore changes nothing');
  machine.startRestore(6, solved);
  assert.equal(machine.restoreFailed(6), true);
  assert.equal(machine.restoreTarget(), solved, 'refused: may be tried again');
  machine.startRestore(7, solved);
  machine.startSolve(8, params({ panels: 60 }), [params({ panels: 60 })], null);
  assert.equal(machine.restoreTarget(), null, 'not while a solve goes on');
  assert.equal(machine.restored(7, true), null, 'the design moved on: not kept');
  assert.equal(machine.keptJob, null);
  assert.equal(machine.workerPanels(), 'pending', 'the solve under way settles it');
  machine.solverDied();
  assert.equal(machine.workerPanels(), 'dead');
});
