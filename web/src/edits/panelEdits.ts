// Per-panel edits as the design holds them (DesignParams.edits): an ordered list the core
// applies to the solved design (core/remesher.h, RemeshParams::edits). Panels are named by a
// triangle of the loaded (cleaned) mesh inside them, since panel ids change between solves
// and triangle ids do not. Pure: validation, the locked panels of a result, neighbours and
// the shortening of solve chains, unit-tested in Node (tests/web/edits.test.mjs).
import { failure, isRecord, type Checked, type DesignParams } from '../params.ts';

export type PanelEdit =
  | { op: 'split'; face: number }
  | { op: 'merge'; face: number; with: number } // `with`: a triangle of the neighbouring panel
  | { op: 'lock'; face: number }
  | { op: 'unlock'; face: number };

export type EditOp = PanelEdit['op'];

// The core takes up to 10,000 (core/remesh_params_json.h, kMaxEdits).
export const MAX_EDITS = 10_000;
// A triangle id: the core reads them as int (0 .. 2^31 - 1).
const MAX_FACE = 2_147_483_647;

function checkFace(value: unknown, what: string): Checked<number> {
  if (typeof value !== 'number' || !Number.isInteger(value) || value < 0 || value > MAX_FACE) return failure(`${what} must be a triangle number (a whole number from 0)`);
  return { ok: true, value };
}

// An untrusted edit list (a link, the stored session): each edit exactly {op, face} or, for a
// merge, {op, face, with}; rebuilt in that key order so equal lists compare equal as JSON.
export function checkEdits(value: unknown): Checked<PanelEdit[]> {
  if (!Array.isArray(value)) return failure('Panel edits must be a list');
  if (value.length > MAX_EDITS) return failure(`Panel edits: at most ${MAX_EDITS.toLocaleString('en')} edits`);
  const out: PanelEdit[] = [];
  for (let i = 0; i < value.length; i++) {
    const entry: unknown = value[i];
    const at = `Panel edit ${i + 1}`;
    if (!isRecord(entry)) return failure(`${at} must be an object`);
    const op = entry.op;
    if (op !== 'split' && op !== 'merge' && op !== 'lock' && op !== 'unlock') return failure(`${at}: the operation must be split, merge, lock or unlock`);
    const allowed = op === 'merge' ? ['op', 'face', 'with'] : ['op', 'face'];
    for (const key of Object.keys(entry)) if (!allowed.includes(key)) return failure(`${at}: unknown field "${key.slice(0, 40)}"`);
    const face = checkFace(entry.face, `${at}: face`);
    if (!face.ok) return face;
    if (op === 'merge') {
      const other = checkFace(entry.with, `${at}: with`);
      if (!other.ok) return other;
      if (other.value === face.value) return failure(`${at}: a panel cannot be merged with itself`);
      out.push({ op, face: face.value, with: other.value });
    } else {
      out.push({ op, face: face.value });
    }
  }
  return { ok: true, value: out };
}

// Whether every triangle the edits name exists in a mesh of `triangles` triangles; the
// message names the first that does not (a link made for another mesh).
export function checkEditsFit(edits: readonly PanelEdit[], triangles: number): Checked<true> {
  for (let i = 0; i < edits.length; i++) {
    const edit = edits[i]!;
    const faces = edit.op === 'merge' ? [edit.face, edit.with] : [edit.face];
    const bad = faces.find((f) => f >= triangles);
    if (bad !== undefined) return failure(`Panel edit ${i + 1} names triangle ${bad}, but the mesh has ${triangles} triangles`);
  }
  return { ok: true, value: true };
}

// The panels locked after the edits, given the result's panel of each triangle: a lock holds
// its panel's triangles through later solves, so the faces the edits name still lie in it.
export function lockedPanels(edits: readonly PanelEdit[], clusterIds: ArrayLike<number>): Set<number> {
  const locked = new Set<number>();
  for (const edit of edits) {
    const panel = clusterIds[edit.face];
    if (panel === undefined || panel < 0) continue;
    if (edit.op === 'lock') locked.add(panel);
    else if (edit.op === 'unlock') locked.delete(panel);
  }
  return locked;
}

// Panels that share a mesh edge with `panel` (triangles per cluster id, 3 indices each).
export function neighbourPanels(panel: number, clusterIds: ArrayLike<number>, indices: ArrayLike<number>): Set<number> {
  const triangles = Math.min(clusterIds.length, Math.floor(indices.length / 3));
  const byEdge = new Map<string, number[]>();
  const key = (a: number, b: number): string => (a < b ? `${a},${b}` : `${b},${a}`);
  for (let t = 0; t < triangles; t++) {
    for (let k = 0; k < 3; k++) {
      const edge = key(indices[t * 3 + k]!, indices[t * 3 + ((k + 1) % 3)]!);
      const list = byEdge.get(edge);
      if (list) list.push(t);
      else byEdge.set(edge, [t]);
    }
  }
  const found = new Set<number>();
  for (const list of byEdge.values()) {
    if (!list.some((t) => clusterIds[t] === panel)) continue;
    for (const t of list) {
      const other = clusterIds[t]!;
      if (other !== panel && other >= 0) found.add(other);
    }
  }
  return found;
}

// The panels a design has after its edits when solved from scratch: the count the solve
// targeted (DesignParams.panels) plus splits minus merges. (A new count typed after edits is
// reached from the edited design, so there the solve's own count is the truth: clusterCount.)
export function countAfterEdits(panels: number, edits: readonly PanelEdit[]): number {
  let count = panels;
  for (const edit of edits) {
    if (edit.op === 'split') count += 1;
    else if (edit.op === 'merge') count -= 1;
  }
  return count;
}

// The panels (clusters) of a result: ids run 0 .. n-1.
export function clusterCount(clusterIds: ArrayLike<number>): number {
  let max = -1;
  for (let i = 0; i < clusterIds.length; i++) max = Math.max(max, clusterIds[i]!);
  return max + 1;
}

// What "Panels" stands for: it shows the count now (`shown`), which after edits differs from
// the count the solve targeted (`target`, what DesignParams.panels stores, so links replay).
// The count shown, read back with edits, is the target: no change, no re-solve (the core
// agrees: Remesher::kept_count). Any other number typed is a new count to reach.
export function targetOfTyped(typed: number, shown: number, target: number, hasEdits: boolean): number {
  return hasEdits && typed === shown ? target : typed;
}

export function describeEdit(edit: PanelEdit): string {
  switch (edit.op) {
    case 'split':
      return 'split a panel';
    case 'merge':
      return 'merged two panels';
    case 'lock':
      return 'locked a panel';
    case 'unlock':
      return 'unlocked a panel';
  }
}

// Said with a solve from another seed or seeding: the clusters start over, and every edit
// names a triangle, so it now applies to whichever panel holds that triangle (README, "Lock
// panel"); null without edits.
export function newSeedNotice(edits: readonly PanelEdit[]): string | null {
  if (edits.length === 0) return null;
  const what = edits.length === 1 ? 'the panel edit applies to the panel now at its triangle, which may not be the one edited' : `the ${edits.length} panel edits apply to the panels now at their triangles, which may not be the ones edited`;
  return `A new seed starts the panels over: ${what}.`;
}

// Whether two designs differ in their edit list only.
export function sameButEdits(a: DesignParams, b: DesignParams): boolean {
  return JSON.stringify({ ...a, edits: [] }) === JSON.stringify({ ...b, edits: [] });
}

// A solve chain with the steps that only changed the edit list folded into the next one: the
// core applies a longer edit list to the design on show in place, and replays a different one
// from the design before the first edit since the last parameter change (core/remesher.h,
// set_edits), so [p, p + e1, p + e1 e2] and [p, p + e1 e2] give the same panels. A step folds
// only between two that differ from it in the edits alone (both ways an edit-only change in
// the core), and only when both have edits (dropping every edit is a step of its own). Keeps a
// long session of edits within the chain a link can carry (share.ts, MAX_HISTORY).
export function compactChain(chain: readonly DesignParams[]): DesignParams[] {
  const out: DesignParams[] = [];
  for (const params of chain) {
    const last = out[out.length - 1];
    const before = out[out.length - 2];
    if (last && before && last.edits.length > 0 && params.edits.length > 0 && sameButEdits(before, last) && sameButEdits(last, params)) out[out.length - 1] = params;
    else out.push(params);
  }
  return out;
}
