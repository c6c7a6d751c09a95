// The sharpest panel corner: the Quality section's "Min angle" (the report's
// min_corner_angle_deg), marked where it is (min_corner_angle_point) with a legend line, so a
// designer can find a needle a fabricator would refuse, and paint density or edit there.
import type { QualityReport, SolveResult } from './protocol.ts';
import { showLegendLine } from './dom.ts';
import { reportPoint } from './reportPoint.ts';

export function sharpestCornerPoint(report: QualityReport): [number, number, number] | null {
  return reportPoint(report, 'min_corner_angle_point');
}

// The legend line, or null when there is nothing to mark (no panels, no point).
export function sharpestCornerNote(report: QualityReport): string | null {
  const angle = report.min_corner_angle_deg;
  if (typeof angle !== 'number' || !Number.isFinite(angle) || !(angle < 360) || sharpestCornerPoint(report) === null) return null;
  return `Sharpest corner: ${angle.toFixed(1)}°`;
}

// #sharpest-legend for the result on show (hidden without one).
export function renderSharpestCorner(result: SolveResult | null): void {
  showLegendLine('sharpest', result ? sharpestCornerNote(result.report) : null);
}
