// Unit tests of the share-link codec (web/src/share.ts, compiled to build/web-tests by
// `npm run test:web`): round trips, and every kind of broken or hostile link we can think of
// gives a clear message instead of a crash or a half-applied design.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { zlibSync } from 'fflate';
import { decodeBase64url, encodeBase64url } from '../../build/web-tests/base64url.js';
import { DEFAULT_PARAMS, LIMITS, toRemeshParams, validateParams } from '../../build/web-tests/params.js';
import { DEFAULT_FABRICATION } from '../../build/web-tests/fabricationParams.js';
import { adler32, decodeState, inflateCapped, encodePayload, encodeState, hashToState, LINK_LIMITS, MAX_HISTORY, MAX_LINK_HASH_CHARS, MAX_SHARED_MESH_BYTES, shareHash, stateToHash } from '../../build/web-tests/share.js';

const encodeFabricationDefaults = () => JSON.parse(JSON.stringify(DEFAULT_FABRICATION));
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
  const bomb = zlibSync(huge, { level: 9 });
  // Poison the stream's last tenth: an inflater that ran on past the cap would reach it and
  // call the link damaged; one that stops at the cap never sees it.
  const poisoned = bomb.slice(0, Math.floor(bomb.length * 0.9));
  poisoned.fill(0xff, poisoned.length - 64);
  assert.match(inflateCapped(poisoned, huge.length * 2).message, /damaged/, 'the poison is found when reached');
  const hash = `#v1=${encodeBase64url(poisoned)}`;
  assert.ok(hash.length < 200_000);
  refused(hash, /unpacks to more than/);
});

test('over-long links are refused before decoding', () => {
  refused(`#v1=${'A'.repeat(4 * 1024 * 1024)}`, /too long/);
  refused(`#v1=${'A'.repeat(MAX_LINK_HASH_CHARS)}`, /too long/);
  refused(`#v1=${'A'.repeat(MAX_LINK_HASH_CHARS - 3)}`, /too long/); // one character over
  refused(`#v1=${'A'.repeat(MAX_LINK_HASH_CHARS - 4)}`, /damaged/); // at the cap: decoded, and refused for what it is
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

// A link from a newer version must not half-apply: unknown fields are refused at the top and
// in the mesh as in the parameters, a mesh naming an example and a file too, and a null is
// not read as an absent field's default.
test('unknown fields, a mesh that is two meshes, and nulls for absent fields are refused', () => {
  const base = { v: 1, mesh: { example: 'saddle' }, params, history: [] };
  assert.ok(hashToState(hashOf(base)).ok);
  refused(hashOf({ ...base, future: { nested: [[[]]] } }), /the link has an unknown field "future"/);
  refused(hashOf(`{"v":1,"mesh":{"example":"saddle"},"params":${JSON.stringify(params)},"history":[],"__proto__":{"panels":5}}`), /unknown field "__proto__"/);
  refused(hashOf({ ...base, mesh: { example: 'saddle', units: 'ft' } }), /the link's mesh has an unknown field "units"/);
  refused(hashOf({ ...base, mesh: { example: 'saddle', file: 'evil.obj', size: 10 } }), /both an example and a mesh file/);
  const bytes = new TextEncoder().encode('OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n');
  refused(hashOf({ ...base, mesh: { file: 'a.off', size: bytes.length, rhinoObject: 'Roof' } }, bytes), /mesh has an unknown field "rhinoObject"/);
  refused(hashOf({ ...base, history: null }), /history/);
  refused(hashOf({ ...base, params: { ...params, edits: null } }), /edit/i);
  refused(hashOf({ ...base, params: { ...params, paint: null } }), /paint key/);
  refused(hashOf({ ...base, params: { ...params, densityExpression: null } }), /xpression/);
  refused(hashOf({ ...base, params: { ...params, anisotropy: null } }), /nisotropy/);
  const fabrication = encodeFabricationDefaults();
  refused(hashOf({ ...base, fabrication: { ...fabrication, boundaryCut: null } }), /oundary/);
  refused(hashOf({ ...base, fabrication: { ...fabrication, upAxis: null } }), /xis/);
});

// The largest design the page can make travels: every step of a full history with thousands of
// panel edits (its settings run to megabytes, which compress to little). Before, the decoder
// capped the settings at 64 KiB and called such a link of the page's own "damaged".
test('a design with a full history of panel edits travels in a link', () => {
  const edits = Array.from({ length: 3000 }, (_, i) => ({ op: 'lock', face: i }));
  const step = { ...params, edits };
  const state = { mesh: { kind: 'example', id: 'saddle' }, params: step, history: Array(MAX_HISTORY).fill(step) };
  const hash = shareHash(state);
  assert.ok(hash.ok, hash.message);
  const decoded = hashToState(hash.value);
  assert.ok(decoded.ok, decoded.message);
  assert.equal(decoded.value.history.length, MAX_HISTORY);
  assert.equal(decoded.value.params.edits.length, 3000);
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
    panelRounds: 100,
    retries: 8,
    seeding: 'farthest',
    teleport: true,
    singlePointNodes: false,
    optimizePlanes: true,
    glass: false,
    minCornerAngleDeg: 0,
    coplanarAngleDeg: 1,
  });
});

test('the coplanar angle: validated, defaulted for old links, sent to the core, carried by a link', () => {
  const wide = validateParams({ ...DEFAULT_PARAMS, coplanarAngleDeg: 2.5 });
  assert.equal(wide.ok, true, wide.message);
  assert.equal(toRemeshParams(wide.value).coplanarAngleDeg, 2.5);
  const { coplanarAngleDeg: _c, ...old } = DEFAULT_PARAMS;
  assert.deepEqual(validateParams(old), { ok: true, value: DEFAULT_PARAMS }, "a link made before the control: the paper's 1 degree");
  assert.equal(DEFAULT_PARAMS.coplanarAngleDeg, 1);
  for (const bad of [10.5, -0.1, Number.NaN, '1']) assert.match(validateParams({ ...DEFAULT_PARAMS, coplanarAngleDeg: bad }).message, /Coplanar angle/, String(bad));
  assert.equal(validateParams({ ...DEFAULT_PARAMS, coplanarAngleDeg: 0 }).ok, true, '0: never share a plane');
  const link = hashToState(stateToHash({ mesh: { kind: 'example', id: 'saddle' }, params: wide.value, history: [] }));
  assert.equal(link.ok, true, link.message);
  assert.equal(link.value.params.coplanarAngleDeg, 2.5);
});

test('the retries: validated, defaulted for old links, sent to the core, carried by a link', () => {
  const few = validateParams({ ...DEFAULT_PARAMS, retries: 2 });
  assert.equal(few.ok, true, few.message);
  assert.equal(toRemeshParams(few.value).retries, 2);
  const { retries: _r, ...old } = DEFAULT_PARAMS;
  assert.deepEqual(validateParams(old), { ok: true, value: DEFAULT_PARAMS }, "a link made before the control: the core's 8");
  assert.equal(DEFAULT_PARAMS.retries, 8);
  for (const bad of [11, -1, 2.5, Number.NaN, '3']) assert.match(validateParams({ ...DEFAULT_PARAMS, retries: bad }).message, /Retries/, String(bad));
  assert.equal(validateParams({ ...DEFAULT_PARAMS, retries: 0 }).ok, true, '0: never retry');
  const link = hashToState(stateToHash({ mesh: { kind: 'example', id: 'saddle' }, params: few.value, history: [] }));
  assert.equal(link.ok, true, link.message);
  assert.equal(link.value.params.retries, 2);
});

test('a corrupted link is refused: the zlib checksum is checked', () => {
  const obj = new TextEncoder().encode('v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n'.repeat(50));
  const state = { mesh: { kind: 'file', name: 'a.obj', bytes: obj }, params, history: [] };
  const compressed = zlibSync(encodePayload(state), { level: 0 }); // stored blocks: any byte can change
  assert.ok(decodeState(compressed, LINK_LIMITS).ok);
  const altered = compressed.slice();
  altered[Math.floor(altered.length * 0.8)] ^= 0x04; // inside the mesh bytes
  const decoded = decodeState(altered, LINK_LIMITS);
  assert.equal(decoded.ok, false);
  assert.match(decoded.message, /checksum/);
  const badSum = compressed.slice();
  badSum[badSum.length - 1] ^= 1;
  assert.match(decodeState(badSum, LINK_LIMITS).message, /checksum/);
});

test('data after the end of the compressed stream is refused', () => {
  const compressed = encodeState({ mesh: { kind: 'example', id: 'saddle' }, params, history: [] });
  assert.ok(decodeState(compressed, LINK_LIMITS).ok);
  for (const junk of [[0], [1, 2, 3, 4, 5, 6, 7, 8], Array.from(compressed.subarray(-4))]) {
    const longer = new Uint8Array([...compressed, ...junk]);
    const decoded = decodeState(longer, LINK_LIMITS);
    assert.equal(decoded.ok, false, `junk ${junk}`);
    assert.match(decoded.message, /damaged/);
  }
  // Junk ending in a copy of the checksum passes the checksum test and is caught by the end check.
  const sneaky = new Uint8Array([...compressed.subarray(0, -4), 9, 9, ...compressed.subarray(-4)]);
  assert.match(decodeState(sneaky, LINK_LIMITS).message, /after the end/);
  const good = stateToHash({ mesh: { kind: 'example', id: 'saddle' }, params, history: [] });
  refused(`${good}AAAA`, /damaged/);
});

test('adler32 matches the reference values', () => {
  assert.equal(adler32(new Uint8Array(0)), 1);
  assert.equal(adler32(new TextEncoder().encode('Wikipedia')), 0x11e60398);
  const big = Uint8Array.from({ length: 100_000 }, (_, i) => (i * 31) % 256);
  assert.equal(adler32(big.subarray(50_000), adler32(big.subarray(0, 50_000))), adler32(big), 'piece by piece = at once');
});

test('a link is capped by its length, the same for writing and reading', () => {
  // Random bytes do not compress: 1.5 MB of them make a hash over the cap.
  let x = 12345;
  const noise = Uint8Array.from({ length: 1_500_000 }, () => ((x = (Math.imul(x, 1103515245) + 12345) >>> 0) >>> 24));
  const large = { mesh: { kind: 'file', name: 'noise.obj', bytes: noise }, params, history: [] };
  const refusedShare = shareHash(large);
  assert.equal(refusedShare.ok, false);
  assert.equal(refusedShare.message, 'the mesh is too large to travel in a link; share an example or a smaller file');
  const hash = stateToHash(large);
  assert.ok(hash.length > MAX_LINK_HASH_CHARS && hash.length < 2_097_152, `${hash.length} characters`);
  refused(hash, /too long/);
  // Just under the cap both ways.
  const small = { mesh: { kind: 'file', name: 'noise.obj', bytes: noise.subarray(0, 1_000_000) }, params, history: [] };
  const accepted = shareHash(small);
  assert.ok(accepted.ok, accepted.message);
  assert.ok(accepted.value.length <= MAX_LINK_HASH_CHARS);
  assert.ok(hashToState(accepted.value).ok);
  assert.equal(shareHash({ ...small, mesh: { ...small.mesh, bytes: new Uint8Array(MAX_SHARED_MESH_BYTES + 1) } }).ok, false, 'too large to try');
});

test('the form limits are the core-compatible ones, shared with links', () => {
  assert.equal(LIMITS.panelRounds.min, 1, 'the core needs at least one panel round');
  assert.ok(LIMITS.lloydIterations.max <= 200 && LIMITS.panelRounds.max <= 100);
  assert.equal(LIMITS.seed.max, 2 ** 53 - 1);
  assert.match(validateParams({ ...DEFAULT_PARAMS, panelRounds: 0 }).message, /Panel rounds must be between 1 and 100/);
  assert.match(validateParams({ ...DEFAULT_PARAMS, lloydIterations: 201 }).message, /Lloyd iterations must be between 0 and 200/);
  assert.ok(validateParams({ ...DEFAULT_PARAMS, seed: 2 ** 53 - 1 }).ok);
});

test("a mesh's preparation travels with it; a hostile one is refused by name", () => {
  const state = { mesh: { kind: 'example', id: 'YasIsland', prepare: { panels: 150, subdivide: 1 } }, params, history: [] };
  const decoded = hashToState(stateToHash(state));
  assert.ok(decoded.ok, decoded.message);
  assert.deepEqual(decoded.value, state);
  const upload = { mesh: { kind: 'file', name: 'grid.obj', bytes: new TextEncoder().encode('v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n'), prepare: { panels: 40, subdivide: 0 } }, params, history: [] };
  const uploaded = hashToState(stateToHash(upload));
  assert.ok(uploaded.ok, uploaded.message);
  assert.deepEqual(uploaded.value.mesh.prepare, { panels: 40, subdivide: 0 });
  const withPrepare = (prepare) => hashOf({ v: 1, mesh: { example: 'YasIsland', prepare }, params, history: [] });
  refused(withPrepare({ panels: 150, subdivide: 5 }), /subdivision levels must be 0 to 4/);
  refused(withPrepare({ panels: 150, subdivide: 1.5 }), /subdivision levels/);
  refused(withPrepare({ panels: 0, subdivide: 1 }), /no valid panel count/);
  refused(withPrepare({ panels: '150', subdivide: 1 }), /no valid panel count/);
  refused(withPrepare({ panels: 150, subdivide: 1, script: 'alert(1)' }), /unknown field "script"/);
  refused(withPrepare([150, 1]), /not an object/);
  refused(withPrepare('refine'), /not an object/);
});

test("a mesh's repair travels with it; the default adds nothing; a hostile one is refused by name", () => {
  const state = { mesh: { kind: 'example', id: 'YasIsland', repair: { fillHoles: 12, largestPart: true } }, params, history: [] };
  const decoded = hashToState(stateToHash(state));
  assert.ok(decoded.ok, decoded.message);
  assert.deepEqual(decoded.value, state);
  // No repair asked: the link is byte for byte the one made without the field.
  const plain = { mesh: { kind: 'example', id: 'YasIsland' }, params, history: [] };
  assert.equal(stateToHash({ ...plain, mesh: { ...plain.mesh, repair: { fillHoles: 0, largestPart: false } } }), stateToHash(plain));
  const withRepair = (repair) => hashOf({ v: 1, mesh: { example: 'YasIsland', repair }, params, history: [] });
  refused(withRepair({ fillHoles: 501, largestPart: false }), /holes to fill must have 0 to 500 edges/);
  refused(withRepair({ fillHoles: -1, largestPart: false }), /holes to fill/);
  refused(withRepair({ fillHoles: 2.5, largestPart: false }), /holes to fill/);
  refused(withRepair({ fillHoles: 3, largestPart: 'yes' }), /largest manifold part/);
  refused(withRepair({ fillHoles: 3 }), /largest manifold part/);
  refused(withRepair({ fillHoles: 3, largestPart: true, script: 'alert(1)' }), /unknown field "script"/);
  refused(withRepair([3, true]), /not an object/);
});
