// What one dab of the density brush does to the field, as plain arithmetic on a log2 density
// per vertex (no DOM, no three.js: unit-tested in Node). A stroke is a row of dabs spaced a
// quarter radius apart along the pointer's path (brushController.ts), so its effect depends on
// where it went, not on how long the pointer lingered.
import { MAX_LOG2 } from './densityField.ts';

export type BrushMode = 'add' | 'erase' | 'smooth';
export const BRUSH_MODES: readonly BrushMode[] = ['add', 'erase', 'smooth'];

// log2 density added at a dab's centre at full strength: one pass of a stroke (about eight
// dabs over a point) at strength 1 raises the density about 4x, at 0.5 about 2x.
export const ADD_PER_DAB = 0.5;

export interface Dab {
  centre: readonly [number, number, number];
  radius: number; // > 0, model units
  strength: number; // 0..1
  mode: BrushMode;
}

// Vertex neighbours from the triangles, compressed rows (for smoothing).
export interface Adjacency {
  offsets: Uint32Array; // vertexCount + 1
  neighbours: Uint32Array;
}

export function vertexAdjacency(vertexCount: number, indices: Uint32Array): Adjacency {
  const sets: Set<number>[] = Array.from({ length: vertexCount }, () => new Set<number>());
  for (let t = 0; t + 2 < indices.length; t += 3) {
    for (let k = 0; k < 3; k++) {
      const a = indices[t + k]!;
      const b = indices[t + ((k + 1) % 3)]!;
      sets[a]?.add(b);
      sets[b]?.add(a);
    }
  }
  const offsets = new Uint32Array(vertexCount + 1);
  for (let v = 0; v < vertexCount; v++) offsets[v + 1] = offsets[v]! + sets[v]!.size;
  const neighbours = new Uint32Array(offsets[vertexCount]!);
  for (let v = 0; v < vertexCount; v++) neighbours.set([...sets[v]!].sort((x, y) => x - y), offsets[v]!);
  return { offsets, neighbours };
}

// Smooth falloff: 1 at the centre, 0 at the rim and beyond, flat at both ends.
export function falloff(distance: number, radius: number): number {
  const t = distance / radius;
  if (!(t < 1)) return 0;
  const s = 1 - t * t;
  return s * s;
}

// Applies one dab to `log2` (per vertex) at the `candidates` (vertices near the centre; others
// are not touched). Positions are xyz per vertex in the same frame as the centre. Returns
// whether anything changed.
export function applyDab(log2: Float32Array, positions: Float32Array, candidates: readonly number[], adjacency: Adjacency, dab: Dab): boolean {
  const [cx, cy, cz] = dab.centre;
  const strength = Math.min(1, Math.max(0, dab.strength));
  const weights: number[] = [];
  for (const v of candidates) {
    const dx = positions[v * 3]! - cx;
    const dy = positions[v * 3 + 1]! - cy;
    const dz = positions[v * 3 + 2]! - cz;
    weights.push(strength * falloff(Math.sqrt(dx * dx + dy * dy + dz * dz), dab.radius));
  }
  // Smoothing reads the values before the dab (order of the candidates does not matter).
  const next = candidates.map((v, i) => {
    const w = weights[i]!;
    const value = log2[v]!;
    if (w === 0) return value;
    switch (dab.mode) {
      case 'add':
        return Math.min(MAX_LOG2, value + ADD_PER_DAB * w);
      case 'erase': // back towards 1x as fast as add moves away from it
        return Math.sign(value) * Math.max(0, Math.abs(value) - ADD_PER_DAB * w);
      case 'smooth': {
        const from = adjacency.offsets[v]!;
        const to = adjacency.offsets[v + 1]!;
        if (to === from) return value;
        let sum = 0;
        for (let k = from; k < to; k++) sum += log2[adjacency.neighbours[k]!]!;
        return value + w * (sum / (to - from) - value);
      }
    }
  });
  let changed = false;
  candidates.forEach((v, i) => {
    if (log2[v] !== next[i]) changed = true;
    log2[v] = next[i]!;
  });
  return changed;
}

// Dab centres along a segment of the pointer's path, every `spacing`, carrying the distance
// left over from the previous segment: returns the centres and the new leftover.
export function dabsAlong(from: readonly [number, number, number], to: readonly [number, number, number], spacing: number, carried: number): { centres: [number, number, number][]; carried: number } {
  const d = [to[0] - from[0], to[1] - from[1], to[2] - from[2]] as const;
  const length = Math.hypot(d[0], d[1], d[2]);
  const centres: [number, number, number][] = [];
  let at = spacing - carried;
  while (at <= length && centres.length < 10_000) {
    const f = at / length;
    centres.push([from[0] + d[0] * f, from[1] + d[1] * f, from[2] + d[2] * f]);
    at += spacing;
  }
  return { centres, carried: length - (at - spacing) };
}
