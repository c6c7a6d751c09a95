// Unit tests of the status line's texts (web/src/statusView.ts, compiled to build/web-tests by
// `npm run test:web`).
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { invalidNote, needleNote, retryNote, solvedSummary, stageName } from '../../build/web-tests/statusView.js';

// A retry from a new seeding (RemeshParams.retries) starts the stages over: the progress line
// says why, so the bar going back does not look like a fault. The first solve says nothing.
test('a retry is named in the progress line, the first solve is not', () => {
  assert.equal(retryNote({ attempt: 1, attempts: 3 }), '');
  assert.equal(retryNote({ attempt: 2, attempts: 3 }), ' · panels stayed invalid: new seeding, try 2 of 3');
  assert.equal(retryNote({ attempt: 3, attempts: 3 }), ' · panels stayed invalid: new seeding, try 3 of 3');
});

// The needle rounds (a valid result with a corner below 1 degree) take the stage back from
// Optimize to Panels: the progress line says why.
test('the needle rounds are named in the progress line, other rounds are not', () => {
  assert.equal(needleNote({ needleRounds: false }), '');
  assert.equal(needleNote({ needleRounds: true }), ' · valid, but a corner is below 1°: more rounds to widen it');
});

// Outside the needle rounds the count says "invalid"; in them a valid result is kept and a
// needle corner counts as a problem, so the count is what is left to mend (never "invalid"
// beside "valid").
test('the invalid count is worded as panels to mend in the needle rounds', () => {
  assert.equal(invalidNote({ invalidPanels: 0, needleRounds: false }), '');
  assert.equal(invalidNote({ invalidPanels: 0, needleRounds: true }), '');
  assert.equal(invalidNote({ invalidPanels: 3, needleRounds: false }), ' · 3 invalid');
  assert.equal(invalidNote({ invalidPanels: 1, needleRounds: true }), ' · 1 panel to mend (a corner below 1° counts)');
  assert.equal(invalidNote({ invalidPanels: 2, needleRounds: true }), ' · 2 panels to mend (a corner below 1° counts)');
  assert.ok(!(needleNote({ needleRounds: true }) + invalidNote({ invalidPanels: 2, needleRounds: true })).includes('invalid'));
});

test('the summary ends with "Done: N panels", the problems in front', () => {
  const result = (invalid, unbuilt) => ({
    report: { panels: 40 },
    panelOffsets: [],
    problems: { invalidPanels: Array(invalid).fill(0), unbuiltClusters: Array(unbuilt).fill(0) },
  });
  assert.deepEqual(solvedSummary(result(0, 0)), { text: 'Done: 40 panels', warning: false });
  // Without the report's "invalid" list (a solve without panels), the problem list's counts.
  assert.deepEqual(solvedSummary(result(1, 2)), {
    text: '1 invalid panel (shown red); 2 clusters could not become panels; another seed or panel count (more or fewer) may make every panel valid. Done: 40 panels',
    warning: true,
  });
  // With it, what is wrong with them (invalidPanels.ts).
  const listed = { ...result(0, 0), report: { panels: 40, invalid: [{ panel: 5, cluster: 5, problems: ['not_star'] }] } };
  assert.deepEqual(solvedSummary(listed), {
    text: '1 invalid panel (shown red: not star-shaped 1); another seed or panel count (more or fewer) may make every panel valid. Done: 40 panels',
    warning: true,
  });
  assert.deepEqual(solvedSummary({ ...result(0, 0), report: { panels: 40, invalid: [] } }), { text: 'Done: 40 panels', warning: false });
});

// "Done: 197 panels" after a solve for 120 in glass mode read as a fault (a review of the page).
test('glass mode says that it cut panels into pieces', () => {
  const clusterIds = Int32Array.from([0, 0, 1, 2, 2, -1]);
  const glass = { report: { panels: 5, glass: true }, clusterIds, panelOffsets: [], problems: { invalidPanels: [], unbuiltClusters: [] } };
  assert.deepEqual(solvedSummary(glass), { text: 'Glass mode cut the concave ones of 3 panels into convex pieces. Done: 5 panels', warning: false });
  // Nothing cut (every panel convex), or no glass mode: nothing said.
  assert.equal(solvedSummary({ ...glass, report: { panels: 3, glass: true } }).text, 'Done: 3 panels');
  assert.equal(solvedSummary({ ...glass, report: { panels: 5, glass: false } }).text, 'Done: 5 panels');
});

// "Solving: panels 1 of 100 · 1414 invalid" while solving 2,000 panels read as a panel count
// (a review of the page): the stage counts rounds, and says so.
test('the progress line names what its stage counts', () => {
  assert.equal(stageName('Panels'), 'panel round');
  assert.equal(stageName('Lloyd'), 'Lloyd iteration');
  assert.equal(stageName('Seeding'), 'seeding');
  assert.equal(stageName('Optimize'), 'optimize');
});
