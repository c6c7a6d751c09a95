// Thick panels: each panel's inner face (the offset plane, cut by the chamfers) and its side
// walls, as one mesh under the panels; the nodes whose panels' inner corners miss one point
// (the extra chamfering they need) as markers in the problem colour; and the parts whose inner
// face folds over at this thickness (they cannot be cut as drawn) outlined in magenta, a colour
// no other problem uses, so they read apart from invalid panels and flipped edges.
import * as THREE from 'three';
import { LineMaterial } from 'three/examples/jsm/lines/LineMaterial.js';
import { LineSegments2 } from 'three/examples/jsm/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/examples/jsm/lines/LineSegmentsGeometry.js';
import type { SpreadNodes } from '@flatfacet/wasm';
import type { SolveResult } from '../protocol.ts';
import { PROBLEM_RED } from './colors.ts';
import { outlineSegments } from './panelLayer.ts';

const MATERIAL_COLOUR = 0xc9a77c; // plywood
const FOLDED_COLOUR = 0xe040fb; // magenta (styles.css .legend-dash)

// Spread above this share of the thickness counts (the core lists anything above 1e-9).
export const SPREAD_TOLERANCE = 1e-6;

export class ThickLayer {
  readonly solid: THREE.Mesh<THREE.BufferGeometry, THREE.MeshStandardMaterial>;
  readonly markers: THREE.Points<THREE.BufferGeometry, THREE.PointsMaterial>;
  readonly folded: LineSegments2;
  private readonly foldedMaterial = new LineMaterial({ color: FOLDED_COLOUR, linewidth: 3, depthTest: false });
  private hasFolded = false;

  constructor() {
    this.solid = new THREE.Mesh(
      new THREE.BufferGeometry(),
      // Pushed further back than the panels (panelLayer.ts): where a thin slab's inner face
      // nearly coincides with its panel on screen, the panel wins instead of z-fighting.
      new THREE.MeshStandardMaterial({ color: MATERIAL_COLOUR, side: THREE.DoubleSide, flatShading: true, roughness: 0.8, metalness: 0, polygonOffset: true, polygonOffsetFactor: 3, polygonOffsetUnits: 6 }),
    );
    this.solid.name = 'thick-panels';
    const red = new THREE.Color().setRGB(PROBLEM_RED[0]!, PROBLEM_RED[1]!, PROBLEM_RED[2]!);
    this.markers = new THREE.Points(new THREE.BufferGeometry(), new THREE.PointsMaterial({ color: red, size: 8, sizeAttenuation: false, depthTest: false }));
    this.markers.name = 'spread-nodes';
    this.markers.renderOrder = 10;
    this.folded = new LineSegments2(new LineSegmentsGeometry(), this.foldedMaterial);
    this.folded.name = 'folded-parts';
    this.folded.renderOrder = 10;
  }

  // Nothing shows unless the inner corners match the result's panels. Returns how many nodes
  // and folded parts are marked.
  set(result: SolveResult | null, inner: Float64Array | null, spread: SpreadNodes | null, origin: THREE.Vector3): { nodes: number; folded: number } {
    this.solid.geometry.dispose();
    this.markers.geometry.dispose();
    this.folded.geometry.dispose();
    const usable = result !== null && inner !== null && inner.length > 0 && inner.length === result.panelIndices.length * 3;
    this.solid.geometry = usable ? solidGeometry(result, inner, origin) : new THREE.BufferGeometry();
    const nodes = spread && spread.thickness > 0 ? spread.nodes.filter((n) => n.spread > SPREAD_TOLERANCE * spread.thickness) : [];
    const points = new Float32Array(nodes.length * 3);
    nodes.forEach((n, i) => {
      for (let k = 0; k < 3; k++) points[i * 3 + k] = n.position[k]! - origin.getComponent(k);
    });
    this.markers.geometry = new THREE.BufferGeometry();
    this.markers.geometry.setAttribute('position', new THREE.BufferAttribute(points, 3));
    const folded = result !== null && spread !== null && spread.thickness > 0 ? spread.foldedPanels.filter((p) => p + 1 < result.panelOffsets.length) : [];
    const outline = result !== null ? outlineSegments(result, folded, origin) : new Float32Array();
    this.folded.geometry = new LineSegmentsGeometry();
    if (outline.length >= 6) this.folded.geometry.setPositions(outline);
    this.hasFolded = outline.length >= 6;
    return { nodes: nodes.length, folded: folded.length };
  }

  // Some part is outlined (the viewer shows the outline with the problems).
  get foldedShown(): boolean {
    return this.hasFolded;
  }

  // LineMaterial measures its width in pixels of the drawing buffer.
  setResolution(width: number, height: number): void {
    this.foldedMaterial.resolution.set(width, height);
  }
}

function solidGeometry(result: SolveResult, inner: Float64Array, origin: THREE.Vector3): THREE.BufferGeometry {
  const out: number[] = [];
  const outer = (corner: number): number[] => {
    const v = result.panelIndices[corner]!;
    return [result.panelPositions[v * 3]! - origin.x, result.panelPositions[v * 3 + 1]! - origin.y, result.panelPositions[v * 3 + 2]! - origin.z];
  };
  const innerAt = (corner: number): number[] => [inner[corner * 3]! - origin.x, inner[corner * 3 + 1]! - origin.y, inner[corner * 3 + 2]! - origin.z];
  const panels = result.panelOffsets.length - 1;
  // Inner faces: the panel's own triangulation, vertex ids mapped to the panel's corners.
  for (let t = 0; t < result.panelTriangleIds.length; t++) {
    const panel = result.panelTriangleIds[t]!;
    const start = result.panelOffsets[panel]!;
    const end = result.panelOffsets[panel + 1]!;
    for (let c = 0; c < 3; c++) {
      const vertex = result.panelTriangles[t * 3 + c]!;
      let corner = start;
      while (corner < end && result.panelIndices[corner] !== vertex) corner++;
      out.push(...innerAt(corner < end ? corner : start));
    }
  }
  // Side walls: a quad per edge, outer edge to inner edge.
  for (let p = 0; p < panels; p++) {
    const start = result.panelOffsets[p]!;
    const end = result.panelOffsets[p + 1]!;
    for (let a = start; a < end; a++) {
      const b = a + 1 < end ? a + 1 : start;
      out.push(...outer(a), ...outer(b), ...innerAt(b), ...outer(a), ...innerAt(b), ...innerAt(a));
    }
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(out), 3));
  geometry.computeVertexNormals();
  return geometry;
}
