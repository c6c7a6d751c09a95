// The fabrication settings (web/src/fabricationParams.ts) and how links carry them: defaults,
// validation by field against LIMITS, a round trip, and old links without them.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { DEFAULT_FABRICATION, validateFabrication } from '../../build/web-tests/fabricationParams.js';
import { DEFAULT_PARAMS, LIMITS } from '../../build/web-tests/params.js';
import { hashToState, stateToHash } from '../../build/web-tests/share.js';

const mesh = { kind: 'example', id: 'saddle' };

test('the defaults validate, and each bad field is named', () => {
  assert.deepEqual(validateFabrication(DEFAULT_FABRICATION), { ok: true, value: DEFAULT_FABRICATION });
  const bad = [
    [{ thickness: -1 }, /Thickness/],
    [{ thickness: LIMITS.thickness.max + 1 }, /Thickness/],
    [{ thickness: '20' }, /Thickness/],
    [{ side: 'middle' }, /side/],
    [{ units: 'yd' }, /Units/],
    [{ meshUnits: 'km' }, /Mesh units/],
    [{ sheetWidth: 0 }, /Sheet width/],
    [{ sheetHeight: Number.NaN }, /Sheet height/],
    [{ kerf: 3 }, /unknown field "kerf"/],
  ];
  for (const [change, pattern] of bad) {
    const checked = validateFabrication({ ...DEFAULT_FABRICATION, ...change });
    assert.equal(checked.ok, false, JSON.stringify(change));
    assert.match(checked.message, pattern);
  }
  assert.equal(validateFabrication(null).ok, false);
});

test('a link carries the fabrication settings; an old link without them still opens', () => {
  const fabrication = { ...DEFAULT_FABRICATION, thickness: 20, side: 'outside', units: 'cm', meshUnits: 'mm', sheetWidth: 250, sheetHeight: 125 };
  const state = { mesh, params: DEFAULT_PARAMS, history: [], fabrication };
  const decoded = hashToState(stateToHash(state));
  assert.equal(decoded.ok, true, decoded.message);
  assert.deepEqual(decoded.value.fabrication, fabrication);

  const old = hashToState(stateToHash({ mesh, params: DEFAULT_PARAMS, history: [] }));
  assert.equal(old.ok, true, old.message);
  assert.equal(old.value.fabrication, undefined, 'the page then uses the defaults');

  const hostile = hashToState(stateToHash({ mesh, params: DEFAULT_PARAMS, history: [], fabrication: { ...fabrication, thickness: -5 } }));
  assert.equal(hostile.ok, false);
  assert.match(hostile.message, /in the link, Thickness/);
});
