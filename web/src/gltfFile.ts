// glTF / GLB on the page: checked so that it cannot make the page fetch anything or fill the
// tab's memory, read by three.js's loader, and turned into one triangle soup in world
// coordinates, the way a glTF viewer shows the file's default scene: node transforms, GPU
// instances (EXT_mesh_gpu_instancing), morph target weights and skins applied. What the page
// leaves out (points and lines, other scenes) is said, never dropped without a word.
import { InstancedMesh, Line, LoadingManager, Matrix4, Mesh, Points, Vector3, type BufferGeometry, type Object3D } from 'three';
import { failure, isRecord, type Checked } from './params.ts';
import type { MeshPayload } from './protocol.ts';

// Each mesh's own label, written into its extras by selfContainedGltf: the loader copies
// extras to every object made of the mesh, while three.js makes names unique ("Shell_1"),
// numbers the copies placed by several nodes ("Shell_instance_0"), and keeps its associations
// for the last scene loaded only.
const LABEL_KEY = 'flatfacetLabel';

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
  const tree = nodeTreeProblem(json.nodes);
  if (tree) return failure(`${name}: ${tree}`);
  for (const key of ['materials', 'textures', 'images', 'samplers']) delete json[key];
  if (Array.isArray(json.meshes)) {
    json.meshes.forEach((mesh: unknown, index: number) => {
      if (!isRecord(mesh)) return;
      if (Array.isArray(mesh.primitives)) for (const primitive of mesh.primitives as unknown[]) if (isRecord(primitive)) delete primitive.material;
      const named = typeof mesh.name === 'string' && mesh.name !== '';
      mesh.extras = { [LABEL_KEY]: named ? `mesh "${(mesh.name as string).slice(0, 40)}"` : `mesh ${index}` };
    });
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

// glTF nodes form trees: each node has at most one parent and none is its own ancestor.
// three.js's loader recurses through `children` without a guard (a cycle overflowed its stack),
// and a node listed under two parents is placed under one of them only.
export function nodeTreeProblem(nodes: unknown): string | null {
  if (nodes === undefined) return null;
  if (!Array.isArray(nodes)) return 'the glTF file\'s "nodes" is not a list';
  const parent = new Array<number>(nodes.length).fill(-1);
  for (let n = 0; n < nodes.length; n++) {
    const node: unknown = nodes[n];
    const children = isRecord(node) ? node.children : undefined;
    if (children === undefined) continue;
    if (!Array.isArray(children)) return `node ${n}'s children are not a list`;
    for (const child of children as unknown[]) {
      if (!Number.isInteger(child) || (child as number) < 0 || (child as number) >= nodes.length) return `node ${n} names a child ${String(child).slice(0, 20)} that is not one of its ${nodes.length} nodes`;
      const c = child as number;
      if (parent[c] !== -1) return `node ${c} is a child of both node ${parent[c]} and node ${n} (a glTF node has one parent)`;
      parent[c] = n;
    }
  }
  // One parent each: walking up from every node either ends at a root or comes back round.
  const walkedFrom = new Array<number>(nodes.length).fill(-1);
  for (let start = 0; start < nodes.length; start++) {
    for (let n = start; n !== -1; n = parent[n]!) {
      if (walkedFrom[n] === start) return `node ${n} is its own ancestor (the glTF file's node tree has a cycle)`;
      if (walkedFrom[n] !== -1) break; // walked before, from another start: no cycle above
      walkedFrom[n] = start;
    }
  }
  return null;
}

// The vertices of `object` (its morph targets and skin applied, as three.js draws it) placed
// by `matrix`, appended to `positions`.
function placeVertices(object: Mesh, count: number, matrix: Matrix4, positions: number[]): void {
  const point = new Vector3();
  for (let i = 0; i < count; i++) {
    object.getVertexPosition(i, point).applyMatrix4(matrix);
    positions.push(point.x, point.y, point.z);
  }
}

// A mesh as the file names it (LABEL_KEY).
function meshLabel(object: Object3D): string {
  const label: unknown = object.userData[LABEL_KEY];
  return typeof label === 'string' ? label : `mesh "${object.name.slice(0, 40)}"`;
}

function sceneHasTriangles(scene: Object3D): boolean {
  let found = false;
  scene.traverse((object) => {
    if (object instanceof Mesh) found = true;
  });
  return found;
}

const plural = (count: number, word: string, words = `${word}s`): string => `${count.toLocaleString('en-US')} ${count === 1 ? word : words}`;

export async function gltfPayload(name: string, bytes: Uint8Array): Promise<Checked<MeshPayload>> {
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
  let scenes: Object3D[] = [];
  try {
    const gltf = await new GLTFLoader(manager).parseAsync(input.value, '');
    scene = gltf.scene;
    scenes = gltf.scenes ?? [];
  } catch (error) {
    const reason = error instanceof Error ? error.message : String(error);
    return failure(`${name}: not a readable glTF file (${reason.replace(/^THREE\.GLTFLoader: /, '').slice(0, 160)})`);
  }
  // No scene (valid glTF: meshes placed by none, or "scene" naming one that is not there).
  if (!scene) return failure(`${name}: the glTF file has no scene that places its meshes`);
  scene.updateMatrixWorld(true);
  const positions: number[] = [];
  const indices: number[] = [];
  const read: string[] = [];
  const instanced: string[] = [];
  const morphed: string[] = [];
  const skinned: string[] = [];
  const cutShort: string[] = [];
  let pointsAndLines = 0;
  let problem: string | null = null;
  const placed = new Matrix4();
  const instance = new Matrix4();
  scene.traverse((object) => {
    if (problem) return;
    // Points and lines (LineSegments and LineLoop are Lines) make no panels.
    if (object instanceof Points || object instanceof Line) {
      pointsAndLines += 1;
      return;
    }
    if (!(object instanceof Mesh)) return;
    const geometry = object.geometry as BufferGeometry;
    const position = geometry.getAttribute('position');
    if (!position) return;
    const what = meshLabel(object);
    // Three floats per vertex (or small integers, quantized); anything else is misread.
    if (position.itemSize !== 3 || position.array instanceof Uint32Array || position.array instanceof Int32Array) {
      problem = `${what} has positions that are not 3 numbers per vertex of a type glTF allows`;
      return;
    }
    const copies = object instanceof InstancedMesh ? object.count : 1;
    if (positions.length / 3 + position.count * copies > MAX_GLTF_VERTICES) {
      problem = `the glTF file places more than ${MAX_GLTF_VERTICES.toLocaleString('en-US')} vertices (its meshes, with every node and instance that places them)`;
      return;
    }
    if (object instanceof InstancedMesh) instanced.push(`${what} ${plural(copies, 'time')}`);
    if (object.morphTargetInfluences?.some((weight) => weight !== 0)) morphed.push(what);
    if ('isSkinnedMesh' in object && object.isSkinnedMesh) skinned.push(what);
    const index = geometry.getIndex();
    const count = index ? index.count : position.count;
    if (count % 3 !== 0) cutShort.push(`${what} (${index ? plural(count % 3, 'index', 'indices') : plural(count % 3, 'vertex', 'vertices')})`);
    // Every index of a whole triangle checked once: past its own vertices it would land on the
    // next mesh's.
    const used = count - (count % 3);
    for (let i = 0; i < used; i++) {
      const v = index ? index.getX(i) : i;
      if (!(v >= 0 && v < position.count)) {
        problem = `${what} has an index ${v} past its ${position.count} vertices`;
        return;
      }
    }
    for (let copy = 0; copy < copies; copy++) {
      placed.copy(object.matrixWorld);
      if (object instanceof InstancedMesh) {
        object.getMatrixAt(copy, instance);
        placed.multiply(instance);
      }
      const base = positions.length / 3;
      placeVertices(object, position.count, placed, positions);
      for (let i = 0; i < used; i += 3) {
        for (let corner = 0; corner < 3; corner++) indices.push(base + (index ? index.getX(i + corner) : i + corner));
      }
    }
  });
  if (problem) return failure(`${name}: ${problem}`);
  if (indices.length === 0) {
    return failure(`${name}: the glTF file has no triangle meshes${pointsAndLines > 0 ? ` in its default scene (only points or lines)` : ''}`);
  }
  if (instanced.length > 0) read.push(`placed ${instanced.join(', ')} (GPU instancing)`);
  if (morphed.length > 0) read.push(`${morphed.join(', ')} shaped by ${morphed.length === 1 ? 'its' : 'their'} morph target weights`);
  if (skinned.length > 0) read.push(`${skinned.join(', ')} posed by ${skinned.length === 1 ? 'its' : 'their'} skin as the file's nodes stand`);
  if (pointsAndLines > 0) read.push(`left out ${plural(pointsAndLines, 'point or line primitive')} (only triangles make panels)`);
  if (cutShort.length > 0) read.push(`left out the last indices of ${cutShort.join(', ')}, too few for a triangle`);
  const others = scenes.filter((other) => other !== scene && sceneHasTriangles(other)).length;
  if (others > 0) read.push(`read the default scene; left out ${plural(others, 'other scene')} with meshes`);
  return { ok: true, value: { kind: 'arrays', name, positions: Float64Array.from(positions), indices: Uint32Array.from(indices), ...(read.length > 0 ? { read } : {}) } };
}
