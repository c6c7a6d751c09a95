// A collapsed panel (web/src/collapsedPanel.ts): which panel the view marks, the legend line's
// words, the marker's place (the panel's centre) and the triangle that selects it, in glass
// mode too.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { collapsedNote, collapsedPanel, faceOfCollapsed, panelCentre } from '../../build/web-tests/collapsedPanel.js';

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
  const report = (panel, cluster) => ({ collapsed_panels: 1, min_panel_coverage: 0.03, min_panel_coverage_panel: panel, min_panel_coverage_cluster: cluster });
  const result = (panel, cluster) => ({ report: report(panel, cluster), clusterIds: new Int32Array([-1, 7, 3, 3, 7]), facePanels: new Int32Array([-1, 0, 1, 1, 0]) });
  assert.equal(faceOfCollapsed(result(1, 3)), 2);
  assert.equal(faceOfCollapsed(result(0, 7)), 1);
  assert.equal(faceOfCollapsed(result(5, -1)), null, 'no triangle and no cluster');
  assert.equal(faceOfCollapsed({ ...result(1, 3), report: { ...report(1, 3), collapsed_panels: 0 } }), null, 'nothing collapsed');
});

// Glass mode: the collapsed panel was cut into pieces 1 and 2 (cluster 3), and every triangle
// of it went to piece 2; the report names piece 1. A triangle of the cluster selects it.
test("in glass mode a named piece without triangles is selected by its cluster's", () => {
  const glass = { clusterIds: new Int32Array([7, 3, 3, 7]), facePanels: new Int32Array([0, 2, 2, 0]) };
  const report = { collapsed_panels: 2, min_panel_coverage: 0.04, min_panel_coverage_panel: 1, min_panel_coverage_cluster: 3 };
  assert.equal(faceOfCollapsed({ ...glass, report }), 1);
  for (const bad of [undefined, -1, 2.5, '3'])
    assert.equal(faceOfCollapsed({ ...glass, report: { ...report, min_panel_coverage_cluster: bad } }), null, String(bad));
  assert.equal(faceOfCollapsed({ ...glass, report: { ...report, min_panel_coverage_cluster: 9 } }), null, 'a cluster without triangles');
});
