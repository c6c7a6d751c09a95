// The Quality section's crossing row (web/src/crossings.ts): the report's pairs of panels that
// pass through each other, named as the parts list names them, with a warning.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { crossingNote, crossingPairs, crossingPoints, crossingRow, selfCrossingLegend, selfCrossingNote, selfCrossingPlaces, selfCrossingPoint, selfCrossingPoints } from '../../build/web-tests/crossings.js';

test('pairs are named P1 ... and warned about with the deepest share', () => {
  const report = {
    crossing_panels: [
      { panels: [36, 37], point: [0, 0, 0] },
      { panels: [44, 51], point: [1, 2, 3] },
    ],
    max_crossing_depth: 0.0479,
  };
  assert.deepEqual(crossingPairs(report), [['P37', 'P38'], ['P45', 'P52']]);
  const row = crossingRow(report);
  assert.equal(row.label, 'Crossing');
  assert.equal(row.value, '2');
  assert.equal(row.warn, true);
  assert.match(row.hint, /\(P37 and P38, P45 and P52; the deepest 4\.8 % of the smaller panel's size\): they cannot be built/);
  assert.match(row.hint, /More panels there, or another seed or panel count, may avoid it\.$/);
  assert.match(crossingRow({ ...report, input_crossings: 83 }).hint, /passes through itself there, and panels made from it follow it: mend the model there\.$/);
});

test('none: a quiet zero; more than four: the first four', () => {
  const none = crossingRow({ crossing_panels: [], max_crossing_depth: 0 });
  assert.equal(none.value, '0');
  assert.equal(none.warn, false);
  const many = crossingRow({ crossing_panels: [0, 1, 2, 3, 4].map((k) => ({ panels: [k, k + 10] })) });
  assert.match(many.hint, /\(P1 and P11, P2 and P12, P3 and P13, P4 and P14, \.\.\.\): they/);
});

test('no row from an older report or a malformed list', () => {
  for (const bad of [{}, { crossing_panels: 3 }, { crossing_panels: [{ panels: [1] }] },
    { crossing_panels: [{ panels: [1, -2] }] }, { crossing_panels: [{ panels: [1.5, 2] }] }, { crossing_panels: [null] }])
    assert.equal(crossingRow(bad), null, JSON.stringify(bad));
});

test('the markers: the deepest point of each pair; the legend line counts the pairs', () => {
  const report = { crossing_panels: [{ panels: [1, 2], point: [1, 2, 3] }, { panels: [2, 5], point: [4, 5, 6] }] };
  assert.deepEqual(crossingPoints(report), [1, 2, 3, 4, 5, 6]);
  assert.equal(crossingNote(report), 'Panels passing through each other: 2 pairs (more panels there may avoid it)');
  assert.equal(crossingNote({ crossing_panels: [{ panels: [1, 2], point: [1, 2, 3] }], input_crossings: 83 }),
    'Panels passing through each other: 1 pair (the surface passes through itself there)');
  for (const none of [{}, { crossing_panels: [] }, { crossing_panels: [{ panels: [1, 2], point: [1, NaN, 3] }] }]) {
    assert.equal(crossingNote(none), null, JSON.stringify(none));
  }
  assert.deepEqual(crossingPoints({ crossing_panels: [{ panels: [1, 2], point: [1, 2] }] }), []);
});

test('a surface passing through itself is told on load, with where, and nothing else is', () => {
  const note = selfCrossingNote({ selfCrossings: 83, selfCrossingPoint: [-0.41975, 0.21912, -0.0069512] });
  assert.equal(
    note,
    'The surface passes through itself: 83 pairs of its triangles cross, one near (-0.42, 0.219, -0.00695). Panels made from it can pass through each other there, whatever their count: mend the model there before building.',
  );
  assert.match(selfCrossingNote({ selfCrossings: 1, selfCrossingPoint: [1, 2, 3] }), /^The surface passes through itself: 1 pair of its triangles cross, one near \(1, 2, 3\)\./);
  assert.match(selfCrossingNote({ selfCrossings: 2, selfCrossingPoint: [1, Number.NaN, 3] }), /: 2 pairs of its triangles cross\. Panels/);
  assert.equal(selfCrossingNote({ selfCrossings: 0, selfCrossingPoint: [0, 0, 0] }), '');
  assert.match(selfCrossingNote({ selfCrossings: -1, selfCrossingPoint: [0, 0, 0] }), /^Not checked whether the surface passes through itself: its triangles overlap too much in space/);
  assert.equal(selfCrossingNote({}), '', 'an older worker that does not say');
  // With the places it crosses in (the core counts them): where the pairs lie, not only how many.
  const at = [-0.41975, 0.21912, -0.0069512];
  assert.equal(
    selfCrossingNote({ selfCrossings: 83, selfCrossingPlaces: 4, selfCrossingPoint: at }),
    'The surface passes through itself: 83 pairs of its triangles cross in 4 places, one near (-0.42, 0.219, -0.00695). Panels made from it can pass through each other there, whatever their count: mend the model there before building.',
  );
  assert.match(selfCrossingNote({ selfCrossings: 5, selfCrossingPlaces: 1, selfCrossingPoint: at }), /: 5 pairs of its triangles cross in one place, near \(-0\.42, 0\.219, -0\.00695\)\. Panels/);
  assert.match(selfCrossingNote({ selfCrossings: 5, selfCrossingPlaces: 2, selfCrossingPoint: [1, Number.NaN, 3] }), /: 5 pairs of its triangles cross in 2 places\. Panels/);
  for (const places of [6, 1.5, Number.NaN, -1, '4']) {
    assert.match(selfCrossingNote({ selfCrossings: 5, selfCrossingPlaces: places, selfCrossingPoint: at }), /: 5 pairs of its triangles cross, one near/, `places ${places}: not said`);
  }
});

test('the places the surface crosses itself in, only as a whole count up to its pairs', () => {
  assert.equal(selfCrossingPlaces({ selfCrossings: 83, selfCrossingPlaces: 4 }), 4);
  assert.equal(selfCrossingPlaces({ selfCrossings: 83 }), 0, 'an older worker');
  assert.equal(selfCrossingPlaces({ selfCrossings: 3, selfCrossingPlaces: 4 }), 0, 'more places than pairs');
  assert.equal(selfCrossingPlaces({ selfCrossings: -1, selfCrossingPlaces: 0 }), 0);
  assert.equal(selfCrossingPlaces({ selfCrossings: 83, selfCrossingPlaces: 2.5 }), 0);
});

test('the point marked where the surface passes through itself, only when it does', () => {
  assert.deepEqual(selfCrossingPoint({ selfCrossings: 83, selfCrossingPoint: [-0.42, 0.22, -0.007] }), [-0.42, 0.22, -0.007]);
  assert.equal(selfCrossingPoint({ selfCrossings: 0, selfCrossingPoint: [0, 0, 0] }), null);
  assert.equal(selfCrossingPoint({ selfCrossings: -1, selfCrossingPoint: [0, 0, 0] }), null, 'not checked');
  assert.equal(selfCrossingPoint({ selfCrossings: 2, selfCrossingPoint: [1, Number.NaN, 3] }), null);
  assert.equal(selfCrossingPoint({}), null);
});

test('every crossing pair of the surface is marked, or the first alone from a worker that gives only that', () => {
  const two = { selfCrossings: 2, selfCrossingPoint: [1, 2, 3], selfCrossingPoints: [1, 2, 3, 4, 5, 6] };
  assert.deepEqual(selfCrossingPoints(two), [1, 2, 3, 4, 5, 6]);
  assert.equal(selfCrossingLegend(two), 'The surface passes through itself: 2 pairs of its triangles, each marked');
  assert.equal(selfCrossingLegend({ ...two, selfCrossingPlaces: 2 }), 'The surface passes through itself: 2 pairs of its triangles in 2 places, each marked');
  assert.equal(selfCrossingLegend({ ...two, selfCrossingPlaces: 1 }), 'The surface passes through itself: 2 pairs of its triangles, each marked', 'one place: nothing to add');
  const one = { selfCrossings: 1, selfCrossingPoint: [1, 2, 3], selfCrossingPoints: [1, 2, 3] };
  assert.equal(selfCrossingLegend(one), 'The surface passes through itself: 1 pair of its triangles, marked');
  const older = { selfCrossings: 83, selfCrossingPoint: [1, 2, 3] };
  assert.deepEqual(selfCrossingPoints(older), [1, 2, 3]);
  assert.equal(selfCrossingLegend(older), 'The surface passes through itself: 83 pairs of its triangles, one marked');
  const capped = { selfCrossings: 5000, selfCrossingPoint: [0, 0, 1], selfCrossingPoints: Array.from({ length: 6000 }, (_, i) => i % 3) };
  assert.equal(selfCrossingLegend(capped), 'The surface passes through itself: 5,000 pairs of its triangles, the first 2,000 marked');
  assert.deepEqual(selfCrossingPoints({ ...two, selfCrossingPoints: [1, 2, Number.NaN, 4, 5, 6] }), [1, 2, 3], 'a broken list: the first point');
  assert.deepEqual(selfCrossingPoints({ ...two, selfCrossingPoints: [1, 2, 3, 4] }), [1, 2, 3], 'not whole points: the first point');
  assert.deepEqual(selfCrossingPoints({ selfCrossings: 0, selfCrossingPoint: [0, 0, 0], selfCrossingPoints: [] }), []);
  assert.equal(selfCrossingLegend({ selfCrossings: 0, selfCrossingPoint: [0, 0, 0], selfCrossingPoints: [] }), null);
  assert.deepEqual(selfCrossingPoints({ selfCrossings: -1, selfCrossingPoint: [1, 2, 3], selfCrossingPoints: [1, 2, 3] }), [], 'not checked: no marker');
  assert.equal(selfCrossingLegend({ selfCrossings: -1, selfCrossingPoint: [1, 2, 3], selfCrossingPoints: [1, 2, 3] }), null);
  assert.deepEqual(selfCrossingPoints({ ...two, selfCrossings: 1 }), [1, 2, 3], 'more points than pairs: the first point');
  assert.equal(selfCrossingLegend({ ...two, selfCrossings: Number.NaN }), null);
  assert.equal(selfCrossingLegend({ ...two, selfCrossings: 1.5 }), null);
});
