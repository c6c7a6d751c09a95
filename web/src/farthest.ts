// Where the panels are farthest from the design: the quality report's worst Hausdorff sample
// (hausdorff_worst_point, on the input or on the panels), marked in the view with a legend
// line that gives the distance.
import type { QualityReport } from './protocol.ts';

// The point, in mesh coordinates, when the report has a finite one.
export function farthestPoint(report: QualityReport): [number, number, number] | null {
  const value = report.hausdorff_worst_point;
  if (!Array.isArray(value) || value.length !== 3) return null;
  const [x, y, z] = value as unknown[];
  if (typeof x !== 'number' || typeof y !== 'number' || typeof z !== 'number') return null;
  return Number.isFinite(x) && Number.isFinite(y) && Number.isFinite(z) ? [x, y, z] : null;
}

// The legend line for it, or null when there is nothing to mark (no point, or panels that
// lie on the design everywhere).
export function farthestNote(report: QualityReport): string | null {
  const hausdorff = report.hausdorff;
  if (typeof hausdorff !== 'number' || !(hausdorff > 0) || !Number.isFinite(hausdorff) || farthestPoint(report) === null) return null;
  return `Farthest from the design: ${(hausdorff * 100).toFixed(2)} % of the diagonal`;
}

// Shows or hides the view's legend line (#farthest-legend) for a report (null: no result).
export function renderFarthestLegend(report: QualityReport | null): void {
  const legend = document.getElementById('farthest-legend');
  const text = document.getElementById('farthest-legend-text');
  if (!legend || !text) return;
  const note = report ? farthestNote(report) : null;
  legend.hidden = note === null;
  text.textContent = note ?? '';
}
