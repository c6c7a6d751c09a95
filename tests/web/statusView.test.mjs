// Unit tests of the status line's texts (web/src/statusView.ts, compiled to build/web-tests by
// `npm run test:web`).
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { retryNote, solvedSummary } from '../../build/web-tests/statusView.js';

// A retry from a new seeding (RemeshParams.retries) starts the stages over: the progress line
// says why, so the bar going back does not look like a fault. The first solve says nothing.
test('a retry is named in the progress line, the first solve is not', () => {
  assert.equal(retryNote({ attempt: 1, attempts: 3 }), '');
  assert.equal(retryNote({ attempt: 2, attempts: 3 }), ' · panels stayed invalid: new seeding, try 2 of 3');
  assert.equal(retryNote({ attempt: 3, attempts: 3 }), ' · panels stayed invalid: new seeding, try 3 of 3');
});

test('the summary ends with "Done: N panels", the problems in front', () => {
  const result = (invalid, unbuilt) => ({
    report: { panels: 40 },
    panelOffsets: [],
    problems: { invalidPanels: Array(invalid).fill(0), unbuiltClusters: Array(unbuilt).fill(0) },
  });
  assert.deepEqual(solvedSummary(result(0, 0)), { text: 'Done: 40 panels', warning: false });
  assert.deepEqual(solvedSummary(result(1, 2)), {
    text: '1 invalid panel (shown red); 2 clusters could not become panels. Done: 40 panels',
    warning: true,
  });
});
