// Turns what the designer opens into something the worker loads. OBJ, OFF, STL and PLY go to
// the core's own readers as bytes (so the page and the command line read a file identically);
// glTF/GLB goes through three.js and arrives as one triangle soup in world coordinates.
import { Mesh, Vector3, type BufferGeometry, type Object3D } from 'three';
import type { Example } from './examples.ts';
import { failure, type Checked } from './params.ts';
import type { MeshPayload } from './protocol.ts';

const GLTF_EXTENSIONS = ['gltf', 'glb'];
export const ACCEPTED_EXTENSIONS = ['obj', 'off', 'stl', 'ply', ...GLTF_EXTENSIONS];

export function extensionOf(name: string): string {
  const dot = name.lastIndexOf('.');
  return dot < 0 ? '' : name.slice(dot + 1).toLowerCase();
}

export async function payloadFromFile(name: string, bytes: Uint8Array): Promise<Checked<MeshPayload>> {
  if (GLTF_EXTENSIONS.includes(extensionOf(name))) return gltfPayload(name, bytes);
  // Anything else goes to the core, which reads by extension or else by content and names
  // the problem when it cannot.
  return { ok: true, value: { kind: 'bytes', name, bytes } };
}

export async function fetchExampleBytes(file: string): Promise<Checked<Uint8Array>> {
  try {
    const response = await fetch(new URL(`examples/${file}`, document.baseURI));
    if (!response.ok) return failure(`the example ${file} is not on this server (HTTP ${response.status})`);
    return { ok: true, value: new Uint8Array(await response.arrayBuffer()) };
  } catch (error) {
    return failure(`the example ${file} could not be fetched (${String(error)})`);
  }
}

export async function payloadFromExample(example: Example): Promise<Checked<MeshPayload>> {
  if (example.kind === 'shape') return { ok: true, value: { kind: 'shape', name: example.shape, triangles: example.triangles } };
  const bytes = await fetchExampleBytes(example.file);
  if (!bytes.ok) return bytes;
  return { ok: true, value: { kind: 'bytes', name: example.file, bytes: bytes.value } };
}

async function gltfPayload(name: string, bytes: Uint8Array): Promise<Checked<MeshPayload>> {
  // Loaded on demand: most designers never open glTF, and the loader is large.
  const { GLTFLoader } = await import('three/examples/jsm/loaders/GLTFLoader.js');
  let scene: Object3D;
  try {
    const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength) as ArrayBuffer;
    scene = (await new GLTFLoader().parseAsync(buffer, '')).scene;
  } catch (error) {
    const reason = error instanceof Error ? error.message : String(error);
    return failure(`${name}: not a readable glTF file (${reason.slice(0, 160)}); a .gltf that refers to separate files cannot be opened, export a .glb instead`);
  }
  scene.updateMatrixWorld(true);
  const positions: number[] = [];
  const indices: number[] = [];
  const point = new Vector3();
  scene.traverse((object) => {
    if (!(object instanceof Mesh)) return;
    const geometry = object.geometry as BufferGeometry;
    const position = geometry.getAttribute('position');
    if (!position) return;
    const base = positions.length / 3;
    for (let i = 0; i < position.count; i++) {
      point.fromBufferAttribute(position, i).applyMatrix4(object.matrixWorld);
      positions.push(point.x, point.y, point.z);
    }
    const index = geometry.getIndex();
    const count = index ? index.count : position.count;
    for (let i = 0; i + 2 < count; i += 3) {
      for (let corner = 0; corner < 3; corner++) indices.push(base + (index ? index.getX(i + corner) : i + corner));
    }
  });
  if (indices.length === 0) return failure(`${name}: the glTF file has no triangle meshes`);
  return { ok: true, value: { kind: 'arrays', name, positions: Float64Array.from(positions), indices: Uint32Array.from(indices) } };
}
