// The glTF guard (web/src/gltfFile.ts selfContainedGltf): a glTF must not make the page fetch
// anything, so any buffer URI other than data: is refused, and materials, textures, images and
// samplers are dropped before three.js sees the file.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { selfContainedGltf } from '../../build/web-tests/gltfFile.js';

const base = {
  asset: { version: '2.0' },
  meshes: [{ primitives: [{ attributes: { POSITION: 0 }, material: 0 }] }],
  materials: [{ pbrMetallicRoughness: { baseColorTexture: { index: 0 } } }],
  textures: [{ source: 0, sampler: 0 }],
  images: [{ uri: 'https://example.invalid/texture.png' }],
  samplers: [{}],
};
const text = (json) => new TextEncoder().encode(JSON.stringify(json));

function glb(json, bin = new Uint8Array(8)) {
  let jsonBytes = text(json);
  const padded = new Uint8Array(Math.ceil(jsonBytes.length / 4) * 4).fill(0x20);
  padded.set(jsonBytes);
  jsonBytes = padded;
  const out = new Uint8Array(12 + 8 + jsonBytes.length + 8 + bin.length);
  const view = new DataView(out.buffer);
  view.setUint32(0, 0x46546c67, true);
  view.setUint32(4, 2, true);
  view.setUint32(8, out.length, true);
  view.setUint32(12, jsonBytes.length, true);
  view.setUint32(16, 0x4e4f534a, true);
  out.set(jsonBytes, 20);
  view.setUint32(20 + jsonBytes.length, bin.length, true);
  view.setUint32(24 + jsonBytes.length, 0x004e4942, true);
  out.set(bin, 28 + jsonBytes.length);
  return out;
}

test('external buffer URIs are refused with a message naming them', () => {
  for (const uri of ['https://example.invalid/mesh.bin', 'mesh.bin', '//evil.example/x', 'blob:x', 'file:///etc/passwd']) {
    const checked = selfContainedGltf('roof.gltf', text({ ...base, buffers: [{ uri, byteLength: 8 }] }));
    assert.equal(checked.ok, false, uri);
    assert.match(checked.message, /roof\.gltf refers to a separate file .*does not fetch/);
  }
  const inGlb = selfContainedGltf('roof.glb', glb({ ...base, buffers: [{ byteLength: 8 }, { uri: 'https://example.invalid/2.bin', byteLength: 8 }] }));
  assert.equal(inGlb.ok, false);
});

test('embedded data passes, without materials, textures, images or samplers', () => {
  const checked = selfContainedGltf('roof.gltf', text({ ...base, buffers: [{ uri: 'data:application/octet-stream;base64,AAAAAAAAAAA=', byteLength: 8 }] }));
  assert.ok(checked.ok, checked.message);
  const json = JSON.parse(checked.value);
  for (const key of ['materials', 'textures', 'images', 'samplers']) assert.equal(json[key], undefined, key);
  assert.equal(json.meshes[0].primitives[0].material, undefined);
  assert.equal(json.buffers.length, 1);
});

test('a GLB is rebuilt with the cleaned JSON and its binary chunk intact', () => {
  const bin = Uint8Array.from({ length: 16 }, (_, i) => i * 3);
  const checked = selfContainedGltf('roof.glb', glb({ ...base, buffers: [{ byteLength: 16 }] }, bin));
  assert.ok(checked.ok, checked.message);
  const out = new Uint8Array(checked.value);
  const view = new DataView(out.buffer);
  assert.equal(view.getUint32(0, true), 0x46546c67);
  assert.equal(view.getUint32(8, true), out.length);
  const jsonLength = view.getUint32(12, true);
  assert.equal(jsonLength % 4, 0);
  const json = JSON.parse(new TextDecoder().decode(out.subarray(20, 20 + jsonLength)));
  assert.equal(json.images, undefined);
  assert.equal(view.getUint32(20 + jsonLength, true), 16);
  assert.deepEqual(out.subarray(28 + jsonLength), bin);
});

test('broken glTF gives a message, not an exception', () => {
  for (const bytes of [text('not json'), new Uint8Array([0xff, 0xfe, 0x00]), glb(base).subarray(0, 24)]) {
    const checked = selfContainedGltf('x.gltf', bytes);
    assert.equal(checked.ok, false);
    assert.match(checked.message, /^x\.gltf: not a readable glTF file/);
  }
});

// ---- the page's reading of a glTF (payloadFromFile, three.js's loader), after a fuzzing review

// three.js's loader reports progress with a ProgressEvent, which Node lacks.
globalThis.ProgressEvent ??= class ProgressEvent extends Event {};
const { payloadFromFile } = await import('../../build/web-tests/meshFiles.js');
const { MAX_GLTF_VERTICES } = await import('../../build/web-tests/gltfFile.js');

// A GLB of triangles: `meshes` lists each mesh's positions and (optional) 16-bit indices.
function meshesGlb(meshes, { scenes = true, positionType = 'VEC3' } = {}) {
  const chunks = [];
  const bufferViews = [];
  const accessors = [];
  let offset = 0;
  const add = (bytes) => {
    const padded = new Uint8Array(Math.ceil(bytes.length / 4) * 4);
    padded.set(bytes);
    bufferViews.push({ buffer: 0, byteOffset: offset, byteLength: bytes.length });
    chunks.push(padded);
    offset += padded.length;
    return bufferViews.length - 1;
  };
  const jsonMeshes = meshes.map(({ positions, indices }) => {
    const view = add(new Uint8Array(new Float32Array(positions).buffer));
    accessors.push({ bufferView: view, componentType: 5126, count: positions.length / (positionType === 'VEC2' ? 2 : 3), type: positionType });
    const primitive = { attributes: { POSITION: accessors.length - 1 } };
    if (indices) {
      accessors.push({ bufferView: add(new Uint8Array(new Uint16Array(indices).buffer)), componentType: 5123, count: indices.length, type: 'SCALAR' });
      primitive.indices = accessors.length - 1;
    }
    return { primitives: [primitive] };
  });
  const bin = new Uint8Array(offset);
  let at = 0;
  for (const chunk of chunks) bin.set(chunk, at), (at += chunk.length);
  const nodes = meshes.map((_, i) => ({ mesh: i }));
  const json = { asset: { version: '2.0' }, nodes, meshes: jsonMeshes, accessors, bufferViews, buffers: [{ byteLength: bin.length }], ...(scenes ? { scene: 0, scenes: [{ nodes: nodes.map((_, i) => i) }] } : {}) };
  return glb(json, bin);
}
const triangle = { positions: [0, 0, 0, 1, 0, 0, 0, 1, 0], indices: [0, 1, 2] };

test('a glTF whose triangles fit is read; one that would mislead or overwhelm the page is refused by name', async () => {
  const two = await payloadFromFile('two.glb', meshesGlb([triangle, { ...triangle, positions: triangle.positions.map((x) => x + 5) }]));
  assert.ok(two.ok, two.message);
  assert.deepEqual([...two.value.indices], [0, 1, 2, 3, 4, 5]);
  // No scene (valid glTF): it threw out of the loader's result and left the open "loading".
  const noScene = await payloadFromFile('bare.glb', meshesGlb([triangle], { scenes: false }));
  assert.equal(noScene.ok, false);
  assert.match(noScene.message, /bare\.glb: the glTF file has no scene/);
  // An index past its own mesh's vertices landed on the next mesh's, without a word.
  const past = await payloadFromFile('past.glb', meshesGlb([{ ...triangle, indices: [0, 1, 5] }, triangle]));
  assert.equal(past.ok, false);
  assert.match(past.message, /has an index 5 past its 3 vertices/);
  // Two numbers per position were read as three, across vertices.
  const flat = await payloadFromFile('flat.glb', meshesGlb([{ positions: [0, 0, 1, 0, 0, 1], indices: [0, 1, 2] }], { positionType: 'VEC2' }));
  assert.equal(flat.ok, false);
  assert.match(flat.message, /not 3 numbers per vertex/);
  // Thirty million vertices of zeros asked by 600 bytes filled 2.6 GB.
  const json = { asset: { version: '2.0' }, scene: 0, scenes: [{ nodes: [0] }], nodes: [{ mesh: 0 }], meshes: [{ primitives: [{ attributes: { POSITION: 0 } }] }], accessors: [{ componentType: 5126, count: 3e7, type: 'VEC3' }] };
  const zeros = await payloadFromFile('zeros.gltf', text(json));
  assert.equal(zeros.ok, false);
  assert.match(zeros.message, new RegExp(`accessor 0 asks for 30,000,000 elements with no data, more than the ${MAX_GLTF_VERTICES.toLocaleString('en-US')}`));
});

// ---- what a glTF viewer shows is what the page reads; what it leaves out is said

// A GLB from a JSON whose accessors each name one of `data` (typed arrays, one buffer view
// each) by `view`; the buffer views and the buffer are added here.
function dataGlb(json, data) {
  const bufferViews = [];
  let offset = 0;
  const parts = data.map((array) => {
    const bytes = new Uint8Array(array.buffer, array.byteOffset, array.byteLength);
    bufferViews.push({ buffer: 0, byteOffset: offset, byteLength: bytes.length });
    const padded = new Uint8Array(Math.ceil(bytes.length / 4) * 4);
    padded.set(bytes);
    offset += padded.length;
    return padded;
  });
  const bin = new Uint8Array(offset);
  let at = 0;
  for (const part of parts) bin.set(part, at), (at += part.length);
  const accessors = json.accessors.map(({ view, ...rest }) => ({ bufferView: view, ...rest }));
  return glb({ asset: { version: '2.0' }, scene: 0, ...json, accessors, bufferViews, buffers: [{ byteLength: bin.length }] }, bin);
}
const f32 = (values) => new Float32Array(values);
const vec3 = (view, count, extra = {}) => ({ view, componentType: 5126, count, type: 'VEC3', ...extra });
const xs = (payload) => [...payload.value.positions].filter((_, i) => i % 3 === 0);

test('GPU instances are each placed, and said', async () => {
  // EXT_mesh_gpu_instancing: three instances of one triangle, 10 apart along x. Before, the
  // page placed the triangle once, at the node.
  const json = {
    extensionsUsed: ['EXT_mesh_gpu_instancing'],
    scenes: [{ nodes: [0] }],
    nodes: [{ mesh: 0, name: 'Tiles', extensions: { EXT_mesh_gpu_instancing: { attributes: { TRANSLATION: 1 } } } }],
    meshes: [{ name: 'Tile', primitives: [{ attributes: { POSITION: 0 } }] }],
    accessors: [vec3(0, 3, { min: [0, 0, 0], max: [1, 1, 0] }), vec3(1, 3)],
  };
  const read = await payloadFromFile('tiles.glb', dataGlb(json, [f32([0, 0, 0, 1, 0, 0, 0, 1, 0]), f32([0, 0, 0, 10, 0, 0, 20, 0, 0])]));
  assert.ok(read.ok, read.message);
  assert.equal(read.value.indices.length, 9);
  assert.deepEqual(xs(read), [0, 1, 0, 10, 11, 10, 20, 21, 20]);
  assert.deepEqual([...read.value.indices], [0, 1, 2, 3, 4, 5, 6, 7, 8]);
  assert.equal(read.value.read.length, 1);
  assert.match(read.value.read[0], /placed mesh "Tile.*" 3 times \(GPU instancing\)/);
});

test('points and lines beside the triangles are left out and said; only lines are refused by name', async () => {
  const json = {
    scenes: [{ nodes: [0, 1] }],
    nodes: [{ mesh: 0 }, { mesh: 1 }],
    meshes: [{ primitives: [{ attributes: { POSITION: 0 } }] }, { primitives: [{ attributes: { POSITION: 0 }, mode: 1 }, { attributes: { POSITION: 0 }, mode: 0 }] }],
    accessors: [vec3(0, 3, { min: [0, 0, 0], max: [1, 1, 0] })],
  };
  const data = [f32([0, 0, 0, 1, 0, 0, 0, 1, 0])];
  const mixed = await payloadFromFile('mixed.glb', dataGlb(json, data));
  assert.ok(mixed.ok, mixed.message);
  assert.equal(mixed.value.indices.length, 3);
  assert.deepEqual(mixed.value.read, ['left out 2 point or line primitives (only triangles make panels)']);
  const lines = await payloadFromFile('lines.glb', dataGlb({ ...json, scenes: [{ nodes: [1] }] }, data));
  assert.equal(lines.ok, false);
  assert.match(lines.message, /lines\.glb: the glTF file has no triangle meshes in its default scene \(only points or lines\)/);
});

test('morph target weights shape the mesh, as a viewer shows it', async () => {
  // One target moving every vertex 2 along x, at weight 0.5 on the mesh: 1 along x. Before,
  // the page read the base shape without a word.
  const json = {
    scenes: [{ nodes: [0] }],
    nodes: [{ mesh: 0 }],
    meshes: [{ name: 'Roof', weights: [0.5], primitives: [{ attributes: { POSITION: 0 }, targets: [{ POSITION: 1 }] }] }],
    accessors: [vec3(0, 3, { min: [0, 0, 0], max: [1, 1, 0] }), vec3(1, 3, { min: [2, 0, 0], max: [2, 0, 0] })],
  };
  const read = await payloadFromFile('morph.glb', dataGlb(json, [f32([0, 0, 0, 1, 0, 0, 0, 1, 0]), f32([2, 0, 0, 2, 0, 0, 2, 0, 0])]));
  assert.ok(read.ok, read.message);
  assert.deepEqual(xs(read), [1, 2, 1]);
  assert.match(read.value.read.join('; '), /mesh "Roof" shaped by its morph target weights/);
  // At weight 0 the base shape is what shows, and nothing is said.
  json.meshes[0].weights = [0];
  const rest = await payloadFromFile('rest.glb', dataGlb(json, [f32([0, 0, 0, 1, 0, 0, 0, 1, 0]), f32([2, 0, 0, 2, 0, 0, 2, 0, 0])]));
  assert.ok(rest.ok, rest.message);
  assert.deepEqual(xs(rest), [0, 1, 0]);
  assert.equal(rest.value.read, undefined);
});

test('a skinned mesh is read posed by its skeleton', async () => {
  // Every vertex bound to one joint that the file moves 5 along z.
  const json = {
    scenes: [{ nodes: [0, 1] }],
    nodes: [{ mesh: 0, skin: 0 }, { name: 'bone', translation: [0, 0, 5] }],
    skins: [{ joints: [1] }],
    meshes: [{ primitives: [{ attributes: { POSITION: 0, JOINTS_0: 1, WEIGHTS_0: 2 } }] }],
    accessors: [vec3(0, 3, { min: [0, 0, 0], max: [1, 1, 0] }), { view: 1, componentType: 5121, count: 3, type: 'VEC4' }, { view: 2, componentType: 5126, count: 3, type: 'VEC4' }],
  };
  const read = await payloadFromFile('skin.glb', dataGlb(json, [f32([0, 0, 0, 1, 0, 0, 0, 1, 0]), new Uint8Array(12), f32([1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0])]));
  assert.ok(read.ok, read.message);
  assert.deepEqual([...read.value.positions].filter((_, i) => i % 3 === 2), [5, 5, 5]);
  assert.match(read.value.read.join('; '), /posed by its skin/);
});

test('other scenes and a last partial triangle are said', async () => {
  const json = {
    scenes: [{ nodes: [0] }, { nodes: [1] }, { nodes: [] }],
    nodes: [{ mesh: 0 }, { mesh: 0 }],
    meshes: [{ name: 'Shell', primitives: [{ attributes: { POSITION: 0 }, indices: 1 }] }],
    accessors: [vec3(0, 3, { min: [0, 0, 0], max: [1, 1, 0] }), { view: 1, componentType: 5123, count: 5, type: 'SCALAR' }],
  };
  const read = await payloadFromFile('scenes.glb', dataGlb(json, [f32([0, 0, 0, 1, 0, 0, 0, 1, 0]), new Uint16Array([0, 1, 2, 2, 1])]));
  assert.ok(read.ok, read.message);
  assert.deepEqual([...read.value.indices], [0, 1, 2]);
  assert.deepEqual(read.value.read, ['left out the last indices of mesh "Shell" (2 indices), too few for a triangle', 'read the default scene; left out 1 other scene with meshes']);
});

test('a node tree with a cycle or a node under two parents is refused by name', async () => {
  const mesh = { meshes: [{ primitives: [{ attributes: { POSITION: 0 } }] }], accessors: [vec3(0, 3, { min: [0, 0, 0], max: [1, 1, 0] })] };
  const data = [f32([0, 0, 0, 1, 0, 0, 0, 1, 0])];
  // Before: "Maximum call stack size exceeded" from three.js's loader.
  const cycle = await payloadFromFile('cycle.glb', dataGlb({ ...mesh, scenes: [{ nodes: [0] }], nodes: [{ mesh: 0, children: [1] }, { children: [2] }, { children: [0] }] }, data));
  assert.equal(cycle.ok, false);
  assert.match(cycle.message, /cycle\.glb: node \d is its own ancestor \(the glTF file's node tree has a cycle\)/);
  const self = await payloadFromFile('self.glb', dataGlb({ ...mesh, scenes: [{ nodes: [0] }], nodes: [{ mesh: 0, children: [0] }] }, data));
  assert.equal(self.ok, false);
  assert.match(self.message, /node 0 is its own ancestor/);
  const two = await payloadFromFile('two.glb', dataGlb({ ...mesh, scenes: [{ nodes: [0, 1] }], nodes: [{ children: [2] }, { children: [2] }, { mesh: 0 }] }, data));
  assert.equal(two.ok, false);
  assert.match(two.message, /node 2 is a child of both node 0 and node 1/);
  const stray = await payloadFromFile('stray.glb', dataGlb({ ...mesh, scenes: [{ nodes: [0] }], nodes: [{ mesh: 0, children: [7] }] }, data));
  assert.equal(stray.ok, false);
  assert.match(stray.message, /node 0 names a child 7 that is not one of its 1 nodes/);
  // A deep chain is fine.
  const nodes = Array.from({ length: 200 }, (_, i) => (i < 199 ? { children: [i + 1] } : { mesh: 0 }));
  const deep = await payloadFromFile('deep.glb', dataGlb({ ...mesh, scenes: [{ nodes: [0] }], nodes }, data));
  assert.ok(deep.ok, deep.message);
});
