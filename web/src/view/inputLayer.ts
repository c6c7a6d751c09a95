// The input surface, coloured per triangle by its cluster (grey when unassigned). Non-indexed
// so each triangle has its own vertex colours. The shading is baked into the colours (a fixed
// light) and drawn unlit: this layer has every input triangle (50k and more) and is redrawn
// live during a solve, and a lit material costs a software rasteriser whole frames.
import * as THREE from 'three';
import { idColor } from './colors.ts';

const LIGHT = new THREE.Vector3(0.35, 0.6, 0.7).normalize();

export class InputLayer {
  readonly mesh: THREE.Mesh<THREE.BufferGeometry, THREE.MeshBasicMaterial>;
  private triangleCount = 0;
  private shade: Float32Array = new Float32Array(0); // per triangle: 0.5 (grazing light) .. 1 (facing it)
  private indices: Uint32Array = new Uint32Array(0);
  private clusterIds: Int32Array | null = null;
  // RGB per vertex shown instead of the clusters (the density paint's colour map), or null.
  private vertexColors: Float32Array | null = null;

  constructor() {
    const material = new THREE.MeshBasicMaterial({
      vertexColors: true,
      side: THREE.DoubleSide,
      // Behind the panels where both show, so the panels win the depth test.
      polygonOffset: true,
      polygonOffsetFactor: 2,
      polygonOffsetUnits: 2,
    });
    this.mesh = new THREE.Mesh(new THREE.BufferGeometry(), material);
    this.mesh.name = 'input';
  }

  // Positions are already shifted to the viewer's origin (Float32 near zero keeps precision).
  setSurface(positions: Float32Array, indices: Uint32Array): void {
    this.triangleCount = Math.floor(indices.length / 3);
    this.indices = indices;
    this.vertexColors = null;
    const flat = new Float32Array(this.triangleCount * 9);
    for (let t = 0; t < this.triangleCount * 3; t++) {
      const v = indices[t]!;
      flat[t * 3] = positions[v * 3]!;
      flat[t * 3 + 1] = positions[v * 3 + 1]!;
      flat[t * 3 + 2] = positions[v * 3 + 2]!;
    }
    this.shade = bakedShade(flat, this.triangleCount);
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(flat, 3));
    geometry.setAttribute('color', new THREE.BufferAttribute(new Float32Array(flat.length), 3));
    geometry.computeBoundingSphere();
    this.mesh.geometry.dispose();
    this.mesh.geometry = geometry;
    this.setClusters(null);
  }

  // One cluster id per cleaned triangle; null or a wrong length shows the plain surface.
  setClusters(clusterIds: Int32Array | null): void {
    this.clusterIds = clusterIds;
    if (!this.vertexColors) this.paint();
  }

  // Colours per vertex (RGB triples, one per vertex of the surface) instead of the
  // clusters, interpolated across each triangle; null goes back to the clusters.
  setVertexColors(rgb: Float32Array | null): void {
    this.vertexColors = rgb;
    // Under the panel edges drawn over the paint, even where a panel's plane dips below it.
    const material = this.mesh.material;
    const offset = rgb ? 8 : 2;
    if (material.polygonOffsetFactor !== offset) {
      material.polygonOffsetFactor = offset;
      material.polygonOffsetUnits = offset;
      material.needsUpdate = true;
    }
    this.paint();
  }

  private paint(): void {
    const attribute = this.mesh.geometry.getAttribute('color');
    if (!(attribute instanceof THREE.BufferAttribute)) return;
    const colors = attribute.array as Float32Array;
    const perVertex = this.vertexColors;
    if (perVertex) {
      for (let corner = 0; corner < this.triangleCount * 3; corner++) {
        const v = this.indices[corner]! * 3;
        const shade = this.shade[Math.floor(corner / 3)]!;
        colors[corner * 3] = (perVertex[v] ?? 0) * shade;
        colors[corner * 3 + 1] = (perVertex[v + 1] ?? 0) * shade;
        colors[corner * 3 + 2] = (perVertex[v + 2] ?? 0) * shade;
      }
      attribute.needsUpdate = true;
      return;
    }
    const clusterIds = this.clusterIds;
    const rgb = new Float32Array(3);
    const usable = clusterIds !== null && clusterIds.length === this.triangleCount;
    for (let t = 0; t < this.triangleCount; t++) {
      idColor(usable ? clusterIds[t]! : -1, rgb, 0);
      const shade = this.shade[t]!;
      for (let corner = 0; corner < 3; corner++) {
        const offset = t * 9 + corner * 3;
        colors[offset] = rgb[0]! * shade;
        colors[offset + 1] = rgb[1]! * shade;
        colors[offset + 2] = rgb[2]! * shade;
      }
    }
    attribute.needsUpdate = true;
  }
}

function bakedShade(flat: Float32Array, triangles: number): Float32Array {
  const shade = new Float32Array(triangles);
  const a = new THREE.Vector3();
  const b = new THREE.Vector3();
  const c = new THREE.Vector3();
  for (let t = 0; t < triangles; t++) {
    a.fromArray(flat, t * 9);
    b.fromArray(flat, t * 9 + 3).sub(a);
    c.fromArray(flat, t * 9 + 6).sub(a);
    const normal = b.cross(c).normalize();
    shade[t] = 0.5 + 0.5 * Math.abs(normal.dot(LIGHT)); // double-sided: either face lit alike
  }
  return shade;
}
