// What the panel edits draw over the panels: the selected panel in a bright tint and the
// locked panels hatched (diagonal stripes in each panel's own plane), in the view's frame.
import * as THREE from 'three';
import type { SolveResult } from '../protocol.ts';

export class EditOverlay {
  readonly group = new THREE.Group();
  private readonly selected: THREE.Mesh<THREE.BufferGeometry, THREE.MeshBasicMaterial>;
  private readonly locked: THREE.Mesh<THREE.BufferGeometry, THREE.MeshBasicMaterial>;

  constructor() {
    const over = { transparent: true, side: THREE.DoubleSide, depthWrite: false, polygonOffset: true, polygonOffsetFactor: -2, polygonOffsetUnits: -2 };
    this.selected = new THREE.Mesh(new THREE.BufferGeometry(), new THREE.MeshBasicMaterial({ ...over, color: 0xffd84a, opacity: 0.45 }));
    this.locked = new THREE.Mesh(new THREE.BufferGeometry(), new THREE.MeshBasicMaterial({ ...over, color: 0xffffff, opacity: 0.85, map: hatchTexture() }));
    this.selected.name = 'selected-panel';
    this.locked.name = 'locked-panels';
    this.selected.renderOrder = 2;
    this.locked.renderOrder = 1;
    this.group.add(this.locked, this.selected);
  }

  // `scale`: the stripes' spacing in mesh units (a fraction of the model's size).
  set(result: SolveResult | null, origin: THREE.Vector3, selected: number | null, locked: ReadonlySet<number>, scale: number): void {
    replace(this.selected, result && selected !== null ? panelGeometry(result, origin, new Set([selected]), 0) : null);
    replace(this.locked, result && locked.size > 0 ? panelGeometry(result, origin, locked, scale) : null);
  }
}

function replace(mesh: THREE.Mesh, geometry: THREE.BufferGeometry | null): void {
  mesh.geometry.dispose();
  mesh.geometry = geometry ?? new THREE.BufferGeometry();
  mesh.visible = geometry !== null;
}

// The triangles of the given panels; with `scale` > 0, UVs in each triangle's plane for the
// hatching (the same axes across a planar panel, so its stripes run straight over it).
function panelGeometry(result: SolveResult, origin: THREE.Vector3, panels: ReadonlySet<number>, scale: number): THREE.BufferGeometry {
  const { panelTriangles, panelTriangleIds, panelPositions } = result;
  const picked: number[] = [];
  for (let t = 0; t < panelTriangleIds.length; t++) if (panels.has(panelTriangleIds[t]!)) picked.push(t);
  const positions = new Float32Array(picked.length * 9);
  const uvs = new Float32Array(picked.length * 6);
  const p = [new THREE.Vector3(), new THREE.Vector3(), new THREE.Vector3()];
  const normal = new THREE.Vector3();
  const u = new THREE.Vector3();
  const v = new THREE.Vector3();
  picked.forEach((t, i) => {
    for (let k = 0; k < 3; k++) p[k]!.fromArray(panelPositions, panelTriangles[t * 3 + k]! * 3);
    normal.subVectors(p[1]!, p[0]!).cross(new THREE.Vector3().subVectors(p[2]!, p[0]!)).normalize();
    // A tangent frame from the normal alone, so the panel's triangles share it.
    const helper = Math.abs(normal.x) < 0.9 ? new THREE.Vector3(1, 0, 0) : new THREE.Vector3(0, 1, 0);
    u.crossVectors(normal, helper).normalize();
    v.crossVectors(normal, u);
    for (let k = 0; k < 3; k++) {
      const q = p[k]!;
      positions.set([q.x - origin.x, q.y - origin.y, q.z - origin.z], i * 9 + k * 3);
      if (scale > 0) uvs.set([q.dot(u) / scale, q.dot(v) / scale], i * 6 + k * 2);
    }
  });
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  geometry.setAttribute('uv', new THREE.BufferAttribute(uvs, 2));
  geometry.computeBoundingSphere();
  return geometry;
}

// Dark diagonal stripes on a pale blue, repeating.
function hatchTexture(): THREE.Texture {
  const size = 32;
  const data = new Uint8Array(size * size * 4);
  for (let y = 0; y < size; y++) {
    for (let x = 0; x < size; x++) {
      const stripe = (x + y) % size < size / 3;
      data.set(stripe ? [30, 58, 110, 255] : [170, 200, 240, 150], (y * size + x) * 4);
    }
  }
  const texture = new THREE.DataTexture(data, size, size);
  texture.wrapS = THREE.RepeatWrapping;
  texture.wrapT = THREE.RepeatWrapping;
  texture.magFilter = THREE.LinearFilter;
  texture.needsUpdate = true;
  return texture;
}
