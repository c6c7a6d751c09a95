// Turns what the designer opens into something the worker loads. OBJ, OFF, STL and PLY go to
// the core's own readers as bytes (so the page and the command line read a file identically);
// glTF/GLB goes through three.js and arrives as one triangle soup in world coordinates; Rhino
// .3dm files become NURBS surfaces for the core's tessellation (web/src/rhino/).
import { LoadingManager, Mesh, Vector3, type BufferGeometry, type Object3D } from 'three';
import type { Example } from './examples.ts';
import { failure, type Checked } from './params.ts';
import type { MeshPayload } from './protocol.ts';
import { rhinoPayload } from './rhino/rhinoOpen.ts';

const GLTF_EXTENSIONS = ['gltf', 'glb'];
export const ACCEPTED_EXTENSIONS = ['obj', 'off', 'stl', 'ply', ...GLTF_EXTENSIONS, '3dm'];

export function extensionOf(name: string): string {
  const dot = name.lastIndexOf('.');
  return dot < 0 ? '' : name.slice(dot + 1).toLowerCase();
}

export async function payloadFromFile(name: string, bytes: Uint8Array): Promise<Checked<MeshPayload>> {
  // The page's own readers (glTF through three.js, Rhino through rhino3dm) meet hostile files:
  // whatever one throws is a refusal of the file, never an open left "loading" for good.
  const onPage = async (read: () => Promise<Checked<MeshPayload>>, kind: string): Promise<Checked<MeshPayload>> => {
    try {
      return await read();
    } catch (error) {
      const reason = error instanceof Error ? error.message : String(error);
      return failure(`${name}: not a readable ${kind} file (${reason.slice(0, 160)})`);
    }
  };
  if (GLTF_EXTENSIONS.includes(extensionOf(name))) return onPage(() => gltfPayload(name, bytes), 'glTF');
  // Rhino: parsed on the page by rhino3dm, itself loaded on the first .3dm (web/src/rhino/).
  if (extensionOf(name) === '3dm') return onPage(() => rhinoPayload(name, bytes), 'Rhino');
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

// The example files this site ships (examples/index.json, written by
// web/scripts/copy_examples.mjs at build time). Without it, or without the shared meshes at
// build time, none: the page then offers only the generated examples.
export async function availableExampleFiles(): Promise<Set<string>> {
  try {
    const response = await fetch(new URL('examples/index.json', document.baseURI));
    if (!response.ok) return new Set();
    const list: unknown = await response.json();
    const files = typeof list === 'object' && list !== null && 'files' in list ? (list as { files: unknown }).files : null;
    return new Set(Array.isArray(files) ? files.filter((file): file is string => typeof file === 'string') : []);
  } catch {
    return new Set();
  }
}

export async function payloadFromExample(example: Example): Promise<Checked<MeshPayload>> {
  if (example.kind === 'shape') return { ok: true, value: { kind: 'shape', name: example.shape, triangles: example.triangles } };
  const bytes = await fetchExampleBytes(example.file);
  if (!bytes.ok) return bytes;
  return { ok: true, value: { kind: 'bytes', name: example.file, bytes: bytes.value } };
}

function isRecord(value: unknown): value is Record<string, unknown> {
  return typeof value === 'object' && value !== null && !Array.isArray(value);
}

// The vertices a glTF may place (all meshes, with every node that places them): well past what
// the core prepares (2 million triangles), short of what fills the tab's memory.
export const MAX_GLTF_VERTICES = 10_000_000;
const GLB_MAGIC = 0x46546c67; // "glTF"
const CHUNK_JSON = 0x4e4f534a;

// A glTF from a file, a share link or the stored session must not make the page fetch
// anything: three.js's loader resolves every `uri` (relative, or absolute https), so the JSON
// is checked and cut down before the loader sees it. Buffers must be embedded (`data:` URIs,
// or the GLB's own binary chunk); materials, textures, images and samplers are dropped, since
// only the geometry is used. Returns what the loader may parse, or why not.
export function selfContainedGltf(name: string, bytes: Uint8Array): Checked<ArrayBuffer | string> {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const binary = bytes.length >= 20 && view.getUint32(0, true) === GLB_MAGIC;
  let jsonText: string;
  let rest: Uint8Array = new Uint8Array(0);
  try {
    if (binary) {
      const jsonLength = view.getUint32(12, true);
      if (view.getUint32(16, true) !== CHUNK_JSON || 20 + jsonLength > bytes.length) return failure(`${name}: not a readable glTF file (its JSON chunk is damaged)`);
      jsonText = new TextDecoder('utf-8', { fatal: true }).decode(bytes.subarray(20, 20 + jsonLength));
      rest = bytes.subarray(20 + jsonLength);
    } else {
      jsonText = new TextDecoder('utf-8', { fatal: true }).decode(bytes);
    }
  } catch {
    return failure(`${name}: not a readable glTF file (its JSON is not UTF-8 text)`);
  }
  let json: unknown;
  try {
    json = JSON.parse(jsonText);
  } catch {
    return failure(`${name}: not a readable glTF file (its JSON cannot be parsed)`);
  }
  if (!isRecord(json)) return failure(`${name}: not a readable glTF file (no JSON object)`);
  const buffers = Array.isArray(json.buffers) ? (json.buffers as unknown[]) : [];
  for (const buffer of buffers) {
    const uri = isRecord(buffer) ? buffer.uri : undefined;
    if (uri === undefined) continue;
    if (typeof uri !== 'string' || !uri.startsWith('data:')) {
      const shown = String(uri).slice(0, 60).replace(/[\u0000-\u001f]/g, '');
      return failure(`${name} refers to a separate file ("${shown}"), which this page does not fetch: export a .glb, or a .gltf with its data embedded`);
    }
  }
  // An accessor without data (zeros, unless sparse) costs its count, not the file's bytes: a
  // 600-byte file asking for 30 million vertices filled 2.6 GB. Those with data are bounded by it.
  const accessors = Array.isArray(json.accessors) ? (json.accessors as unknown[]) : [];
  for (let a = 0; a < accessors.length; a++) {
    const accessor = accessors[a];
    if (!isRecord(accessor) || accessor.bufferView !== undefined) continue;
    const count = accessor.count;
    if (typeof count === 'number' && count > MAX_GLTF_VERTICES) {
      return failure(`${name}: accessor ${a} asks for ${count.toLocaleString('en-US')} elements with no data, more than the ${MAX_GLTF_VERTICES.toLocaleString('en-US')} this page reads`);
    }
  }
  for (const key of ['materials', 'textures', 'images', 'samplers']) delete json[key];
  if (Array.isArray(json.meshes)) {
    for (const mesh of json.meshes as unknown[]) {
      if (!isRecord(mesh) || !Array.isArray(mesh.primitives)) continue;
      for (const primitive of mesh.primitives as unknown[]) if (isRecord(primitive)) delete primitive.material;
    }
  }
  const cleanJson = JSON.stringify(json);
  if (!binary) return { ok: true, value: cleanJson };
  // The GLB again, with the cleaned JSON chunk (padded with spaces to 4 bytes) and the other
  // chunks as they were.
  let jsonBytes = new TextEncoder().encode(cleanJson);
  const padded = new Uint8Array(Math.ceil(jsonBytes.length / 4) * 4).fill(0x20);
  padded.set(jsonBytes);
  jsonBytes = padded;
  const out = new Uint8Array(20 + jsonBytes.length + rest.length);
  const outView = new DataView(out.buffer);
  outView.setUint32(0, GLB_MAGIC, true);
  outView.setUint32(4, view.getUint32(4, true), true);
  outView.setUint32(8, out.length, true);
  outView.setUint32(12, jsonBytes.length, true);
  outView.setUint32(16, CHUNK_JSON, true);
  out.set(jsonBytes, 20);
  out.set(rest, 20 + jsonBytes.length);
  return { ok: true, value: out.buffer };
}

async function gltfPayload(name: string, bytes: Uint8Array): Promise<Checked<MeshPayload>> {
  const input = selfContainedGltf(name, bytes);
  if (!input.ok) return input;
  // Loaded on demand: most designers never open glTF, and the loader is large.
  const { GLTFLoader } = await import('three/examples/jsm/loaders/GLTFLoader.js');
  // Belt and braces: whatever the check above missed still cannot leave the page.
  const manager = new LoadingManager();
  manager.setURLModifier((url) => {
    if (!url.startsWith('data:')) throw new Error('a glTF may not refer to separate files');
    return url;
  });
  let scene: Object3D | undefined;
  try {
    scene = (await new GLTFLoader(manager).parseAsync(input.value, '')).scene;
  } catch (error) {
    const reason = error instanceof Error ? error.message : String(error);
    return failure(`${name}: not a readable glTF file (${reason.replace(/^THREE\.GLTFLoader: /, '').slice(0, 160)})`);
  }
  // No scene (valid glTF: meshes placed by none, or "scene" naming one that is not there).
  if (!scene) return failure(`${name}: the glTF file has no scene that places its meshes`);
  scene.updateMatrixWorld(true);
  const positions: number[] = [];
  const indices: number[] = [];
  const point = new Vector3();
  let problem: string | null = null;
  scene.traverse((object) => {
    if (problem || !(object instanceof Mesh)) return;
    const geometry = object.geometry as BufferGeometry;
    const position = geometry.getAttribute('position');
    if (!position) return;
    const what = `mesh "${String(object.name || geometry.name || 'unnamed').slice(0, 40)}"`;
    // Three floats per vertex (or small integers, quantized); anything else is misread.
    if (position.itemSize !== 3 || position.array instanceof Uint32Array || position.array instanceof Int32Array) {
      problem = `${what} has positions that are not 3 numbers per vertex of a type glTF allows`;
      return;
    }
    if (positions.length / 3 + position.count > MAX_GLTF_VERTICES) {
      problem = `the glTF file places more than ${MAX_GLTF_VERTICES.toLocaleString('en-US')} vertices (its meshes, with every node that places them)`;
      return;
    }
    const base = positions.length / 3;
    for (let i = 0; i < position.count; i++) {
      point.fromBufferAttribute(position, i).applyMatrix4(object.matrixWorld);
      positions.push(point.x, point.y, point.z);
    }
    const index = geometry.getIndex();
    const count = index ? index.count : position.count;
    for (let i = 0; i + 2 < count; i += 3) {
      for (let corner = 0; corner < 3; corner++) {
        const v = index ? index.getX(i + corner) : i + corner;
        // Past its own vertices an index would land on the next mesh's: refused, not joined.
        if (!(v >= 0 && v < position.count)) {
          problem = `${what} has an index ${v} past its ${position.count} vertices`;
          return;
        }
        indices.push(base + v);
      }
    }
  });
  if (problem) return failure(`${name}: ${problem}`);
  if (indices.length === 0) return failure(`${name}: the glTF file has no triangle meshes`);
  return { ok: true, value: { kind: 'arrays', name, positions: Float64Array.from(positions), indices: Uint32Array.from(indices) } };
}
