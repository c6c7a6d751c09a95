// The sharpest panel corner (web/src/sharpestCorner.ts): the report's point read defensively,
// and the legend line's words, which give the Quality section's "Min angle".
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { sharpestCornerNote, sharpestCornerPoint } from '../../build/web-tests/sharpestCorner.js';

test('the corner is read only when it is three finite numbers', () => {
  assert.deepEqual(sharpestCornerPoint({ min_corner_angle_point: [4, 0.5, -2e3] }), [4, 0.5, -2000]);
  for (const bad of [undefined, null, [1, 2], [1, 2, 3, 4], [1, '2', 3], [1, NaN, 3], [0, -Infinity, 0], { x: 1 }])
    assert.equal(sharpestCornerPoint({ min_corner_angle_point: bad }), null, JSON.stringify(bad));
  // The farthest point's key is not this one's.
  assert.equal(sharpestCornerPoint({ hausdorff_worst_point: [1, 2, 3] }), null);
});

test('the legend gives the angle as the Quality section does, and is absent without a corner', () => {
  const point = [0, 0, 0];
  assert.equal(sharpestCornerNote({ min_corner_angle_deg: 2.2134, min_corner_angle_point: point }), 'Sharpest corner: 2.2°');
  assert.equal(sharpestCornerNote({ min_corner_angle_deg: 0, min_corner_angle_point: point }), 'Sharpest corner: 0.0°', 'a degenerate corner is shown');
  assert.equal(sharpestCornerNote({ min_corner_angle_deg: 360, min_corner_angle_point: point }), null, 'no panels');
  assert.equal(sharpestCornerNote({ min_corner_angle_deg: 12 }), null, 'no point to mark');
  assert.equal(sharpestCornerNote({ min_corner_angle_deg: 'x', min_corner_angle_point: point }), null);
  assert.equal(sharpestCornerNote({}), null);
});
