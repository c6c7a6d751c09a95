// A collapsed panel (web/src/collapsedPanel.ts): which panel the view marks, the legend line's
// words, the marker's place (the panel's centre) and the triangle that selects it.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { collapsedNote, collapsedPanel, faceOfPanel, panelCentre } from '../../build/web-tests/collapsedPanel.js';

test('only a collapsed panel is marked, the worst when there are several', () => {
  assert.equal(collapsedPanel({ collapsed_panels: 1, min_panel_coverage: 0.03, min_panel_coverage_panel: 31 }), 31);
  assert.equal(collapsedPanel({ collapsed_panels: 0, min_panel_coverage: 0.4, min_panel_coverage_panel: 7 }), null, 'the smallest coverage is not a collapse');
  assert.equal(collapsedPanel({ min_panel_coverage: 0.03, min_panel_coverage_panel: 31 }), null, 'a report from before coverage');
  for (const bad of [-1, 2.5, '3', null, undefined])
    assert.equal(collapsedPanel({ collapsed_panels: 1, min_panel_coverage: 0.03, min_panel_coverage_panel: bad }), null, String(bad));
});

test('the legend names the panel as the parts list does and gives its coverage as the Quality section does', () => {
  assert.equal(collapsedNote({ collapsed_panels: 1, min_panel_coverage: 0.0312, min_panel_coverage_panel: 31 }), 'Collapsed panel P32: covers 3 % of its triangles');
  assert.equal(
    collapsedNote({ collapsed_panels: 3, min_panel_coverage: 0.004, min_panel_coverage_panel: 0 }),
    'Collapsed panel P1: covers 0 % of its triangles (3 collapsed, the worst marked)',
  );
  assert.equal(collapsedNote({ collapsed_panels: 0, min_panel_coverage: 0.5, min_panel_coverage_panel: 2 }), null);
  assert.equal(collapsedNote({ collapsed_panels: 1, min_panel_coverage: NaN, min_panel_coverage_panel: 2 }), null);
});

// Two panels: a unit square (corners 0-3) and a triangle (corners 1, 4, 2).
const panels = {
  panelPositions: new Float64Array([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 3, 0.5, 0]),
  panelOffsets: new Uint32Array([0, 4, 7]),
  panelIndices: new Uint32Array([0, 1, 2, 3, 1, 4, 2]),
};

test("the marker sits at the mean of the panel's corners", () => {
  assert.deepEqual(panelCentre(panels, 0), [0.5, 0.5, 0]);
  assert.deepEqual(panelCentre(panels, 1), [5 / 3, 0.5, 0]);
  assert.equal(panelCentre(panels, 2), null, 'no such panel');
  assert.equal(panelCentre(panels, -1), null);
  assert.equal(panelCentre({ ...panels, panelOffsets: new Uint32Array([0, 0, 7]) }, 0), null, 'a panel without corners');
});

test('the panel is selected by a triangle inside it, none when no triangle is', () => {
  const facePanels = new Int32Array([-1, 0, 1, 1, 0]);
  assert.equal(faceOfPanel(facePanels, 1), 2);
  assert.equal(faceOfPanel(facePanels, 0), 1);
  assert.equal(faceOfPanel(facePanels, 5), null);
});
