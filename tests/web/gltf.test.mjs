// The glTF guard (web/src/meshFiles.ts selfContainedGltf): a glTF must not make the page fetch
// anything, so any buffer URI other than data: is refused, and materials, textures, images and
// samplers are dropped before three.js sees the file.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { selfContainedGltf } from '../../build/web-tests/meshFiles.js';

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
const { payloadFromFile, MAX_GLTF_VERTICES } = await import('../../build/web-tests/meshFiles.js');

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
