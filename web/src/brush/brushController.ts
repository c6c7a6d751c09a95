// The density brush in the viewport: while "Paint density" is on, a cursor ring follows the
// pointer over the surface, and a left-button drag that starts on the surface paints (the orbit
// controls never see it); a drag that starts off the surface, or with another button, still
// turns the view. A stroke works on a log2 copy of the field and ends as one quantised field.
import * as THREE from 'three';
import type { Viewer } from '../view/viewer.ts';
import { applyDab, dabsAlong, vertexAdjacency, type Adjacency, type BrushMode } from './brushPainter.ts';
import { quantiseField, STEPS_PER_OCTAVE } from './densityField.ts';
import { MeshPicker } from './meshPicker.ts';

export interface BrushSettings {
  radius: number; // fraction of the surface's bounding-box diagonal
  strength: number; // 0..1
  mode: BrushMode;
}

export interface BrushHost {
  viewer: Viewer;
  settings(): BrushSettings;
  field(): Int8Array | null; // the field on show (levels per vertex), null: none painted
  preview(log2: Float32Array): void; // the stroke so far
  strokeEnded(field: Int8Array): void;
}

interface Stroke {
  pointerId: number;
  log2: Float32Array;
  last: [number, number, number];
  carried: number;
  centres: [number, number, number][]; // of the dabs, view frame
}

type Vec = [number, number, number];

export class BrushController {
  private enabled = false;
  private picker: MeshPicker | null = null;
  private adjacency: Adjacency | null = null;
  private stroke: Stroke | null = null;
  private readonly cursor = makeCursor();
  private readonly raycaster = new THREE.Raycaster();

  constructor(private readonly host: BrushHost) {
    host.viewer.addOverlay(this.cursor);
    const canvas = host.viewer.canvas;
    const container = canvas.parentElement ?? canvas;
    // Capture phase on the container: runs before the orbit controls' listener on the canvas.
    container.addEventListener('pointerdown', (event) => this.down(event), { capture: true });
    canvas.addEventListener('pointermove', (event) => this.move(event));
    canvas.addEventListener('pointerup', (event) => this.up(event));
    canvas.addEventListener('pointercancel', (event) => this.up(event));
    canvas.addEventListener('pointerleave', () => this.hideCursor());
  }

  get active(): boolean {
    return this.enabled;
  }

  get painting(): boolean {
    return this.stroke !== null;
  }

  setEnabled(on: boolean): void {
    this.enabled = on;
    if (!on) {
      this.stroke = null;
      this.hideCursor();
    }
    this.host.viewer.canvas.parentElement?.classList.toggle('painting', on);
  }

  // A new surface: picking structures are rebuilt on first use.
  surfaceChanged(): void {
    this.picker = null;
    this.adjacency = null;
    this.stroke = null;
    this.hideCursor();
  }

  private ensurePicker(): MeshPicker | null {
    const surface = this.host.viewer.surface;
    if (!surface) return null;
    if (!this.picker) {
      this.picker = new MeshPicker(surface.positions, surface.indices);
      this.adjacency = vertexAdjacency(surface.positions.length / 3, surface.indices);
    }
    return this.picker;
  }

  private hit(event: PointerEvent): { point: THREE.Vector3; normal: THREE.Vector3 } | null {
    const picker = this.ensurePicker();
    if (!picker) return null;
    const rect = this.host.viewer.canvas.getBoundingClientRect();
    const ndc = new THREE.Vector2(((event.clientX - rect.left) / rect.width) * 2 - 1, -((event.clientY - rect.top) / rect.height) * 2 + 1);
    this.raycaster.setFromCamera(ndc, this.host.viewer.viewCamera);
    return picker.raycast(this.raycaster.ray);
  }

  private radius(): number {
    return Math.max(1e-9, this.host.settings().radius * (this.host.viewer.surface?.diagonal ?? 1));
  }

  private down(event: PointerEvent): void {
    if (!this.enabled || event.button !== 0 || event.altKey || this.stroke) return;
    const hit = this.hit(event);
    if (!hit) return; // off the surface: the view turns
    event.stopPropagation();
    event.preventDefault();
    const surface = this.host.viewer.surface!;
    const vertices = surface.positions.length / 3;
    const field = this.host.field();
    const log2 = new Float32Array(vertices);
    if (field && field.length === vertices) for (let v = 0; v < vertices; v++) log2[v] = field[v]! / STEPS_PER_OCTAVE;
    const at: Vec = [hit.point.x, hit.point.y, hit.point.z];
    this.stroke = { pointerId: event.pointerId, log2, last: at, carried: 0, centres: [] };
    try {
      this.host.viewer.canvas.setPointerCapture(event.pointerId); // moves beyond the canvas still paint
    } catch {
      // a pointer that is already gone: the stroke ends with its pointerup anyway
    }
    this.dab(at);
    this.showCursor(hit);
    this.host.preview(log2);
  }

  private move(event: PointerEvent): void {
    if (!this.enabled) return;
    const hit = this.hit(event);
    if (hit) this.showCursor(hit);
    else this.hideCursor();
    const stroke = this.stroke;
    if (!stroke || event.pointerId !== stroke.pointerId || !hit) return;
    const to: Vec = [hit.point.x, hit.point.y, hit.point.z];
    const path = dabsAlong(stroke.last, to, this.radius() / 4, stroke.carried);
    for (const centre of path.centres) this.dab(centre);
    stroke.last = to;
    stroke.carried = path.carried;
    if (path.centres.length > 0) this.host.preview(stroke.log2);
  }

  private up(event: PointerEvent): void {
    const stroke = this.stroke;
    if (!stroke || event.pointerId !== stroke.pointerId) return;
    this.stroke = null;
    if (this.host.viewer.canvas.hasPointerCapture(event.pointerId)) this.host.viewer.canvas.releasePointerCapture(event.pointerId);
    // Where the stroke went, in mesh coordinates, for tests and scripts (data-last-stroke).
    const o = this.host.viewer.offset;
    const step = Math.max(1, Math.ceil(stroke.centres.length / 200));
    const points = stroke.centres.filter((_, i) => i % step === 0).map((c) => [c[0] + o.x, c[1] + o.y, c[2] + o.z]);
    document.body.dataset.lastStroke = JSON.stringify({ radius: this.radius(), points });
    this.host.strokeEnded(quantiseField(stroke.log2));
  }

  private dab(centre: Vec): void {
    const stroke = this.stroke;
    const picker = this.picker;
    const surface = this.host.viewer.surface;
    if (!stroke || !picker || !surface || !this.adjacency) return;
    const settings = this.host.settings();
    const radius = this.radius();
    stroke.centres.push(centre);
    const candidates = picker.verticesWithin(new THREE.Vector3(...centre), radius);
    applyDab(stroke.log2, surface.positions, candidates, this.adjacency, { centre, radius, strength: settings.strength, mode: settings.mode });
  }

  private showCursor(hit: { point: THREE.Vector3; normal: THREE.Vector3 }): void {
    const radius = this.radius();
    this.cursor.position.copy(hit.point).addScaledVector(hit.normal, radius * 0.02);
    this.cursor.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), hit.normal);
    this.cursor.scale.setScalar(radius);
    this.cursor.visible = true;
    this.host.viewer.requestRender();
  }

  private hideCursor(): void {
    if (!this.cursor.visible) return;
    this.cursor.visible = false;
    this.host.viewer.requestRender();
  }
}

// A unit ring with a faint disc and a centre dot, drawn over everything so it shows on any
// colour of the paint.
function makeCursor(): THREE.Group {
  const group = new THREE.Group();
  group.name = 'brush-cursor';
  const overlay = (color: number, opacity: number): THREE.MeshBasicMaterial =>
    new THREE.MeshBasicMaterial({ color, transparent: true, opacity, depthTest: false, depthWrite: false, side: THREE.DoubleSide });
  const parts: [THREE.BufferGeometry, THREE.MeshBasicMaterial][] = [
    [new THREE.CircleGeometry(1, 64), overlay(0xffffff, 0.14)],
    [new THREE.RingGeometry(0.93, 1.0, 96), overlay(0x111111, 0.9)],
    [new THREE.RingGeometry(0.96, 1.0, 96), overlay(0xffffff, 1)],
    [new THREE.CircleGeometry(0.035, 24), overlay(0xffffff, 1)],
  ];
  parts.forEach(([geometry, material], i) => {
    const mesh = new THREE.Mesh(geometry, material);
    mesh.renderOrder = 1000 + i;
    group.add(mesh);
  });
  group.visible = false;
  return group;
}
