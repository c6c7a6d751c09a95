// When the page prepares the design's mesh again (issue 7), and how what the designer attached
// to the mesh before comes along. The mesh is prepared for the panel count it was opened with;
// a count it cannot serve (core/prepare/prepare.h: fewer than 20 triangles per panel; fewer
// than 30 where 50 per panel is within reach; or a huge mesh with more than 1000 per panel) or
// a new subdivision / target edge length prepares it again from the mesh as loaded, recorded
// in the design (DesignMesh.prepare) so links and reloads make the same mesh. Painted density
// (per vertex) and panel edits (per triangle) are carried over by the worker
// (Session.transferField / remapFaces); this module rebuilds the parameters from what it
// answers. No DOM: unit-tested in Node (tests/web/preparation.test.mjs).
import { levelOf, STEPS_PER_OCTAVE } from './brush/densityField.ts';
import type { PanelEdit } from './edits/panelEdits.ts';
import type { DesignParams } from './params.ts';
import { LEGACY_REFINE_BELOW, type MeshPrepare } from './share.ts';

// The core's policy numbers (core/prepare/prepare.h, kPrepare*).
export const MIN_TRIANGLES_PER_PANEL = 20;
export const REFINE_TRIANGLES_PER_PANEL = 30;
export const HUGE_TRIANGLES_PER_PANEL = 1000;
export const HUGE_TRIANGLES = 400_000;
export const REFINE_ROUNDS = 5; // kPrepareRefineRounds

// What the Surface section sets (prepareControl.ts): subdivision, and a target edge length
// (undefined: automatic, from the panel count).
export interface PrepareChoice {
  subdivide: number;
  edgeLength?: number;
}

// `mesh` (a design's, or the worker's payload of it) with this preparation; none: the field
// left out, the mesh as loaded (as designs saved before preparations were recorded have it).
export function withPrepare<T extends { prepare?: MeshPrepare }>(mesh: T, prepare: MeshPrepare | null | undefined): T {
  const { prepare: _old, ...rest } = mesh;
  return (prepare ? { ...rest, prepare: { ...prepare } } : rest) as T;
}

export function samePrepare(a: MeshPrepare | undefined, b: MeshPrepare | undefined): boolean {
  if (!a || !b) return a === b;
  return a.panels === b.panels && a.subdivide === b.subdivide && a.edgeLength === b.edgeLength && a.refineBelow === b.refineBelow && a.refineRounds === b.refineRounds;
}

// A new preparation records the rule it is made with (share.ts, MeshPrepare): refined below 30,
// or 20 where 50 per panel would pass the page's refinement cap (a mesh that opened as it was
// in a browser tab before the 30 still does), in REFINE_ROUNDS remeshing rounds.
export function prepareOf(panels: number, choice: PrepareChoice): MeshPrepare {
  const refineBelow = panels * TARGET_TRIANGLES_PER_PANEL <= MAX_PAGE_REFINE_TRIANGLES ? REFINE_TRIANGLES_PER_PANEL : LEGACY_REFINE_BELOW;
  return { panels, subdivide: choice.subdivide, ...(choice.edgeLength !== undefined ? { edgeLength: choice.edgeLength } : {}), refineBelow, refineRounds: REFINE_ROUNDS };
}

// The preparation the design's mesh needs to make `panels` panels, or null when the mesh on
// show serves (so the solve warm-starts and paint and edits stay as they are).
// current: the design's preparation; triangles: of the mesh on show.
// A count no higher than the one the mesh was prepared for never re-prepares unless the mesh
// becomes huge for it: a finer mesh only costs time, while preparing again loses the warm start
// and moves paint and edits.
export function preparationNeeded(current: MeshPrepare | undefined, triangles: number, panels: number, choice: PrepareChoice): MeshPrepare | null {
  const next = prepareOf(panels, choice);
  if (choice.subdivide !== (current?.subdivide ?? 0) || choice.edgeLength !== current?.edgeLength) return next;
  // The designer's own resolution: the panel count does not change it.
  if (choice.edgeLength !== undefined) return null;
  // The same preparation makes the same mesh: never again for nothing.
  if (current && samePrepare(current, next)) return null;
  const perPanel = triangles / panels;
  if (perPanel < MIN_TRIANGLES_PER_PANEL) return next;
  // From 20 to 30 the mesh serves, but valid panels come far more often on a finer one: refined
  // for a count above the one the mesh was prepared for, by the rule `next` records (30 where
  // 50 per panel are within the page's cap, else 20: prepareOf). Not for the count a design was
  // saved with under the rule before (20): its edits and paint name that mesh.
  const raised = current !== undefined && panels > current.panels;
  if (raised && perPanel < (next.refineBelow ?? LEGACY_REFINE_BELOW)) return next;
  if (perPanel > HUGE_TRIANGLES_PER_PANEL && triangles > HUGE_TRIANGLES) return next;
  return null;
}

// The most triangles the page refines a mesh to for a panel count (about 50 per panel): the
// core's "huge" threshold. More takes minutes and gigabytes in a browser tab, and the worker
// cannot be interrupted inside one preparation; a target edge length opts in to more.
export const TARGET_TRIANGLES_PER_PANEL = 50;
export const MAX_PAGE_REFINE_TRIANGLES = HUGE_TRIANGLES;

// Why `needed` (preparationNeeded's answer) is refused on the page, or null. triangles: of the
// mesh on show; only a refinement for the panel count is capped.
export function refusedPreparation(needed: MeshPrepare, triangles: number): string | null {
  if (needed.edgeLength !== undefined || triangles / needed.panels >= MIN_TRIANGLES_PER_PANEL) return null;
  const wanted = needed.panels * TARGET_TRIANGLES_PER_PANEL;
  if (wanted <= MAX_PAGE_REFINE_TRIANGLES) return null;
  const most = Math.floor(MAX_PAGE_REFINE_TRIANGLES / TARGET_TRIANGLES_PER_PANEL);
  return `${needed.panels.toLocaleString('en')} panels need the mesh refined to about ${wanted.toLocaleString('en')} triangles, more than the page makes (${MAX_PAGE_REFINE_TRIANGLES.toLocaleString('en')}); ask for at most ${most.toLocaleString('en')} panels, or set a Target edge length`;
}

// The triangles the edits name, in order (a merge names two): what the worker remaps.
export function editFaces(edits: readonly PanelEdit[]): Int32Array {
  const faces: number[] = [];
  for (const edit of edits) {
    faces.push(edit.face);
    if (edit.op === 'merge') faces.push(edit.with);
  }
  return Int32Array.from(faces);
}

// The edits with their triangles replaced by `faces` (editFaces' order, remapped). A merge
// whose two triangles land in one is dropped (nothing is left to merge); `dropped` counts them.
export function remapEdits(edits: readonly PanelEdit[], faces: ArrayLike<number>): { edits: PanelEdit[]; dropped: number } {
  if (faces.length !== editFaces(edits).length) throw new Error('remapEdits: one face per named triangle expected');
  const out: PanelEdit[] = [];
  let dropped = 0;
  let at = 0;
  for (const edit of edits) {
    const face = faces[at++]!;
    if (edit.op === 'merge') {
      const other = faces[at++]!;
      if (other === face) dropped += 1;
      else out.push({ op: 'merge', face, with: other });
    } else {
      out.push({ op: edit.op, face });
    }
  }
  return { edits: out, dropped };
}

// Carried density values (log2 levels interpolated by the worker) back to the page's levels.
export function levelsOf(values: ArrayLike<number>): Int8Array {
  const out = new Int8Array(values.length);
  for (let i = 0; i < values.length; i++) out[i] = levelOf(values[i]! / STEPS_PER_OCTAVE);
  return out;
}

// The parameters on the mesh prepared again: the carried paint's key ('' for none) and the
// remapped edits.
export function carriedParams(params: DesignParams, paintKey: string, faces: ArrayLike<number>): { params: DesignParams; dropped: number } {
  const { edits, dropped } = remapEdits(params.edits, faces);
  return { params: { ...params, paint: paintKey, edits }, dropped };
}
