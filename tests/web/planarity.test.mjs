// The Planarity row and status warning (web/src/planarity.ts): flat to 10⁻⁹, and when the coordinates cannot hold that
// (a model far from the origin), a warning that says so. Checked on a real solve (wasm).
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { planarityRow, planarityWarning, PLANARITY_TARGET } from '../../build/web-tests/planarity.js';
import { movedOff } from '../fixtures/meshes.mjs';
import { json, loadModule, meshes, solve } from '../wasm/module.mjs';

const ff = await loadModule();

test('flat panels: no warning', () => {
  const row = planarityRow({ max_planarity: 4e-16, planarity_floor: 2e-15 });
  assert.equal(row.warn, false);
  assert.equal(row.value, '4.0×10⁻¹⁶');
  assert.doesNotMatch(row.hint, /origin|above/);
});

test('above the target: a warning, and the origin named only when the coordinates explain it', () => {
  const far = planarityRow({ max_planarity: 1.5e-6, planarity_floor: 9e-6 });
  assert.equal(far.warn, true);
  assert.match(far.hint, /far from the origin .* 9\.0×10⁻⁶ of a panel: moved near the origin/);
  const unexplained = planarityRow({ max_planarity: 1.5e-6, planarity_floor: 1e-15, max_planarity_panel: 4 });
  assert.equal(unexplained.warn, true);
  assert.match(unexplained.hint, /above the target: the least flat is panel 4$/);
  assert.doesNotMatch(unexplained.hint, /origin/);
  // Where planes have no common point the panel is invalid (a spike), and the row says which.
  const spike = planarityRow({ max_planarity: 9e-8, planarity_floor: 1e-15, max_planarity_panel: 36, invalid: [{ panel: 36, problems: ['spike'] }] });
  assert.match(spike.hint, /the least flat is panel 36, an invalid one \(a vertex where its planes do not meet\)$/);
  // Off its plane with every other check passed: the solver's error, said so.
  const error = planarityRow({ max_planarity: 9e-8, planarity_floor: 1e-15, max_planarity_panel: 36, invalid: [{ panel: 36, problems: ['off_plane'] }] });
  assert.match(error.hint, /the least flat is panel 36, an invalid one, off its plane though it passes every other check \(an error of the solver: please report it\)$/);
  assert.equal(planarityRow({}).value, '–');
  // A far-off part: the panels were solved about the middle of the whole mesh.
  const part = { max_planarity: 1.19e-9, planarity_floor: 1.8e-16, planarity_floor_solve: 2.5e-9 };
  assert.match(planarityRow(part).hint, /a part of the mesh lies so far from the rest .* without the far-off part, the model gives flat panels$/);
  assert.equal(planarityWarning(part), 'panels flat to 1.2×10⁻⁹ of their size, not 10⁻⁹: a part of the mesh lies far from the rest (remove it)');
  // The status line names only what the designer can act on: the model's place, not a spike.
  assert.match(planarityWarning({ max_planarity: 1.5e-6, planarity_floor: 9e-6 }), /far from the origin/);
  assert.equal(planarityWarning({ max_planarity: 9e-8, planarity_floor: 1e-15, max_planarity_panel: 36, invalid: [{ panel: 36 }] }), '');
  assert.equal(planarityRow({}).warn, false);
});

// epcot.off as it is and moved 1e9 along x (a stray georeference): the same solve, and only the
// far one is above the target, by what its coordinates' rounding allows.
function solvedEpcot(offset) {
  const bytes = movedOff(readFileSync(path.join(meshes, 'epcot.off'), 'utf8'), offset);
  const s = new ff.Session();
  try {
    assert.equal(json(s.loadMesh('epcot.off', bytes)).ok, true);
    assert.equal(json(s.setParams(JSON.stringify({ panels: 30, seed: 1 }))).ok, true);
    solve(s);
    return json(s.reportJson());
  } finally {
    s.delete();
  }
}

test('a model 1e9 from the origin: above the target by its rounding, and the row says so', () => {
  const near = solvedEpcot(0);
  assert.ok(near.max_planarity <= PLANARITY_TARGET, `near: ${near.max_planarity}`);
  assert.ok(near.planarity_floor < 1e-13, `near floor: ${near.planarity_floor}`);
  assert.equal(planarityRow(near).warn, false);
  const far = solvedEpcot(1e9);
  assert.ok(far.max_planarity > PLANARITY_TARGET, `far: ${far.max_planarity}`);
  assert.ok(far.planarity_floor * 100 >= far.max_planarity, `far floor ${far.planarity_floor}`);
  const row = planarityRow(far);
  assert.equal(row.warn, true);
  assert.match(row.hint, /moved near the origin/);
  assert.match(planarityWarning(far), /^panels flat to \d\.\d×10⁻[⁰¹²³⁴⁵⁶⁷⁸⁹]+ of their size, not 10⁻⁹: the model is far from the origin \(move it nearer\)$/);
  assert.equal(planarityWarning(near), '');
});
