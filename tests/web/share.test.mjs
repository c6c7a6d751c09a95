// Unit tests of the share-link codec (web/src/share.ts, compiled to build/web-tests by
// `npm run test:web`): round trips, and every kind of broken or hostile link we can think of
// gives a clear message instead of a crash or a half-applied design.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { zlibSync } from 'fflate';
import { decodeBase64url, encodeBase64url } from '../../build/web-tests/base64url.js';
import { DEFAULT_PARAMS, toRemeshParams, validateParams } from '../../build/web-tests/params.js';
import { decodeState, encodePayload, hashToState, LINK_LIMITS, MAX_HISTORY, stateToHash } from '../../build/web-tests/share.js';

const params = { ...DEFAULT_PARAMS, panels: 90, seed: 12345678901, weights: { euclidean: 1, l2: 0.5, l21: 2, boundary: 1 } };

// A hash from raw JSON (and optional file bytes), bypassing the encoder's own checks.
function hashOf(json, fileBytes = new Uint8Array(0), { compress = (b) => zlibSync(b) } = {}) {
  const text = new TextEncoder().encode(typeof json === 'string' ? json : JSON.stringify(json));
  const payload = new Uint8Array(4 + text.length + fileBytes.length);
  new DataView(payload.buffer).setUint32(0, text.length, true);
  payload.set(text, 4);
  payload.set(fileBytes, 4 + text.length);
  return `#v1=${encodeBase64url(compress(payload))}`;
}

function refused(hash, pattern) {
  const decoded = hashToState(hash);
  assert.equal(decoded.ok, false, `refused: ${hash.slice(0, 60)}`);
  assert.equal(typeof decoded.message, 'string');
  assert.ok(decoded.message.length > 10, 'a message that says something');
  if (pattern) assert.match(decoded.message, pattern);
}

test('base64url round-trips every length and byte value', () => {
  for (let length = 0; length < 70; length++) {
    const bytes = Uint8Array.from({ length }, (_, i) => (i * 37 + length * 11) % 256);
    const text = encodeBase64url(bytes);
    assert.match(text, /^[A-Za-z0-9_-]*$/);
    assert.deepEqual(decodeBase64url(text), bytes);
  }
  assert.equal(decodeBase64url('abc$'), null);
  assert.equal(decodeBase64url('a'), null, 'a length no encoder produces');
  assert.equal(decodeBase64url('ab=='), null, 'no padding in base64url links');
});

test('an example design round-trips through the hash', () => {
  const state = { mesh: { kind: 'example', id: 'groin_vault' }, params, history: [{ ...params, panels: 120 }] };
  const hash = stateToHash(state);
  assert.match(hash, /^#v1=[A-Za-z0-9_-]+$/);
  const decoded = hashToState(hash);
  assert.ok(decoded.ok, decoded.message);
  assert.deepEqual(decoded.value, state);
});

test('an uploaded mesh travels as its bytes, compressed', () => {
  const obj = new TextEncoder().encode('v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n'.repeat(2000));
  const state = { mesh: { kind: 'file', name: 'roof (v2).obj', bytes: obj }, params, history: [] };
  const hash = stateToHash(state);
  assert.ok(hash.length < obj.length / 10, `compressed (${hash.length} characters for ${obj.length} bytes)`);
  const decoded = hashToState(hash);
  assert.ok(decoded.ok, decoded.message);
  assert.equal(decoded.value.mesh.kind, 'file');
  assert.equal(decoded.value.mesh.name, 'roof (v2).obj');
  assert.deepEqual(decoded.value.mesh.bytes, obj);
  assert.deepEqual(decoded.value.params, params);
});

test('garbage, truncated and foreign links are refused with a message', () => {
  refused('#v1=!!!not-base64!!!', /characters/);
  refused('#v1=', /empty|short/);
  refused('#v1=AAAA', /damaged|short/);
  refused(`#v1=${encodeBase64url(new TextEncoder().encode('just some text, not compressed'))}`, /damaged/);
  const good = stateToHash({ mesh: { kind: 'example', id: 'saddle' }, params, history: [] });
  refused(good.slice(0, good.length - 6), /damaged/);
  refused('#hello', /not a Flatfacet share link/);
  refused('#v2=AAAA', /version 2/);
  refused('#v99999=AAAA', /version/);
});

test('a deflate bomb stops at the size cap', () => {
  const huge = new Uint8Array(40 * 1024 * 1024); // 40 MiB of zeros: about 40 KiB compressed
  const hash = `#v1=${encodeBase64url(zlibSync(huge, { level: 9 }))}`;
  assert.ok(hash.length < 200_000);
  const started = Date.now();
  refused(hash, /unpacks to more than/);
  assert.ok(Date.now() - started < 2000, 'stops early, does not inflate everything');
});

test('over-long links are refused before decoding', () => {
  refused(`#v1=${'A'.repeat(4 * 1024 * 1024)}`, /too long/);
});

test('wrong versions, types and ranges in the settings are refused', () => {
  const base = { v: 1, mesh: { example: 'saddle' }, params, history: [] };
  refused(hashOf({ ...base, v: 2 }), /version 2/);
  refused(hashOf({ ...base, v: '1' }), /no format version/);
  refused(hashOf('[1,2,3]'), /not an object/);
  refused(hashOf('{"v":1,'), /not readable/);
  refused(hashOf({ ...base, mesh: { example: 'eiffel_tower' } }), /unknown example/);
  refused(hashOf({ ...base, mesh: { example: 42 } }), /no mesh/);
  refused(hashOf({ ...base, mesh: null }), /no mesh/);
  refused(hashOf({ ...base, params: { ...params, panels: 'many' } }), /Panels must be a whole number/);
  refused(hashOf({ ...base, params: { ...params, panels: 0 } }), /Panels must be between/);
  refused(hashOf({ ...base, params: { ...params, panels: 1e9 } }), /Panels must be between/);
  refused(hashOf({ ...base, params: { ...params, panels: 10.5 } }), /whole number/);
  refused(hashOf({ ...base, params: { ...params, seed: -1 } }), /Seed/);
  refused(hashOf({ ...base, params: { ...params, seed: 2 ** 60 } }), /Seed/);
  refused(hashOf({ ...base, params: { ...params, weights: { ...params.weights, l2: -1 } } }), /Weight l2/);
  refused(hashOf({ ...base, params: { ...params, weights: { euclidean: 1, l2: 1, l21: 1 } } }), /Weight boundary/);
  refused(hashOf({ ...base, params: { ...params, weights: { ...params.weights, density: 1 } } }), /unknown term/);
  refused(hashOf({ ...base, params: { ...params, weights: { euclidean: 0, l2: 0, l21: 0, boundary: 1 } } }), /At least one/);
  refused(hashOf({ ...base, params: { ...params, seeding: 'magic' } }), /Seeding/);
  refused(hashOf({ ...base, params: { ...params, teleport: 'yes' } }), /teleport/);
  refused(hashOf({ ...base, params: { ...params, lloydIterations: 1e6 } }), /Lloyd iterations/);
  refused(hashOf({ ...base, params: { ...params, __proto__: { panels: 5 }, extra: 1 } }), /unknown field/);
  refused(hashOf({ ...base, params: undefined }), /must be an object/);
  refused(hashOf({ ...base, history: 'none' }), /history/);
  refused(hashOf({ ...base, history: Array(MAX_HISTORY + 1).fill(params) }), /history/);
  refused(hashOf({ ...base, history: [{ ...params, panels: -3 }] }), /history/);
});

test('file meshes: sizes, names and extra data are checked', () => {
  const bytes = new TextEncoder().encode('OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n');
  const base = { v: 1, params, history: [] };
  assert.ok(hashToState(hashOf({ ...base, mesh: { file: 'a.off', size: bytes.length } }, bytes)).ok);
  refused(hashOf({ ...base, mesh: { file: 'a.off', size: bytes.length + 1 } }, bytes), /truncated/);
  refused(hashOf({ ...base, mesh: { file: 'a.off', size: -1 } }, bytes), /size/);
  refused(hashOf({ ...base, mesh: { file: 'a.off', size: LINK_LIMITS.maxMeshBytes + 1 } }, bytes), /larger than/);
  refused(hashOf({ ...base, mesh: { file: '../../etc/passwd', size: bytes.length } }, bytes), /file name/);
  refused(hashOf({ ...base, mesh: { file: '', size: bytes.length } }, bytes), /file name/);
  refused(hashOf({ ...base, mesh: { file: 'x'.repeat(300), size: bytes.length } }, bytes), /file name/);
  refused(hashOf({ ...base, mesh: { example: 'saddle' } }, bytes), /extra data/);
});

test('a bad header length is refused', () => {
  const payload = encodePayload({ mesh: { kind: 'example', id: 'saddle' }, params, history: [] });
  new DataView(payload.buffer).setUint32(0, 0xffffffff, true);
  const decoded = decodeState(zlibSync(payload), LINK_LIMITS);
  assert.equal(decoded.ok, false);
  assert.match(decoded.message, /bad header/);
});

test('form values are validated the same way, and map onto the wasm parameters', () => {
  assert.ok(validateParams(DEFAULT_PARAMS).ok);
  assert.equal(validateParams({ ...DEFAULT_PARAMS, panels: Number.NaN }).ok, false);
  assert.deepEqual(toRemeshParams(params), {
    panels: 90,
    seed: 12345678901,
    weights: { euclidean: 1, l2: 0.5, l21: 2, boundary: 1 },
    lloydIterations: 20,
    panelRounds: 30,
    seeding: 'farthest',
    teleport: true,
    singlePointNodes: false,
    optimizePlanes: true,
  });
});
