// How far the panels are from the design: where they are farthest (the quality report's worst
// Hausdorff sample, hausdorff_worst_point, on the input or on the panels), marked in the view
// with a legend line that gives the distance; and the scale of the deviation view (panels
// coloured by their own distance, SolveResult.panelDeviation).
import type { QualityReport, SolveResult } from './protocol.ts';
import { showLegendLine } from './dom.ts';
import { reportPoint } from './reportPoint.ts';

// The point, in mesh coordinates, when the report has a finite one.
export function farthestPoint(report: QualityReport): [number, number, number] | null {
  return reportPoint(report, 'hausdorff_worst_point');
}

// The legend line for it, or null when there is nothing to mark (no point, or panels that
// lie on the design everywhere).
export function farthestNote(report: QualityReport): string | null {
  const hausdorff = report.hausdorff;
  if (typeof hausdorff !== 'number' || !(hausdorff > 0) || !Number.isFinite(hausdorff) || farthestPoint(report) === null) return null;
  return `Farthest from the design: ${(hausdorff * 100).toFixed(2)} % of the diagonal`;
}

// The largest finite panel deviation (0 for none): the top of the deviation view's colours and
// of its legend's scale.
export function largestDeviation(deviation: Float64Array): number {
  return deviation.reduce((a, b) => (Number.isFinite(b) ? Math.max(a, b) : a), 0);
}

// The top of the deviation view's scale, in % of the diagonal.
export function deviationScaleTop(deviation: Float64Array): string {
  return `${(largestDeviation(deviation) * 100).toFixed(2)} % of the diagonal`;
}

// The farthest point's legend line (#farthest-legend, hidden without a result or a point) and
// the deviation legend's scale (#deviation-top) for the result on show.
export function renderDesignDistance(result: SolveResult | null): void {
  const top = document.getElementById('deviation-top');
  if (!showLegendLine('farthest', result ? farthestNote(result.report) : null) || !top) return;
  top.textContent = result ? deviationScaleTop(result.panelDeviation) : '–';
}
