// The quality panel: the report's numbers in words a designer reads (DESIGN.md 5 targets).
import type { QualityReport, SolveResult } from './protocol.ts';
import { coverageRow } from './coverage.ts';
import { crossingRow } from './crossings.ts';
import { planarityRow } from './planarity.ts';
import { numberAt } from './reportNumber.ts';
import { scientific } from './scientific.ts';
import { problemsPhrase, summarizeInvalid } from './invalidPanels.ts';
import { statsList, type StatRow } from './statsList.ts';


// The invalid panels appear as a count or as a list of {panel, problems}.
function countAt(report: QualityReport, key: string): number | null {
  const value = report[key];
  if (Array.isArray(value)) return value.length;
  return numberAt(report, key);
}

// Share of interior nodes where exactly three panels meet, from the key or the histogram.
export function valence3Share(report: QualityReport): number | null {
  const direct = numberAt(report, 'valence3_share');
  if (direct !== null) return direct;
  const histogram = report.interior_valence;
  let total = 0;
  let three = 0;
  if (Array.isArray(histogram)) {
    histogram.forEach((count, valence) => {
      if (typeof count === 'number') {
        total += count;
        if (valence === 3) three += count;
      }
    });
  } else if (typeof histogram === 'object' && histogram !== null) {
    for (const [valence, count] of Object.entries(histogram)) {
      if (typeof count === 'number') {
        total += count;
        if (valence === '3') three += count;
      }
    }
  } else {
    return null;
  }
  return total > 0 ? three / total : null;
}

type Row = StatRow;

export function statsRows(result: SolveResult): Row[] {
  const report = result.report;
  const timings = typeof report.timings_s === 'object' && report.timings_s !== null ? (report.timings_s as Record<string, unknown>) : {};
  const total = typeof timings.total === 'number' ? timings.total : null;
  const share = valence3Share(report);
  // The report's "invalid" list (the status line's count too), else its count.
  const summary = summarizeInvalid(report);
  const invalid = summary ? summary.panels + summary.unbuilt : countAt(report, 'invalid_panels');
  const invalidWhy = summary && summary.problems.length > 0 ? `: ${problemsPhrase(summary)}` : '';
  const topology = report.topology_preserved;
  const minAngle = numberAt(report, 'min_corner_angle_deg');
  const hausdorff = numberAt(report, 'hausdorff');
  const minAngleTarget = numberAt(report, 'min_corner_angle_target_deg') ?? 0;
  const acute = numberAt(report, 'acute_corners');
  const coverage = coverageRow(report);
  const crossing = crossingRow(report);
  const undirected = numberAt(report, 'anisotropy_isotropic_faces');
  const before = result.cornerPlanarity.length > 0 ? result.cornerPlanarity.reduce((worst, value) => Math.max(worst, value), 0) : null;
  return [
    { label: 'Panels', value: String(numberAt(report, 'panels') ?? '–'), hint: 'planar panels in the result' },
    planarityRow(report),
    { label: 'Before the fix', value: scientific(before), hint: 'planarity of the same polygons through their mesh corners, before the planes were intersected' },
    { label: 'Hausdorff', value: hausdorff === null ? '–' : `${(hausdorff * 100).toFixed(2)} %`, hint: 'two-sided distance to the input surface, relative to the bounding-box diagonal; where it is largest is marked cyan in the view' },
    { label: 'Valence 3', value: share === null ? '–' : `${(share * 100).toFixed(1)} %`, hint: 'interior nodes where exactly three panels meet' },
    { label: 'Min angle', value: minAngle === null ? '–' : `${minAngle.toFixed(1)}°`, hint: 'smallest corner angle of any panel; where it is is marked violet in the view' },
    ...(coverage ? [coverage] : []),
    ...(minAngleTarget > 0
      ? [{ label: 'Acute corners', value: acute === null ? '–' : String(acute), hint: `panel corners below the minimum corner angle of ${minAngleTarget}° (marked amber)`, warn: (acute ?? 0) > 0 }]
      : []),
    ...(undirected !== null
      ? [{ label: 'No direction', value: String(undirected), hint: 'triangles where the direction expression is zero or along the surface normal: no stretch there' }]
      : []),
    { label: 'Invalid', value: invalid === null ? '–' : String(invalid), hint: `panels that are not simple, star-shaped and spike-free (shown red), and clusters that could not become panels${invalidWhy}`, warn: (invalid ?? 0) > 0 },
    { label: 'Topology', value: topology === true ? 'preserved' : topology === false ? 'changed' : '–', hint: 'same Euler characteristic and boundary loops as the input', warn: topology === false },
    ...(crossing ? [crossing] : []),
    { label: 'Solve time', value: `${result.solveSeconds.toFixed(2)} s`, hint: total === null ? 'in the worker' : `in the worker; the core reports ${total.toFixed(2)} s` },
  ];
}

export function renderStats(container: HTMLElement, result: SolveResult | null): void {
  container.replaceChildren();
  if (!result) {
    const empty = document.createElement('p');
    empty.className = 'muted';
    empty.textContent = 'Remesh to see the quality of the panels.';
    container.append(empty);
    return;
  }
  container.append(statsList(statsRows(result)));
  // For bench/browser_bench.mjs: the worker's wall time and the core's own total.
  container.dataset.solveSeconds = result.solveSeconds.toFixed(4);
  const timings = result.report.timings_s;
  if (typeof timings === 'object' && timings !== null && typeof (timings as Record<string, unknown>).total === 'number') {
    container.dataset.coreSeconds = ((timings as Record<string, number>).total ?? 0).toFixed(4);
  }
}
