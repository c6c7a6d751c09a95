// Planarity in words: flat to 10⁻⁹ by construction (DESIGN.md 5), except where the coordinates
// cannot hold it (far from the origin a double's last digit is already more than that of a
// panel: the report's planarity_floor) or at an invalid panel whose planes do not meet. The
// CLI's warning says the same (core/quality/report_json.h, planarity_phrase).
import { panelProblems } from './invalidPanels.ts';
import type { QualityReport } from './protocol.ts';
import { numberAt } from './reportNumber.ts';
import { scientific } from './scientific.ts';
import type { StatRow } from './statsList.ts';

export const PLANARITY_TARGET = 1e-9;
// Within this many times the rounding floor the bend is the coordinates' (kRoundingAllowance in
// core/quality/planarity.h).
const ROUNDING_ALLOWANCE = 100;

// Why the panels are above the target (cause null when they are not): the coordinates far
// from the origin, a far-off part, an invalid panel, or nothing known.
type Cause = 'origin' | 'part' | 'invalid' | 'unknown';

function reason(report: QualityReport): { cause: Cause | null; why: string } {
  const planarity = numberAt(report, 'max_planarity');
  if (planarity === null || !(planarity > PLANARITY_TARGET)) return { cause: null, why: '' };
  const floor = numberAt(report, 'planarity_floor') ?? 0;
  if (floor * ROUNDING_ALLOWANCE >= planarity)
    return { cause: 'origin', why: `the coordinates are so far from the origin that their last digit is already ${scientific(floor)} of a panel: moved near the origin, the model gives flat panels` };
  const solveFloor = numberAt(report, 'planarity_floor_solve') ?? 0;
  if (solveFloor * ROUNDING_ALLOWANCE >= planarity)
    return { cause: 'part', why: `a part of the mesh lies so far from the rest that the coordinates' last digit is already ${scientific(solveFloor)} of a panel: without the far-off part, the model gives flat panels` };
  const panel = numberAt(report, 'max_planarity_panel');
  if (panel === null) return { cause: 'unknown', why: '' };
  const least = `the least flat is panel ${panel}`;
  const problems = panelProblems(report, panel);
  // Off its plane with every other check passed (the core's "off_plane"): the solver's error.
  if (problems?.includes('off_plane'))
    return { cause: 'invalid', why: `${least}, an invalid one, off its plane though it passes every other check (an error of the solver: please report it)` };
  if (problems) return { cause: 'invalid', why: `${least}, an invalid one (a vertex where its planes do not meet)` };
  return { cause: 'unknown', why: least };
}

export function planarityRow(report: QualityReport): StatRow {
  const { cause, why } = reason(report);
  const above = cause !== null;
  return {
    label: 'Planarity',
    value: scientific(numberAt(report, 'max_planarity')),
    hint: `largest distance of a panel vertex to its plane, relative to the panel size (target ≤ 10⁻⁹)${above ? `; above the target${why ? `: ${why}` : ''}` : ''}`,
    warn: above,
  };
}

// For the status line, only where the designer can act on it (valid panels on a model far from
// the origin; invalid panels are named there already): '' otherwise.
export function planarityWarning(report: QualityReport): string {
  const { cause } = reason(report);
  if (cause !== 'origin' && cause !== 'part') return '';
  const where = cause === 'origin' ? 'the model is far from the origin (move it nearer)' : 'a part of the mesh lies far from the rest (remove it)';
  return `panels flat to ${scientific(numberAt(report, 'max_planarity'))} of their size, not 10⁻⁹: ${where}`;
}
