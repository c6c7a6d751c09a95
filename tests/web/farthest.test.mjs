// Where the panels are farthest from the design (web/src/farthest.ts): the report's worst
// Hausdorff point read defensively, and the legend line's words.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { farthestNote, farthestPoint } from '../../build/web-tests/farthest.js';

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
