// The Quality section's coverage row (web/src/coverage.ts): the report's smallest panel
// coverage in words, a warning that names the panel when some have collapsed.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { coverageRow } from '../../build/web-tests/coverage.js';

test('a healthy design: the share and the panel, no warning', () => {
  const row = coverageRow({ min_panel_coverage: 0.4936, min_panel_coverage_panel: 97, collapsed_panels: 0 });
  assert.equal(row.label, 'Coverage');
  assert.equal(row.value, '49 % (P98)');
  assert.equal(row.warn, false);
  assert.doesNotMatch(row.hint, /merge/);
});

test('a collapsed panel warns and says what to do with it', () => {
  const row = coverageRow({ min_panel_coverage: 2.66e-5, min_panel_coverage_panel: 25, collapsed_panels: 3 });
  assert.equal(row.value, '0 % (P26)');
  assert.equal(row.warn, true);
  assert.match(row.hint, /: 3 here\. Select P26 and merge it with a neighbour/);
});

test('no row without a usable coverage', () => {
  for (const bad of [{}, { min_panel_coverage: 0.5 }, { min_panel_coverage: 0.5, min_panel_coverage_panel: -1 },
    { min_panel_coverage: NaN, min_panel_coverage_panel: 3 }, { min_panel_coverage: '0.5', min_panel_coverage_panel: 3 },
    { min_panel_coverage: 0.5, min_panel_coverage_panel: 1.5 }])
    assert.equal(coverageRow(bad), null, JSON.stringify(bad));
});
