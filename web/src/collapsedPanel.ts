// A collapsed panel (coverage.ts: below a tenth of its own triangles' area) is often too small
// to see, let alone to click. So it is marked in the view at its centre, with a legend line
// whose button selects it for the panel edits: merging it away is then "Merge with
// neighbour" and a click on any panel beside it.
import { showLegendLine } from './dom.ts';
import type { QualityReport, SolveResult } from './protocol.ts';

// The panel to mark (a panel mesh id: the report's smallest coverage), or null when no panel
// has collapsed.
export function collapsedPanel(report: QualityReport): number | null {
  const collapsed = report.collapsed_panels;
  const panel = report.min_panel_coverage_panel;
  if (typeof collapsed !== 'number' || !(collapsed > 0)) return null;
  return typeof panel === 'number' && Number.isInteger(panel) && panel >= 0 ? panel : null;
}

// The legend line, or null without a collapsed panel. More than one: the worst is marked.
export function collapsedNote(report: QualityReport): string | null {
  const panel = collapsedPanel(report);
  const coverage = report.min_panel_coverage;
  if (panel === null || typeof coverage !== 'number' || !Number.isFinite(coverage)) return null;
  const collapsed = report.collapsed_panels as number;
  const others = collapsed > 1 ? ` (${collapsed} collapsed, the worst marked)` : '';
  return `Collapsed panel P${panel + 1}: covers ${Math.round(coverage * 100)} % of its triangles${others}`;
}

// The mean of a panel's corners (mesh coordinates), or null for no such panel.
export function panelCentre(result: Pick<SolveResult, 'panelPositions' | 'panelOffsets' | 'panelIndices'>, panel: number): [number, number, number] | null {
  if (!(panel >= 0 && panel + 1 < result.panelOffsets.length)) return null;
  const begin = result.panelOffsets[panel]!;
  const end = result.panelOffsets[panel + 1]!;
  if (end <= begin) return null;
  const sum = [0, 0, 0];
  for (let i = begin; i < end; i++)
    for (let k = 0; k < 3; k++) sum[k]! += result.panelPositions[result.panelIndices[i]! * 3 + k]!;
  const centre: [number, number, number] = [sum[0]! / (end - begin), sum[1]! / (end - begin), sum[2]! / (end - begin)];
  return centre.every(Number.isFinite) ? centre : null;
}

// A triangle of the loaded mesh inside the collapsed panel (how the page selects a panel:
// panelSelection.ts), or null without one. In glass mode the report names the panel's first
// piece, and a triangle goes to the piece over its centroid, so that piece may own none: then
// any triangle of its cluster (min_panel_coverage_cluster) selects the panel the edits know.
export function faceOfCollapsed(result: Pick<SolveResult, 'report' | 'clusterIds' | 'facePanels'>): number | null {
  const panel = collapsedPanel(result.report);
  if (panel === null) return null;
  const face = result.facePanels.indexOf(panel);
  if (face >= 0) return face;
  const cluster = result.report.min_panel_coverage_cluster;
  if (typeof cluster !== 'number' || !Number.isInteger(cluster) || cluster < 0) return null;
  const n = Math.min(result.clusterIds.length, result.facePanels.length);
  for (let f = 0; f < n; f++) if (result.clusterIds[f] === cluster && result.facePanels[f]! >= 0) return f;
  return null;
}

// #collapsed-legend and its button for the result on show (hidden without a collapsed panel).
export function renderCollapsedPanel(result: SolveResult | null): void {
  const button = document.getElementById('collapsed-select');
  if (!showLegendLine('collapsed', result ? collapsedNote(result.report) : null) || !button) return;
  const panel = result ? collapsedPanel(result.report) : null;
  button.textContent = panel === null ? 'Select' : `Select P${panel + 1}`;
  button.hidden = panel === null || faceOfCollapsed(result!) === null;
}
