// The fabrication settings (web/src/fabricationParams.ts) and how links carry them: defaults,
// validation by field against LIMITS, a round trip, and old links without them.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { DEFAULT_FABRICATION, toFabricationParams, validateFabrication } from '../../build/web-tests/fabricationParams.js';
import { fabricationRows, foldedHint } from '../../build/web-tests/fabricationStats.js';
import { DEFAULT_PARAMS, LIMITS, toRemeshParams, validateParams } from '../../build/web-tests/params.js';
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
  const unknown = hashToState(stateToHash({ mesh, params: DEFAULT_PARAMS, history: [], fabrication: { ...fabrication, sheetMargin: 10 } }));
  assert.equal(unknown.message, 'in the link, fabrication: unknown field "sheetMargin"');
});

test('per-panel thickness and boundary cuts: validated, sorted, carried by links, sent with a thickness only', () => {
  const fabrication = { ...DEFAULT_FABRICATION, thickness: 20, panelThickness: { P7: 12, P3a: 30 }, boundaryCut: 'bevel', boundaryBevelDeg: -10, upAxis: 'y' };
  const checked = validateFabrication(fabrication);
  assert.equal(checked.ok, true, checked.message);
  assert.deepEqual(Object.keys(checked.value.panelThickness), ['P3a', 'P7'], 'keys sorted: equal settings stringify equally');
  const decoded = hashToState(stateToHash({ mesh, params: DEFAULT_PARAMS, history: [], fabrication: checked.value }));
  assert.equal(decoded.ok, true, decoded.message);
  assert.deepEqual(decoded.value.fabrication, checked.value);
  assert.deepEqual(toFabricationParams(checked.value).panelThickness, { P3a: 30, P7: 12 });
  assert.equal(toFabricationParams({ ...checked.value, thickness: 0 }).panelThickness, undefined, 'the core needs a common thickness');
  // Settings stored before these fields existed still validate, to the defaults.
  const { panelThickness, boundaryCut, boundaryBevelDeg, upAxis, ...old } = DEFAULT_FABRICATION;
  assert.deepEqual(validateFabrication(old), { ok: true, value: DEFAULT_FABRICATION });
  const bad = [
    [{ panelThickness: { Q1: 3 } }, /not a panel label/],
    [{ panelThickness: { P0: 3 } }, /not a panel label/],
    [{ panelThickness: { P1: 0 } }, /Panel thickness of P1/],
    [{ panelThickness: [3] }, /Panel thickness/],
    [{ boundaryCut: 'round' }, /Boundary edges/],
    [{ boundaryBevelDeg: 61 }, /Boundary bevel/],
    [{ upAxis: 'w' }, /Up axis/],
  ];
  for (const [change, pattern] of bad) {
    const result = validateFabrication({ ...DEFAULT_FABRICATION, ...change });
    assert.equal(result.ok, false, JSON.stringify(change));
    assert.match(result.message, pattern);
  }
});

test('glass mode and the minimum corner angle: validated, defaulted for old links, sent to the core', () => {
  const glass = validateParams({ ...DEFAULT_PARAMS, glass: true, minCornerAngleDeg: 15 });
  assert.equal(glass.ok, true, glass.message);
  assert.equal(toRemeshParams(glass.value).glass, true);
  assert.equal(toRemeshParams(glass.value).minCornerAngleDeg, 15);
  const { glass: _g, minCornerAngleDeg: _m, ...old } = DEFAULT_PARAMS;
  assert.deepEqual(validateParams(old), { ok: true, value: DEFAULT_PARAMS });
  assert.match(validateParams({ ...DEFAULT_PARAMS, minCornerAngleDeg: 61 }).message, /Min corner angle/);
  assert.match(validateParams({ ...DEFAULT_PARAMS, minCornerAngleDeg: -1 }).message, /Min corner angle/);
  assert.match(validateParams({ ...DEFAULT_PARAMS, glass: 'yes' }).message, /Glass mode/);
  const link = hashToState(stateToHash({ mesh, params: glass.value, history: [] }));
  assert.equal(link.ok, true, link.message);
  assert.deepEqual(link.value.params, glass.value);
});

test('parts whose inner face folds over are counted and named, with what to do', () => {
  const result = (thickness, folded) => ({
    partsCsv: '', partsJson: '{}', solidObj: null, innerPositions: new Float64Array(),
    sheets: { ok: true, svg: '', dxf: '', stats: { sheets: 1, materialUse: 0.5 } },
    spread: { ok: true, message: '', units: 'mm', thickness, maxSpread: 0, nodes: [], folded },
  });
  const row = (r) => fabricationRows(r).find((x) => x.label === 'Folded parts');
  assert.equal(row(result(0, [])), undefined, 'no row without a thickness');
  assert.equal(foldedHint(result(0, [])), null);
  assert.equal(row(result(20, [])).value, '0');
  assert.equal(foldedHint(result(20, [])), null);
  const many = ['P2', 'P6', 'P8', 'P9', 'P13', 'P14', 'P15'];
  assert.equal(row(result(20, many)).value, '7: P2, P6, P8, P9, P13, P14, …');
  assert.match(foldedHint(result(20, many)), /At 20 mm the inner face folds over on 7 parts: they cannot be cut as drawn\. Use thinner material/);
  assert.match(foldedHint(result(2, ['P5'])), /on 1 part:/);
});
