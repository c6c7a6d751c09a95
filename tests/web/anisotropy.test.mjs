// Unit tests of the procedural anisotropy direction on the page (web/src/params.ts, compiled to
// build/web-tests by `npm run test:web`): the "Direction expression" checks token by token
// like the density expression plus its three components; the Expression direction's field in
// params, share links and the stored session's shape (strict both ways); what reaches the core.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { unzlibSync as inflate, zlibSync } from 'fflate';
import { encodeBase64url } from '../../build/web-tests/base64url.js';
import { checkDirectionExpression, DEFAULT_PARAMS, DIRECTION_PRESETS, toRemeshParams, validateParams } from '../../build/web-tests/params.js';
import { hashToState, stateToHash } from '../../build/web-tests/share.js';

const vortex = { direction: 'expression', stretch: 3, expression: '-y, x, 0' };

test('direction expressions: presets and formulas pass, anything else is refused with a reason', () => {
  for (const preset of DIRECTION_PRESETS) assert.ok(checkDirectionExpression(preset.expression).ok, preset.expression);
  for (const good of ['-y, x, 0', ' nz, 0, -nx ', 'if(z > 1, 1, 0), 0, 1', 'atan2(y, x), min(u, v, w), clamp(z, 0, 1)', 'x,y,z']) {
    const checked = checkDirectionExpression(good);
    assert.ok(checked.ok, `${good}: ${checked.message}`);
    assert.equal(checked.value, good.trim());
  }
  const bad = [
    ['', /is empty/],
    ['   ', /is empty/],
    ['-y, x', /needs three components .* it has 2/],
    ['x, y, z, 1', /it has 4/],
    ['x, (y, z)', /it has 2/],
    ['x, , z', /component 2 \(y\) is empty/],
    ['x, y, ', /component 3 \(z\) is empty/],
    ['x, y, alert(1)', /^Direction expression uses an unknown name "alert" \(use x y z, u v w, nx ny nz, k1 k2 H K curv, pi e/],
    ['x, border, 0', /^Direction expression uses border, which only the density expression has/],
    ['x, y; z, 1', /^Direction expression has a character .*";" at column 5/],
    ['x, y, "z"', /U\+0022 at column 7/],
    ['x, ü, z', /U\+00FC/],
    ['x, y,\nz', /U\+000A/],
    ['x,'.repeat(600), /longer than 1000/],
    [3, /^Direction expression must be text/],
    [null, /must be text/],
  ];
  for (const [text, pattern] of bad) {
    const checked = checkDirectionExpression(text);
    assert.equal(checked.ok, false, String(text).slice(0, 30));
    assert.match(checked.message, pattern);
  }
});

test('params: the Expression direction carries its expression, the others none, strictly', () => {
  const set = { ...DEFAULT_PARAMS, anisotropy: vortex };
  const checked = validateParams(set);
  assert.ok(checked.ok, checked.message);
  assert.deepEqual(checked.value.anisotropy, vortex);
  assert.deepEqual(toRemeshParams(checked.value).anisotropy, vortex, 'the core gets direction, stretch and expression');
  // Whitespace around is trimmed, as the density expression's.
  assert.equal(validateParams({ ...set, anisotropy: { ...vortex, expression: '  -y, x, 0 ' } }).value.anisotropy.expression, '-y, x, 0');
  // The other directions: as before, no expression field at all.
  const x = validateParams({ ...DEFAULT_PARAMS, anisotropy: { direction: 'x', stretch: 2 } });
  assert.ok(x.ok);
  assert.deepEqual(toRemeshParams(x.value).anisotropy, { direction: 'x', stretch: 2 });
  const refusals = [
    [{ direction: 'expression', stretch: 3 }, /Direction expression is empty/],
    [{ direction: 'expression', stretch: 3, expression: 'fetch(1), 0, 0' }, /unknown name "fetch"/],
    [{ direction: 'expression', stretch: 3, expression: '-y, x' }, /needs three components/],
    [{ direction: 'expression', stretch: 3, expression: ['-y', 'x', '0'] }, /must be text/],
    [{ direction: 'expression', stretch: 30, expression: '-y, x, 0' }, /Stretch must be between 1 and 10/],
    [{ direction: 'x', stretch: 2, expression: '1, 0, 0' }, /expression goes with the Expression direction only/],
    [{ direction: 'none', stretch: 1, expression: '' }, /Expression direction only/],
    [{ direction: 'expression', stretch: 3, expression: '-y, x, 0', extra: 1 }, /unknown field "extra"/],
  ];
  for (const [anisotropy, pattern] of refusals) {
    const refused = validateParams({ ...DEFAULT_PARAMS, anisotropy });
    assert.equal(refused.ok, false, JSON.stringify(anisotropy));
    assert.match(refused.message, pattern);
  }
});

// A hash from raw JSON, bypassing the encoder's own checks (as tests/web/share.test.mjs).
function hashOf(json) {
  const text = new TextEncoder().encode(JSON.stringify(json));
  const payload = new Uint8Array(4 + text.length);
  new DataView(payload.buffer).setUint32(0, text.length, true);
  payload.set(text, 4);
  return `#v1=${encodeBase64url(zlibSync(payload))}`;
}

test('share links: the expression round-trips, in the design and its history; hostile ones are refused', () => {
  const params = { ...DEFAULT_PARAMS, panels: 80, anisotropy: vortex };
  const state = { mesh: { kind: 'example', id: 'groin_vault' }, params, history: [{ ...params, anisotropy: { ...vortex, expression: 'nz, 0, -nx' } }] };
  const decoded = hashToState(stateToHash(state));
  assert.ok(decoded.ok, decoded.message);
  assert.deepEqual(decoded.value, state);
  // The encoder's JSON, edited by hand: each hostile variant gives the checker's message.
  const json = JSON.parse(new TextDecoder().decode(hashPayloadJson(stateToHash(state))));
  for (const [expression, pattern] of [
    ['constructor, 0, 0', /unknown name "constructor"/],
    ['x, y, z, w', /needs three components/],
    ['x, y\u2028, z', /U\+2028/],
    [{ toString: 1 }, /must be text/],
  ]) {
    const hostile = structuredClone(json);
    hostile.params.anisotropy.expression = expression;
    const result = hashToState(hashOf(hostile));
    assert.equal(result.ok, false, JSON.stringify(expression));
    assert.match(result.message, pattern);
  }
  const inHistory = structuredClone(json);
  inHistory.history[0].anisotropy = { direction: 'y', stretch: 2, expression: '0, 1, 0' };
  const refusedHistory = hashToState(hashOf(inHistory));
  assert.equal(refusedHistory.ok, false);
  assert.match(refusedHistory.message, /Expression direction only/);
});

// The JSON text inside a v1 hash (the payload's first part).
function hashPayloadJson(hash) {
  const b64 = hash.slice('#v1='.length).replace(/-/g, '+').replace(/_/g, '/');
  const bytes = Uint8Array.from(Buffer.from(b64, 'base64'));
  const payload = inflate(bytes);
  const length = new DataView(payload.buffer, payload.byteOffset).getUint32(0, true);
  return payload.subarray(4, 4 + length);
}
