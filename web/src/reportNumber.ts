// A finite number of the report, or null (absent, not a number, NaN or infinite).
import type { QualityReport } from './protocol.ts';

export function numberAt(report: QualityReport, key: string): number | null {
  const value = report[key];
  return typeof value === 'number' && Number.isFinite(value) ? value : null;
}
