// The Quality section's crossing row: pairs of panels that pass through each other in space
// (report crossing_panels, core/panels/panel_crossings.h). The solver does not avoid them yet
// and does not count them invalid, so the row is the designer's warning: such panels cannot
// be built as drawn. And the note on load when the surface itself passes through itself.
import type { MeshInfo } from '@flatfacet/wasm';
import { showLegendLine } from './dom.ts';
import { isRecord } from './params.ts';
import type { QualityReport, SolveResult } from './protocol.ts';
import type { StatRow } from './statsList.ts';

// The pairs as the parts list labels them (P1 ...), or null when the report has no usable list.
export function crossingPairs(report: QualityReport): [string, string][] | null {
  const list = report.crossing_panels;
  if (!Array.isArray(list)) return null;
  const pairs: [string, string][] = [];
  for (const entry of list) {
    const panels = isRecord(entry) ? entry.panels : null;
    if (!Array.isArray(panels) || panels.length !== 2) return null;
    const [a, b] = panels;
    if (!Number.isInteger(a) || !Number.isInteger(b) || (a as number) < 0 || (b as number) < 0) return null;
    pairs.push([`P${(a as number) + 1}`, `P${(b as number) + 1}`]);
  }
  return pairs;
}

// How many pairs of the input's own triangles cross (the surface passing through itself), 0
// when none or not known.
export function inputCrossings(report: QualityReport): number {
  const n = report.input_crossings;
  return typeof n === 'number' && Number.isInteger(n) && n > 0 ? n : 0;
}

// What to do about them: mend a model that passes through itself, else try more panels.
function advice(report: QualityReport): string {
  return inputCrossings(report) > 0
    ? 'The surface itself passes through itself there, and panels made from it follow it: mend the model there.'
    : 'More panels there, or another seed or panel count, may avoid it.';
}

export function crossingRow(report: QualityReport): StatRow | null {
  const pairs = crossingPairs(report);
  if (pairs === null) return null;
  const depth = report.max_crossing_depth;
  const shown = pairs.slice(0, 4).map(([a, b]) => `${a} and ${b}`).join(', ') + (pairs.length > 4 ? ', ...' : '');
  const hint =
    pairs.length === 0
      ? 'pairs of panels that pass through each other in space: none'
      : `pairs of panels that pass through each other in space (${shown}` +
        (typeof depth === 'number' && Number.isFinite(depth) ? `; the deepest ${(depth * 100).toFixed(1)} % of the smaller panel's size` : '') +
        `): they cannot be built as drawn, and the solver does not avoid them yet. ${advice(report)}`;
  return { label: 'Crossing', value: String(pairs.length), hint, warn: pairs.length > 0 };
}

// Where they cross (each pair's deepest point, mesh coordinates, flat x y z ...), for the view's
// orange markers; empty without a usable list.
export function crossingPoints(report: QualityReport): number[] {
  if (crossingPairs(report) === null) return [];
  const out: number[] = [];
  for (const entry of report.crossing_panels as Record<string, unknown>[]) {
    const p = entry.point;
    if (Array.isArray(p) && p.length === 3 && p.every((v) => typeof v === 'number' && Number.isFinite(v))) out.push(...(p as number[]));
  }
  return out;
}

// The legend line beside the markers, or null when nothing crosses.
export function crossingNote(report: QualityReport): string | null {
  const pairs = crossingPairs(report);
  if (pairs === null || pairs.length === 0 || crossingPoints(report).length === 0) return null;
  const why = inputCrossings(report) > 0 ? 'the surface passes through itself there' : 'more panels there may avoid it';
  return `Panels passing through each other: ${pairs.length} ${pairs.length === 1 ? 'pair' : 'pairs'} (${why})`;
}

// #crossing-legend for the result on show (hidden without one).
export function renderCrossings(result: SolveResult | null): void {
  showLegendLine('crossing', result ? crossingNote(result.report) : null);
}

// "N pairs" (or "1 pair") of the surface's own triangles.
function pairsOf(n: number): string {
  return `${n.toLocaleString('en')} ${n === 1 ? 'pair' : 'pairs'}`;
}

// The point to mark where the loaded surface passes through itself, or null.
export function selfCrossingPoint(info: MeshInfo): [number, number, number] | null {
  const n = info.selfCrossings;
  const p = info.selfCrossingPoint;
  if (typeof n !== 'number' || !Number.isInteger(n) || n <= 0 || !Array.isArray(p) || p.length !== 3 || !p.every(Number.isFinite)) return null;
  return [p[0], p[1], p[2]];
}

// Where the loaded surface passes through itself, one point per crossing pair (mesh
// coordinates, flat x y z ...), for the view's orange markers: the core's list, or its first
// point from a worker that gives only that (or a list that is not one point per pair at most);
// empty when it does not cross or was not checked.
export function selfCrossingPoints(info: MeshInfo): number[] {
  const first = selfCrossingPoint(info);
  if (first === null) return [];
  const all = info.selfCrossingPoints;
  const whole = Array.isArray(all) && all.length >= 3 && all.length % 3 === 0 && all.length / 3 <= info.selfCrossings;
  return whole && all.every(Number.isFinite) ? all : first;
}

// The surface passing through itself, told on load: panels there can cross too, whatever
// their count, so the model is what to mend ('' when it does not, or the core did not say).
export function selfCrossingNote(info: MeshInfo): string {
  const n = info.selfCrossings;
  if (n === -1) return 'Not checked whether the surface passes through itself: its triangles overlap too much in space (long thin triangles around one point?).';
  if (typeof n !== 'number' || !Number.isInteger(n) || n <= 0) return '';
  const p = selfCrossingPoint(info);
  const places = selfCrossingPlaces(info);
  const at = p ? `near (${p.map((v) => String(Number(v.toPrecision(3)))).join(', ')})` : '';
  const where = places === 1 ? ` in one place${at ? `, ${at}` : ''}` : places > 1 ? ` in ${places.toLocaleString('en')} places${at ? `, one ${at}` : ''}` : at ? `, one ${at}` : '';
  return `The surface passes through itself: ${pairsOf(n)} of its triangles cross${where}. Panels made from it can pass through each other there, whatever their count: mend the model there before building.`;
}

// The separate places where the loaded surface crosses itself (0 when it does not, or the
// worker did not count them: an older one, or a count that is not a whole number up to the
// pairs).
export function selfCrossingPlaces(info: MeshInfo): number {
  const places = info.selfCrossingPlaces;
  const pairs = info.selfCrossings;
  if (typeof places !== 'number' || !Number.isInteger(places) || places <= 0) return 0;
  return typeof pairs === 'number' && places <= pairs ? places : 0;
}

// #crossing-legend for a surface on show without panels: its own crossing, marked in the view.
export function renderSelfCrossing(info: MeshInfo): void {
  showLegendLine('crossing', selfCrossingLegend(info));
}

// The legend line beside the self-crossing markers, or null without any.
export function selfCrossingLegend(info: MeshInfo): string | null {
  const marked = selfCrossingPoints(info).length / 3;
  if (marked === 0) return null;
  const which =
    marked >= info.selfCrossings ? (marked === 1 ? 'marked' : 'each marked') : marked === 1 ? 'one marked' : `the first ${marked.toLocaleString('en')} marked`;
  const places = selfCrossingPlaces(info);
  const where = places > 1 ? ` in ${places.toLocaleString('en')} places` : '';
  return `The surface passes through itself: ${pairsOf(info.selfCrossings)} of its triangles${where}, ${which}`;
}
