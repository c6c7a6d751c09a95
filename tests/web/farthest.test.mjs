// How far the panels are from the design (web/src/farthest.ts): the report's worst Hausdorff
// point read defensively, the legend line's words, the deviation view's scale.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { deviationScaleTop, farthestNote, farthestPoint } from '../../build/web-tests/farthest.js';

test('the worst point is read only when it is three finite numbers', () => {
  assert.deepEqual(farthestPoint({ hausdorff_worst_point: [1, -2.5, 3e3] }), [1, -2.5, 3000]);
  for (const bad of [undefined, null, [1, 2], [1, 2, 3, 4], [1, '2', 3], [1, NaN, 3], [Infinity, 0, 0], { x: 1 }])
    assert.equal(farthestPoint({ hausdorff_worst_point: bad }), null, JSON.stringify(bad));
});

test('the legend gives the distance as a share of the diagonal, and is absent without one', () => {
  const point = [0, 0, 0];
  assert.equal(farthestNote({ hausdorff: 0.0056, hausdorff_worst_point: point }), 'Farthest from the design: 0.56 % of the diagonal');
  assert.equal(farthestNote({ hausdorff: 0, hausdorff_worst_point: point }), null, 'panels on the design everywhere');
  assert.equal(farthestNote({ hausdorff: 0.01 }), null, 'no point to mark');
  assert.equal(farthestNote({ hausdorff: 'x', hausdorff_worst_point: point }), null);
  assert.equal(farthestNote({}), null);
});

test("the deviation view's scale tops at the largest panel deviation", () => {
  assert.equal(deviationScaleTop(new Float64Array([0.001, 0.0076, 0.003])), '0.76 % of the diagonal');
  assert.equal(deviationScaleTop(new Float64Array([])), '0.00 % of the diagonal');
  assert.equal(deviationScaleTop(new Float64Array([NaN, 0.002])), '0.20 % of the diagonal');
});
