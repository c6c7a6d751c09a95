// A point the quality report gives in mesh coordinates (an [x, y, z] array: where the panels are
// farthest from the design, where the sharpest corner is), when it is there and finite.
import type { QualityReport } from './protocol.ts';

export function reportPoint(report: QualityReport, key: string): [number, number, number] | null {
  const value = report[key];
  if (!Array.isArray(value) || value.length !== 3) return null;
  const [x, y, z] = value as unknown[];
  if (typeof x !== 'number' || typeof y !== 'number' || typeof z !== 'number') return null;
  return Number.isFinite(x) && Number.isFinite(y) && Number.isFinite(z) ? [x, y, z] : null;
}
