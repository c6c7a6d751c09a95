// Unit tests of the page's density side (compiled to build/web-tests by `npm run test:web`):
// the undo history, the quantised paint field (round trip, exact decoded values, keys), the
// brush's dabs, the expression and anisotropy validation, and paint in share links (round
// trip, and every hostile variant refused with a clear message).
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { zlibSync } from 'fflate';
import { encodeBase64url } from '../../build/web-tests/base64url.js';
import { applyDab, dabsAlong, falloff, vertexAdjacency } from '../../build/web-tests/brush/brushPainter.js';
import { decodeField, densityOfLevel, fieldKey, fieldProblem, isUniform, levelOf, MAX_LEVEL, quantiseField } from '../../build/web-tests/brush/densityField.js';
import { expressionLog2, fieldColors, log2Colors } from '../../build/web-tests/brush/densityColors.js';
import { History } from '../../build/web-tests/history.js';
import { paintKeys } from '../../build/web-tests/paintFields.js';
import { checkExpression, DEFAULT_PARAMS, DENSITY_PRESETS, toRemeshParams, validateParams } from '../../build/web-tests/params.js';
import { encodePayload, hashToState, PAINT_TOO_LARGE, shareHash, stateToHash } from '../../build/web-tests/share.js';

// ---- history

test('history: undo, redo, a new step drops the redo branch', () => {
  const h = new History(100);
  assert.equal(h.current, null);
  assert.equal(h.canUndo, false);
  h.reset('a');
  assert.equal(h.canUndo, false);
  assert.equal(h.canRedo, false);
  h.push('b');
  h.push('c');
  assert.equal(h.current, 'c');
  assert.equal(h.undo(), 'b');
  assert.equal(h.undo(), 'a');
  assert.equal(h.undo(), null, 'nothing before the first state');
  assert.equal(h.current, 'a');
  assert.equal(h.redo(), 'b');
  assert.equal(h.canRedo, true);
  h.push('d'); // an edit after undo: 'c' is gone
  assert.equal(h.canRedo, false);
  assert.equal(h.redo(), null);
  assert.deepEqual([...h.all], ['a', 'b', 'd']);
  h.replaceCurrent('d2');
  assert.equal(h.current, 'd2');
  assert.equal(h.size, 3);
});

test('history: bounded, the oldest states go first', () => {
  const h = new History(5);
  h.reset(0);
  for (let i = 1; i <= 12; i++) h.push(i);
  assert.equal(h.size, 5);
  assert.deepEqual([...h.all], [8, 9, 10, 11, 12]);
  let undone = 0;
  while (h.undo() !== null) undone++;
  assert.equal(undone, 4);
  assert.equal(h.current, 8);
  assert.throws(() => new History(0));
  assert.throws(() => new History(1).replaceCurrent(1), /no current state/);
});

// ---- the quantised field

test('quantisation: levels in 1/16 octaves over [-4, 4], decoded exactly', () => {
  assert.equal(levelOf(0), 0);
  assert.equal(Object.is(levelOf(-0.01), -0), false, 'never -0');
  assert.equal(levelOf(1), 16);
  assert.equal(levelOf(-1), -16);
  assert.equal(levelOf(100), MAX_LEVEL);
  assert.equal(levelOf(-100), -MAX_LEVEL);
  assert.equal(levelOf(Number.NaN), 0);
  for (let level = -MAX_LEVEL; level <= MAX_LEVEL; level++) {
    const density = densityOfLevel(level);
    assert.ok(Math.abs(density / 2 ** (level / 16) - 1) < 1e-15, `level ${level}`);
    assert.equal(levelOf(Math.log2(density)), level, 'round trip level -> density -> level');
  }
  assert.equal(densityOfLevel(16), 2);
  assert.equal(densityOfLevel(-64), 1 / 16);
  assert.equal(densityOfLevel(8), Math.SQRT2);
  // A painted log2 field -> levels -> densities -> levels again: unchanged.
  const log2 = Float32Array.from({ length: 500 }, (_, i) => Math.sin(i * 0.37) * 5);
  const field = quantiseField(log2);
  const again = quantiseField(Float64Array.from(decodeField(field), (d) => Math.log2(d)));
  assert.deepEqual(again, field);
  for (let i = 0; i < log2.length; i++) assert.ok(Math.abs(field[i] / 16 - Math.max(-4, Math.min(4, log2[i]))) <= 1 / 32 + 1e-6);
  assert.ok(decodeField(field).every((d) => d > 0 && Number.isFinite(d)));
});

test('field keys: content keys, 16 hex digits, sensitive to every byte and the length', () => {
  const a = Int8Array.from({ length: 1000 }, (_, i) => (i % 7) - 3);
  const key = fieldKey(a);
  assert.match(key, /^[0-9a-f]{16}$/);
  assert.equal(fieldKey(a.slice()), key);
  const b = a.slice();
  b[999] = 64;
  assert.notEqual(fieldKey(b), key);
  assert.notEqual(fieldKey(new Int8Array(10)), fieldKey(new Int8Array(11)));
  assert.equal(isUniform(new Int8Array(5)), true);
  assert.equal(isUniform(a), false);
  assert.equal(fieldProblem(new Uint8Array(a.buffer), key), null);
  assert.match(fieldProblem(new Uint8Array(b.buffer), key), /does not match/);
  const wild = Int8Array.from([0, 65]);
  assert.match(fieldProblem(new Uint8Array(wild.buffer), fieldKey(wild)), /outside the paint range/);
});

// ---- the brush

test('a dab: add raises the density under it with a smooth falloff, erase and smooth undo it', () => {
  // A 21 x 21 grid in the plane, spacing 0.1.
  const n = 21;
  const positions = new Float32Array(n * n * 3);
  for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) positions.set([i * 0.1, j * 0.1, 0], (j * n + i) * 3);
  const indices = [];
  for (let j = 0; j + 1 < n; j++) for (let i = 0; i + 1 < n; i++) {
    const v = j * n + i;
    indices.push(v, v + 1, v + n, v + 1, v + n + 1, v + n);
  }
  const adjacency = vertexAdjacency(n * n, Uint32Array.from(indices));
  assert.equal(adjacency.offsets[n * n], adjacency.neighbours.length);
  const all = Array.from({ length: n * n }, (_, i) => i);
  const log2 = new Float32Array(n * n);
  const centre = [1, 1, 0];
  const middle = 10 * n + 10;
  assert.ok(applyDab(log2, positions, all, adjacency, { centre, radius: 0.5, strength: 1, mode: 'add' }));
  assert.ok(Math.abs(log2[middle] - 0.5) < 1e-6, 'full strength at the centre');
  assert.equal(log2[0], 0, 'nothing outside the radius');
  assert.ok(log2[middle + 2] > 0 && log2[middle + 2] < log2[middle + 1] && log2[middle + 1] < log2[middle], 'falls off');
  assert.equal(falloff(0.5, 0.5), 0);
  assert.equal(falloff(0, 1), 1);
  for (let k = 0; k < 20; k++) applyDab(log2, positions, all, adjacency, { centre, radius: 0.5, strength: 1, mode: 'add' });
  assert.equal(log2[middle], 4, 'clamped at 16x');
  const before = log2[middle + 4];
  applyDab(log2, positions, all, adjacency, { centre, radius: 0.5, strength: 1, mode: 'smooth' });
  assert.ok(log2[middle + 4] > before, 'smoothing spreads paint outwards at the rim');
  for (let k = 0; k < 20; k++) applyDab(log2, positions, all, adjacency, { centre, radius: 2, strength: 1, mode: 'erase' });
  assert.ok(log2.every((x) => x === 0), 'erase at full strength brings it back to 1x');
  assert.equal(applyDab(log2, positions, all, adjacency, { centre, radius: 0.5, strength: 0, mode: 'add' }), false);
});

test('dabs along a path: evenly spaced, the remainder carried to the next segment', () => {
  let carried = 0;
  const centres = [];
  const points = [[0, 0, 0], [0.25, 0, 0], [0.3, 0, 0], [1, 0, 0]];
  for (let i = 0; i + 1 < points.length; i++) {
    const path = dabsAlong(points[i], points[i + 1], 0.1, carried);
    centres.push(...path.centres);
    carried = path.carried;
  }
  assert.equal(centres.length, 10);
  centres.forEach((c, i) => assert.ok(Math.abs(c[0] - 0.1 * (i + 1)) < 1e-9, `dab ${i} at ${c[0]}`));
  assert.equal(dabsAlong([0, 0, 0], [0, 0, 0], 0.1, 0).centres.length, 0);
});

// ---- expression and anisotropy

test('density expressions: presets and formulas pass, anything else is refused with a reason', () => {
  for (const preset of DENSITY_PRESETS) assert.ok(checkExpression(preset.expression).ok, preset.expression);
  for (const good of ['', '1', '1 + 3*u', '1 + 3 * exp(-border / 0.05)', '2.5e-3 * x + .5', 'if(u < 0.5, 1, 4)', 'max(1, min(curv, 4)) ^ 2', 'clamp(abs(nz), 0.1, 1) * pi / e', 'u >= 0.5 && v != 1 ? 2 : 1']) {
    assert.ok(checkExpression(good).ok, good);
  }
  const bad = [
    ['alert(1)', /unknown name "alert" \(use x y z, u v w, nx ny nz, k1 k2 H K curv, border, pi e/],
    ['u + window', /unknown name "window"/],
    ['2alert', /unknown name "alert"/],
    ['u; 1', /character .*";" at column 2/],
    ['"u"', /character .*U\+0022 at column 1/],
    ['u\n+1', /character .*U\+000A at column 2/],
    ['1 + ü', /U\+00FC/],
    ['<script>', /unknown name "script"/],
    ['x'.repeat(1001), /longer than 1000/],
    [42, /must be text/],
  ];
  for (const [text, pattern] of bad) {
    const checked = checkExpression(text);
    assert.equal(checked.ok, false, String(text).slice(0, 20));
    assert.match(checked.message, pattern);
  }
});

test('params: the new fields default when absent, are checked, and reach the core only when set', () => {
  const old = { ...DEFAULT_PARAMS };
  delete old.densityExpression;
  delete old.anisotropy;
  delete old.paint;
  const checked = validateParams(old);
  assert.ok(checked.ok);
  assert.deepEqual(checked.value, DEFAULT_PARAMS, 'links and sessions from before: the defaults');
  const remesh = toRemeshParams(DEFAULT_PARAMS);
  assert.equal('densityExpression' in remesh, false);
  assert.equal('anisotropy' in remesh, false);
  assert.equal('paint' in remesh, false, 'the paint travels as a field of its own');
  const set = { ...DEFAULT_PARAMS, densityExpression: '1 + 3 * u', anisotropy: { direction: 'maxCurvature', stretch: 2.5 }, paint: '0123456789abcdef' };
  assert.ok(validateParams(set).ok);
  assert.deepEqual(toRemeshParams(set).anisotropy, { direction: 'maxCurvature', stretch: 2.5 });
  assert.equal(toRemeshParams(set).densityExpression, '1 + 3 * u');
  const refusals = [
    [{ anisotropy: { direction: 'diagonal', stretch: 2 } }, /Anisotropy direction must be one of/],
    [{ anisotropy: { direction: 'x', stretch: 11 } }, /Stretch must be between 1 and 10/],
    [{ anisotropy: { direction: 'x', stretch: 0.5 } }, /Stretch/],
    [{ anisotropy: { direction: 'x', stretch: Number.NaN } }, /Stretch must be a number/],
    [{ anisotropy: { direction: 'x', stretch: 2, extra: 1 } }, /unknown field "extra"/],
    [{ anisotropy: 'x' }, /Anisotropy must be an object/],
    [{ densityExpression: 'fetch(1)' }, /unknown name "fetch"/],
    [{ paint: 'ABC' }, /paint key/],
    [{ paint: 7 }, /paint key/],
  ];
  for (const [change, pattern] of refusals) {
    const result = validateParams({ ...DEFAULT_PARAMS, ...change });
    assert.equal(result.ok, false, JSON.stringify(change));
    assert.match(result.message, pattern);
  }
});

// ---- paint in share links

const VERTICES = 300;
function painted(seed) {
  return Int8Array.from({ length: VERTICES }, (_, i) => (i * seed) % 50 > 30 ? ((i + seed) % 129) - 64 : 0);
}

function paintedState() {
  const f1 = painted(7);
  const f2 = painted(11);
  const k1 = fieldKey(f1);
  const k2 = fieldKey(f2);
  const p0 = { ...DEFAULT_PARAMS, panels: 60 };
  return {
    state: { mesh: { kind: 'example', id: 'saddle' }, params: { ...p0, paint: k2 }, history: [p0, { ...p0, paint: k1 }], paint: new Map([[k1, f1], [k2, f2]]) },
    f1,
    f2,
    k1,
    k2,
  };
}

test('a link carries the painted fields its parameters name, and gives them back exactly', () => {
  const { state, k1, k2, f1, f2 } = paintedState();
  assert.deepEqual(paintKeys(state.params, state.history), [k1, k2]);
  const hash = shareHash(state);
  assert.ok(hash.ok, hash.message);
  const decoded = hashToState(hash.value);
  assert.ok(decoded.ok, decoded.message);
  assert.deepEqual(decoded.value.params, state.params);
  assert.deepEqual(decoded.value.history, state.history);
  assert.deepEqual(decoded.value.paint.get(k1), f1);
  assert.deepEqual(decoded.value.paint.get(k2), f2);
  assert.equal(decoded.value.paint.size, 2);
  // An uploaded mesh with paint: the mesh bytes and the paint bytes stay apart.
  const bytes = new TextEncoder().encode('OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n');
  const withFile = { ...state, mesh: { kind: 'file', name: 'tri.off', bytes } };
  const fileDecoded = hashToState(stateToHash(withFile));
  assert.ok(fileDecoded.ok, fileDecoded.message);
  assert.deepEqual(fileDecoded.value.mesh.bytes, bytes);
  assert.deepEqual(fileDecoded.value.paint.get(k2), f2);
  // A link without paint decodes with no paint at all (older links).
  const plain = hashToState(stateToHash({ mesh: { kind: 'example', id: 'saddle' }, params: DEFAULT_PARAMS, history: [] }));
  assert.ok(plain.ok);
  assert.equal('paint' in plain.value, false);
  // Parameters naming a field the state does not hold: a bug, said loudly.
  assert.throws(() => encodePayload({ ...state, paint: new Map() }), /missing/);
});

// A hash from JSON and the bytes after it, bypassing the encoder.
function hashOf(json, tail) {
  const text = new TextEncoder().encode(JSON.stringify(json));
  const payload = new Uint8Array(4 + text.length + tail.length);
  new DataView(payload.buffer).setUint32(0, text.length, true);
  payload.set(text, 4);
  payload.set(tail, 4 + text.length);
  return `#v1=${encodeBase64url(zlibSync(payload))}`;
}

test('hostile paint in a link is refused with a clear message', () => {
  const { state, k1, k2, f1, f2 } = paintedState();
  const json = { v: 1, mesh: { example: 'saddle' }, params: state.params, history: state.history, paint: [{ key: k1, vertices: VERTICES }, { key: k2, vertices: VERTICES }] };
  const tail = new Uint8Array(2 * VERTICES);
  tail.set(new Uint8Array(f1.buffer), 0);
  tail.set(new Uint8Array(f2.buffer), VERTICES);
  assert.ok(hashToState(hashOf(json, tail)).ok, 'the hand-made link is valid');
  const refused = (hash, pattern) => {
    const decoded = hashToState(hash);
    assert.equal(decoded.ok, false);
    assert.match(decoded.message, pattern);
  };
  const altered = tail.slice();
  altered[5] ^= 1;
  refused(hashOf(json, altered), /density paint is damaged: it does not match its key/);
  const wild = tail.slice();
  wild[3] = 100;
  refused(hashOf(json, wild), /outside the paint range/);
  refused(hashOf(json, tail.subarray(0, tail.length - 1)), /truncated|extra data|damaged/);
  refused(hashOf(json, new Uint8Array([...tail, 0])), /extra data/);
  refused(hashOf({ ...json, paint: [{ key: k1, vertices: 1e12 }] }, tail), /size outside/);
  refused(hashOf({ ...json, paint: [{ key: k1, vertices: 4_000_000 }, { key: k2, vertices: 4_000_000 }] }, tail), /larger than/);
  refused(hashOf({ ...json, paint: [{ key: k1, vertices: -3 }] }, tail), /size outside/);
  refused(hashOf({ ...json, paint: [{ key: k1, vertices: 2.5 }] }, tail), /size outside/);
  refused(hashOf({ ...json, paint: [{ key: '../../etc', vertices: VERTICES }] }, tail), /bad density paint key/);
  refused(hashOf({ ...json, paint: [{ key: k1, vertices: VERTICES, more: 1 }] }, tail), /bad density paint entry/);
  refused(hashOf({ ...json, paint: 'lots' }, tail), /bad density paint list/);
  refused(hashOf({ ...json, paint: Array(17).fill({ key: k1, vertices: 1 }) }, tail), /bad density paint list/);
  refused(hashOf({ ...json, paint: [{ key: k1, vertices: VERTICES }] }, tail.subarray(0, VERTICES)), /does not match its parameters/);
  refused(hashOf({ ...json, paint: [{ key: k1, vertices: VERTICES }, { key: k1, vertices: VERTICES }] }, new Uint8Array([...tail.subarray(0, VERTICES), ...tail.subarray(0, VERTICES)])), /does not match its parameters/);
  refused(hashOf({ ...json, paint: [{ key: k1, vertices: VERTICES }, { key: k2, vertices: VERTICES - 1 }] }, tail.subarray(0, 2 * VERTICES - 1)), /differ in size|does not match/);
  refused(hashOf({ ...json, params: { ...state.params, paint: 'ffffffffffffffff' } }, tail), /does not match its parameters/);
  const { paint: _, ...withoutTable } = json;
  refused(hashOf(withoutTable, tail), /extra data|does not match/);
});

test('paint too large for a link is refused when sharing, not written', () => {
  const big = new Int8Array(3 * 1024 * 1024);
  big[0] = 1;
  const key = fieldKey(big);
  const outcome = shareHash({ mesh: { kind: 'example', id: 'saddle' }, params: { ...DEFAULT_PARAMS, paint: key }, history: [], paint: new Map([[key, big]]) });
  assert.equal(outcome.ok, false);
  assert.equal(outcome.message, PAINT_TOO_LARGE);
});

test('density colours: with an expression the map shows expression x paint (the solver\'s density)', () => {
  const rgb = (colors, v) => [...colors.slice(v * 3, v * 3 + 3)].map((c) => c.toFixed(4)).join(',');
  const levels = Int8Array.from([0, 16, -16, 0]); // 1x, 2x, 1/2x, 1x painted
  const paintOnly = fieldColors(levels, 4);
  const expression = expressionLog2(Float64Array.from([1, 0.5, 2, 4]), 4); // the core's values
  assert.deepEqual([...expression], [0, -1, 1, 2]);
  const effective = fieldColors(levels, 4, expression);
  assert.equal(rgb(effective, 0), rgb(paintOnly, 0), '1 x 1 = 1');
  assert.equal(rgb(effective, 1), rgb(fieldColors(null, 1), 0), '0.5 x 2 = 1: neutral');
  assert.equal(rgb(effective, 2), rgb(paintOnly, 0), '2 x 0.5 = 1: neutral');
  assert.equal(rgb(effective, 3), rgb(fieldColors(Int8Array.from([32]), 1), 0), 'unpainted: the expression alone (4x)');
  assert.notEqual(rgb(effective, 3), rgb(paintOnly, 3), 'the paint-only map would show 1x there');
  // The stroke preview adds it the same way.
  const preview = new Float32Array(12);
  log2Colors(Float32Array.from([0, 1, -1, 0]), preview, expression);
  assert.deepEqual([...preview].map((c) => c.toFixed(4)), [...effective].map((c) => c.toFixed(4)));
  // No values, another mesh's, or a non-positive one: no expression on the map.
  assert.equal(expressionLog2(new Float64Array(0), 4), null);
  assert.equal(expressionLog2(Float64Array.from([1, 2]), 4), null);
  assert.equal(expressionLog2(Float64Array.from([1, 0, 1, 1]), 4), null);
});
