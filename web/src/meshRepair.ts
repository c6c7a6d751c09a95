// How an opened mesh is repaired beyond the clean-up every load gets (issue 7, Session.setRepair):
// holes of at most `fillHoles` edges filled, and with `largestPart` a mesh with non-manifold
// edges cut there and only its largest part kept (a stray part far off dropped too). Recorded with the design's mesh
// (DesignMesh.repair) so a link or a reload opens the very same mesh; absent means neither
// (links made before this open as they did). No DOM: unit-tested in Node.
import { failure, type Checked } from './params.ts';

export interface MeshRepair {
  fillHoles: number; // 0 = off
  largestPart: boolean;
}

export const MAX_FILL_HOLES = 500;

function isRecord(value: unknown): value is Record<string, unknown> {
  return typeof value === 'object' && value !== null && !Array.isArray(value);
}

// A mesh's repair from a link or the stored session: absent, or exactly {fillHoles, largestPart}.
export function checkRepair(value: unknown, where: string): Checked<MeshRepair | undefined> {
  if (value === undefined) return { ok: true, value: undefined };
  if (!isRecord(value)) return failure(`${where}: the mesh's repair is not an object`);
  for (const key of Object.keys(value)) if (key !== 'fillHoles' && key !== 'largestPart') return failure(`${where}: the mesh's repair has an unknown field "${key.slice(0, 40)}"`);
  const { fillHoles, largestPart } = value;
  if (typeof fillHoles !== 'number' || !Number.isInteger(fillHoles) || fillHoles < 0 || fillHoles > MAX_FILL_HOLES) return failure(`${where}: holes to fill must have 0 to ${MAX_FILL_HOLES} edges`);
  if (typeof largestPart !== 'boolean') return failure(`${where}: the mesh's repair says neither yes nor no to the largest manifold part`);
  return { ok: true, value: { fillHoles, largestPart } };
}

// What a link or the stored session records: nothing for the default (no repair asked).
export function repairJson(mesh: { repair?: MeshRepair }): { repair?: MeshRepair } {
  const r = mesh.repair;
  return r && (r.fillHoles > 0 || r.largestPart) ? { repair: { fillHoles: r.fillHoles, largestPart: r.largestPart } } : {};
}
