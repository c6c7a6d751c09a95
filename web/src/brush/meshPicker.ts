// Picking on the input surface for the density brush: a BVH (three-mesh-bvh) over the
// surface, so a pointer ray and the brush's reach cost a few tree visits even on meshes of
// hundreds of thousands of triangles. Works in the view's frame (Viewer.surface).
import * as THREE from 'three';
import { MeshBVH } from 'three-mesh-bvh';

export interface Hit {
  point: THREE.Vector3;
  normal: THREE.Vector3; // of the triangle hit, unit, facing the ray
}

export class MeshPicker {
  private readonly bvh: MeshBVH;
  private readonly index: ArrayLike<number>; // the BVH's triangle order (it reorders a copy)
  private readonly stamp: Uint32Array; // per vertex: the query that last collected it
  private query = 0;
  private readonly sphere = new THREE.Sphere();
  private readonly triangle = new THREE.Triangle();

  constructor(private readonly positions: Float32Array, indices: Uint32Array) {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    geometry.setIndex(new THREE.BufferAttribute(indices.slice(), 1));
    this.bvh = new MeshBVH(geometry);
    this.index = geometry.index!.array;
    this.stamp = new Uint32Array(positions.length / 3);
  }

  raycast(ray: THREE.Ray): Hit | null {
    const hit = this.bvh.raycastFirst(ray, THREE.DoubleSide);
    if (!hit) return null;
    const t = hit.faceIndex ?? 0;
    const p = (k: number): THREE.Vector3 => new THREE.Vector3().fromArray(this.positions, this.index[t * 3 + k]! * 3);
    this.triangle.set(p(0), p(1), p(2));
    const normal = this.triangle.getNormal(new THREE.Vector3());
    if (normal.dot(ray.direction) > 0) normal.negate();
    return { point: hit.point.clone(), normal };
  }

  // The vertices within `radius` of `centre` (straight-line distance), each once.
  verticesWithin(centre: THREE.Vector3, radius: number): number[] {
    this.query = (this.query + 1) >>> 0 || 1;
    const stamp = this.query;
    const found: number[] = [];
    const r2 = radius * radius;
    this.sphere.set(centre, radius);
    this.bvh.shapecast({
      intersectsBounds: (box) => this.sphere.intersectsBox(box),
      intersectsTriangle: (_triangle, t) => {
        for (let k = 0; k < 3; k++) {
          const v = this.index[t * 3 + k]!;
          if (this.stamp[v] === stamp) continue;
          this.stamp[v] = stamp;
          const dx = this.positions[v * 3]! - centre.x;
          const dy = this.positions[v * 3 + 1]! - centre.y;
          const dz = this.positions[v * 3 + 2]! - centre.z;
          if (dx * dx + dy * dy + dz * dz <= r2) found.push(v);
        }
        return false;
      },
    });
    return found;
  }
}
