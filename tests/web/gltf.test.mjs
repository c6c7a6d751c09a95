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
