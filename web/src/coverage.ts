// The Quality section's coverage row: the smallest share of its own triangles' area that a
// panel covers (report min_panel_coverage). Below a tenth a panel has collapsed to a sliver
// whose triangles lie under its neighbours: valid by the paper's checks, but no part to cut,
// so the row warns and names it (the parts list's label), for the designer to merge it away.
import { collapsedPanel } from './collapsedPanel.ts';
import type { QualityReport } from './protocol.ts';
import type { StatRow } from './statsList.ts';

export function coverageRow(report: QualityReport): StatRow | null {
  const coverage = report.min_panel_coverage;
  const panel = report.min_panel_coverage_panel;
  if (typeof coverage !== 'number' || !Number.isFinite(coverage)) return null;
  if (typeof panel !== 'number' || !Number.isInteger(panel) || panel < 0) return null;
  const name = `P${panel + 1}`;
  // The same judgement as the view's marker (collapsedPanel.ts).
  const warn = collapsedPanel(report) !== null;
  const hint =
    `the smallest share of its own triangles' area that a panel covers (${name}); below 10 % a panel has ` +
    `collapsed to a sliver over its neighbours' triangles` +
    (warn ? `: ${report.collapsed_panels} here. Select ${name} and merge it with a neighbour (Merge with neighbour).` : '');
  return { label: 'Coverage', value: `${Math.round(coverage * 100)} % (${name})`, hint, warn };
}
