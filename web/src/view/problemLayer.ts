// Problem markers (paper fig. 6): spike vertices as red points, flipped edges as thick red
// lines (screen-space width, since WebGL lines are one pixel wide), corners below the minimum
// corner angle (glass mode) as larger amber points, and where the panels are farthest from the
// design (the Hausdorff distance's worst sample) as a cyan point, the sharpest corner of any
// panel as a violet one, a collapsed panel's centre (collapsedPanel.ts) as a lime one, and
// where panels pass through each other (crossings.ts) as orange ones.
// Invalid panels are tinted by the panel layer.
import * as THREE from 'three';
import { LineMaterial } from 'three/examples/jsm/lines/LineMaterial.js';
import { LineSegments2 } from 'three/examples/jsm/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/examples/jsm/lines/LineSegmentsGeometry.js';
import type { Problems } from '@flatfacet/wasm';

const RED = 0xee2924;
const AMBER = 0xffb000;
const CYAN = 0x22d3ee; // styles.css .legend-dot.farthest
const VIOLET = 0xa855f7; // styles.css .legend-dot.sharpest
const LIME = 0xa3e635; // styles.css .legend-dot.collapsed
export const ORANGE = 0xf97316; // styles.css .legend-dot.crossing

type Point = [number, number, number];

// The report's points to mark (mesh coordinates), each null when there is none.
export interface MarkedPoints {
  farthest: Point | null;
  sharpest: Point | null;
  collapsed: Point | null;
  crossings: number[];  // x y z of each point where two panels cross
}

export function shiftedPoints(values: number[], origin: THREE.Vector3): THREE.BufferGeometry {
  const positions = new Float32Array(values.length);
  for (let i = 0; i < values.length; i++) positions[i] = values[i]! - origin.getComponent(i % 3);
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  return geometry;
}

export class ProblemLayer {
  readonly group = new THREE.Group();
  private readonly spikes: THREE.Points<THREE.BufferGeometry, THREE.PointsMaterial>;
  private readonly flipped: LineSegments2;
  readonly acute: THREE.Points<THREE.BufferGeometry, THREE.PointsMaterial>;
  private readonly farthest: THREE.Points<THREE.BufferGeometry, THREE.PointsMaterial>;
  private readonly sharpest: THREE.Points<THREE.BufferGeometry, THREE.PointsMaterial>;
  private readonly collapsed: THREE.Points<THREE.BufferGeometry, THREE.PointsMaterial>;
  private readonly crossings: THREE.Points<THREE.BufferGeometry, THREE.PointsMaterial>;
  private readonly lineMaterial: LineMaterial;

  constructor() {
    this.group.name = 'problems';
    this.spikes = new THREE.Points(
      new THREE.BufferGeometry(),
      new THREE.PointsMaterial({ color: RED, size: 9, sizeAttenuation: false, depthTest: false }),
    );
    this.lineMaterial = new LineMaterial({ color: RED, linewidth: 4, depthTest: false });
    this.flipped = new LineSegments2(new LineSegmentsGeometry(), this.lineMaterial);
    this.acute = new THREE.Points(
      new THREE.BufferGeometry(),
      new THREE.PointsMaterial({ color: AMBER, size: 13, sizeAttenuation: false, depthTest: false }),
    );
    this.acute.name = 'acute-corners';
    this.farthest = new THREE.Points(new THREE.BufferGeometry(), new THREE.PointsMaterial({ color: CYAN, size: 12, sizeAttenuation: false, depthTest: false }));
    this.farthest.name = 'farthest-point';
    this.farthest.renderOrder = 9;
    this.sharpest = new THREE.Points(new THREE.BufferGeometry(), new THREE.PointsMaterial({ color: VIOLET, size: 12, sizeAttenuation: false, depthTest: false }));
    this.sharpest.name = 'sharpest-corner';
    this.sharpest.renderOrder = 9;
    this.collapsed = new THREE.Points(new THREE.BufferGeometry(), new THREE.PointsMaterial({ color: LIME, size: 14, sizeAttenuation: false, depthTest: false }));
    this.collapsed.name = 'collapsed-panel';
    this.collapsed.renderOrder = 9;
    this.crossings = new THREE.Points(new THREE.BufferGeometry(), new THREE.PointsMaterial({ color: ORANGE, size: 12, sizeAttenuation: false, depthTest: false }));
    this.crossings.name = 'crossing-panels';
    this.crossings.renderOrder = 9;
    this.spikes.renderOrder = 10;
    this.flipped.renderOrder = 10;
    this.acute.renderOrder = 9;
    this.group.add(this.crossings, this.collapsed, this.farthest, this.sharpest, this.acute, this.spikes, this.flipped);
  }

  set(problems: Problems | null, points: MarkedPoints, origin: THREE.Vector3): void {
    for (const [layer, point] of [
      [this.farthest, points.farthest],
      [this.sharpest, points.sharpest],
      [this.collapsed, points.collapsed],
    ] as const) {
      layer.geometry.dispose();
      layer.geometry = shiftedPoints(point ?? [], origin);
      layer.visible = point !== null;
    }
    this.crossings.geometry.dispose();
    this.crossings.geometry = shiftedPoints(points.crossings, origin);
    this.crossings.visible = points.crossings.length >= 3;

    const spikes = problems?.spikes ?? [];
    const spikePositions = new Float32Array(spikes.length);
    for (let i = 0; i < spikes.length; i++) spikePositions[i] = spikes[i]! - origin.getComponent(i % 3);
    this.spikes.geometry.dispose();
    this.spikes.geometry = new THREE.BufferGeometry();
    this.spikes.geometry.setAttribute('position', new THREE.BufferAttribute(spikePositions, 3));

    const edges = problems?.flippedEdges ?? [];
    const edgePositions = new Float32Array(edges.length);
    for (let i = 0; i < edges.length; i++) edgePositions[i] = edges[i]! - origin.getComponent(i % 3);
    this.flipped.geometry.dispose();
    const geometry = new LineSegmentsGeometry();
    if (edgePositions.length >= 6) geometry.setPositions(edgePositions);
    this.flipped.geometry = geometry;
    this.flipped.visible = edgePositions.length >= 6;
    this.spikes.visible = spikePositions.length >= 3;

    const acute = problems?.acuteCorners ?? [];
    this.acute.geometry.dispose();
    this.acute.geometry = shiftedPoints(acute, origin);
    this.acute.visible = acute.length >= 3;
  }

  // Corners below the minimum corner angle on show (for the legend and tests).
  get acuteCorners(): number {
    return this.acute.visible ? this.acute.geometry.getAttribute('position').count : 0;
  }

  // LineMaterial measures its width in pixels of the drawing buffer.
  setResolution(width: number, height: number): void {
    this.lineMaterial.resolution.set(width, height);
  }
}
