// The planar panels (triangulated in their own planes, one colour per panel, invalid panels
// tinted red; or coloured by how far each is from the design) and their polygon edges. Or,
// "before the fix", the same polygons through their mesh corners, coloured by how far each is
// from planar: what intersecting planes buys.
import * as THREE from 'three';
import { largestDeviation } from '../farthest.ts';
import type { SolveResult } from '../protocol.ts';
import { deviationColor, idColor, planarityColor, PROBLEM_RED } from './colors.ts';

export class PanelLayer {
  readonly faces: THREE.Mesh<THREE.BufferGeometry, THREE.MeshStandardMaterial>;
  readonly edges: THREE.LineSegments<THREE.BufferGeometry, THREE.LineBasicMaterial>;

  constructor() {
    this.faces = new THREE.Mesh(
      new THREE.BufferGeometry(),
      new THREE.MeshStandardMaterial({
        vertexColors: true,
        side: THREE.DoubleSide,
        flatShading: true,
        roughness: 0.55,
        metalness: 0.05,
        polygonOffset: true,
        polygonOffsetFactor: 1,
        polygonOffsetUnits: 1,
      }),
    );
    this.faces.name = 'panels';
    this.edges = new THREE.LineSegments(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color: 0x16181c }));
    this.edges.name = 'panel-edges';
  }

  set(result: SolveResult | null, origin: THREE.Vector3, beforeFix: boolean, deviation = false): void {
    this.faces.geometry.dispose();
    this.edges.geometry.dispose();
    const usable = result !== null && (!beforeFix || result.cornerPositions.length === result.panelPositions.length);
    this.faces.geometry = usable ? faceGeometry(result, origin, beforeFix, deviation) : new THREE.BufferGeometry();
    this.edges.geometry = usable ? edgeGeometry(result, origin, beforeFix) : new THREE.BufferGeometry();
  }
}

function shifted(positions: Float64Array, vertex: number, origin: THREE.Vector3, out: Float32Array, offset: number): void {
  out[offset] = positions[vertex * 3]! - origin.x;
  out[offset + 1] = positions[vertex * 3 + 1]! - origin.y;
  out[offset + 2] = positions[vertex * 3 + 2]! - origin.z;
}

function faceGeometry(result: SolveResult, origin: THREE.Vector3, beforeFix: boolean, deviation: boolean): THREE.BufferGeometry {
  const source = beforeFix ? result.cornerPositions : result.panelPositions;
  const triangles = Math.floor(result.panelTriangles.length / 3);
  const positions = new Float32Array(triangles * 9);
  const colors = new Float32Array(triangles * 9);
  const invalid = new Set(result.problems.invalidPanels);
  const rgb = new Float32Array(3);
  const largest = largestDeviation(result.panelDeviation);
  for (let t = 0; t < triangles; t++) {
    const panel = result.panelTriangleIds[t] ?? 0;
    if (beforeFix) planarityColor(result.cornerPlanarity[panel] ?? 0, rgb, 0);
    else if (deviation) deviationColor(largest > 0 ? (result.panelDeviation[panel] ?? 0) / largest : 0, rgb, 0);
    else if (invalid.has(panel)) rgb.set(PROBLEM_RED);
    else idColor(panel, rgb, 0);
    for (let corner = 0; corner < 3; corner++) {
      shifted(source, result.panelTriangles[t * 3 + corner]!, origin, positions, t * 9 + corner * 3);
      colors.set(rgb, t * 9 + corner * 3);
    }
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  geometry.setAttribute('color', new THREE.BufferAttribute(colors, 3));
  geometry.computeVertexNormals();
  geometry.computeBoundingSphere();
  return geometry;
}

function edgeGeometry(result: SolveResult, origin: THREE.Vector3, beforeFix: boolean): THREE.BufferGeometry {
  const all = Array.from({ length: Math.max(0, result.panelOffsets.length - 1) }, (_, panel) => panel);
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(outlineSegments(result, all, origin, beforeFix), 3));
  return geometry;
}

// The polygon sides of `panels` as line segments (corner to next corner), shifted by `origin`;
// through the mesh corners ("before the fix") or through the panel vertices.
export function outlineSegments(result: SolveResult, panels: readonly number[], origin: THREE.Vector3, beforeFix = false): Float32Array {
  const { panelOffsets, panelIndices } = result;
  const source = beforeFix ? result.cornerPositions : result.panelPositions;
  let sides = 0;
  for (const panel of panels) sides += panelOffsets[panel + 1]! - panelOffsets[panel]!;
  const positions = new Float32Array(sides * 6);
  let s = 0;
  for (const panel of panels) {
    const begin = panelOffsets[panel]!;
    const end = panelOffsets[panel + 1]!;
    for (let i = begin; i < end; i++) {
      shifted(source, panelIndices[i]!, origin, positions, s * 6);
      shifted(source, panelIndices[i + 1 < end ? i + 1 : begin]!, origin, positions, s * 6 + 3);
      s += 1;
    }
  }
  return positions;
}
