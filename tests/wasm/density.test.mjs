// Session.setDensity (wasm/session_density.cpp): a density per vertex of the cleaned mesh.
// Refused with a message on a wrong length or bad values (nothing changed); kept across
// setParams; the same field twice is a no-op; a new mesh drops it; and it does what it says:
// panels in the dense half are smaller than in the other.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { json, loadModule, parseObj, solve } from './module.mjs';

const ff = await loadModule();

function expectError(text, pattern) {
  const status = json(text);
  assert.equal(status.ok, false, `expected an error, got ${text}`);
  assert.match(status.message, pattern);
}

// 4x denser where x > the middle of the mesh.
function halfDense(s) {
  const p = s.inputPositions();
  const n = p.length / 3;
  let lo = Infinity;
  let hi = -Infinity;
  for (let v = 0; v < n; v++) {
    lo = Math.min(lo, p[v * 3]);
    hi = Math.max(hi, p[v * 3]);
  }
  const mid = (lo + hi) / 2;
  return { mid, density: Float64Array.from({ length: n }, (_, v) => (p[v * 3] > mid ? 4 : 1)) };
}

function meanAreas(objText, mid) {
  const { vertices, faces } = parseObj(objText);
  const sides = [[], []];
  for (const f of faces) {
    const pts = f.map((i) => vertices[i]);
    const n = [0, 0, 0];
    for (let i = 0; i < pts.length; i++) {
      const a = pts[i];
      const b = pts[(i + 1) % pts.length];
      n[0] += a[1] * b[2] - a[2] * b[1];
      n[1] += a[2] * b[0] - a[0] * b[2];
      n[2] += a[0] * b[1] - a[1] * b[0];
    }
    const cx = pts.reduce((s, q) => s + q[0], 0) / pts.length;
    sides[cx > mid ? 1 : 0].push(Math.hypot(...n) / 2);
  }
  return sides.map((a) => a.reduce((s, x) => s + x, 0) / a.length);
}

test('setDensity validates and keeps the session as it was on failure', () => {
  const s = new ff.Session();
  expectError(s.setDensity(new Float64Array([1, 2, 3])), /no mesh/);
  assert.equal(json(s.setDensity(new Float64Array(0))).ok, true, 'empty is uniform, always fine');
  const info = json(s.loadShape('saddle', 2000));
  assert.equal(info.ok, true);
  expectError(s.setDensity(new Float64Array(info.vertices - 1)), new RegExp(`${info.vertices - 1} values; the mesh has ${info.vertices} vertices`));
  const bad = new Float64Array(info.vertices).fill(1);
  bad[7] = 0;
  expectError(s.setDensity(bad), /density value 8 is 0/);
  bad[7] = Number.NaN;
  expectError(s.setDensity(bad), /density value 8/);
  bad[7] = -2;
  expectError(s.setDensity(bad), /greater than 0/);
  s.delete();
});

test('a dense half gets smaller panels; the field survives setParams, warm-starts, and a new mesh drops it', () => {
  const s = new ff.Session();
  json(s.loadShape('saddle', 4000));
  const { mid, density } = halfDense(s);
  assert.equal(json(s.setParams(JSON.stringify({ panels: 60, seed: 1 }))).ok, true);
  solve(s);
  const uniform = s.objText();
  const [u0, u1] = meanAreas(uniform, mid);
  // Warm start: the field on the finished solve.
  assert.equal(json(s.setDensity(density)).ok, true);
  assert.equal(s.done(), false, 'a new field restarts the solve from the result');
  solve(s);
  const warm = s.objText();
  const [d0, d1] = meanAreas(warm, mid);
  console.log(`setDensity: mean panel area sparse/dense half, uniform ${u0.toPrecision(3)}/${u1.toPrecision(3)}, painted ${d0.toPrecision(3)}/${d1.toPrecision(3)} (ratio dense/sparse ${(d1 / d0).toFixed(3)})`);
  assert.ok(d1 / d0 < 0.6, `the dense half has smaller panels (${(d1 / d0).toFixed(3)})`);
  assert.equal(json(s.setDensity(density)).ok, true);
  assert.equal(s.done(), true, 'the same field again changes nothing');
  // setParams keeps the field: a cold replay of the same calls gives the same OBJ.
  const t = new ff.Session();
  json(t.loadShape('saddle', 4000));
  json(t.setParams(JSON.stringify({ panels: 60, seed: 1 })));
  solve(t);
  json(t.setDensity(density));
  json(t.setParams(JSON.stringify({ panels: 60, seed: 1 })));
  solve(t);
  const replayed = t.objText();
  s.resetSolve();
  json(s.setDensity(new Float64Array(0)));
  json(s.setParams(JSON.stringify({ panels: 60, seed: 1 })));
  solve(s);
  assert.equal(s.objText(), uniform, 'uniform again after resetting the field');
  json(s.setDensity(density));
  json(s.setParams(JSON.stringify({ panels: 60, seed: 1 })));
  solve(s);
  assert.equal(s.objText(), replayed, 'the same calls give the same panels');
  // A new mesh drops the field (its length would not fit).
  const info = json(s.loadShape('barrel_vault', 1500));
  assert.equal(json(s.setParams(JSON.stringify({ panels: 30 }))).ok, true);
  solve(s);
  assert.equal(json(s.reportJson()).panels, 30);
  assert.notEqual(info.vertices, density.length);
  s.delete();
  t.delete();
});

test('expressionDensity: the expression per vertex, as the solver multiplies it with the paint', () => {
  const s = new ff.Session();
  assert.equal(s.expressionDensity('1 + 3 * u').length, 0, 'no mesh: no values');
  const info = json(s.loadShape('saddle', 2000));
  assert.equal(info.ok, true);
  const p = s.inputPositions();
  let lo = Infinity;
  let hi = -Infinity;
  for (let i = 0; i < p.length; i += 3) lo = Math.min(lo, p[i]), hi = Math.max(hi, p[i]);
  const values = s.expressionDensity('1 + 3 * u');
  assert.equal(values.length, info.vertices);
  for (let v = 0; v < info.vertices; v++) {
    const u = (p[v * 3] - lo) / (hi - lo);
    assert.ok(Math.abs(values[v] - (1 + 3 * u)) < 1e-5, `vertex ${v}: ${values[v]} vs ${1 + 3 * u}`);
  }
  assert.ok(s.expressionDensity('1 + 2 * min(curv, 4)').every((x) => x >= 1 && x <= 9), 'curvature expressions evaluate too');
  // border: 0 on the saddle's edge (the largest value of the preset, 4), 1 nowhere on an open
  // surface, so the preset stays within (1, 4].
  const border = s.expressionDensity('1 + 3 * exp(-border / 0.05)');
  assert.equal(border.length, info.vertices);
  assert.ok(border.every((x) => x > 1 && x <= 4), 'the border preset within (1, 4]');
  assert.equal(Math.max(...border), 4, 'vertices on the edge');
  assert.ok(border.filter((x) => x === 4).length < info.vertices / 4, 'most vertices are inside');
  assert.equal(s.expressionDensity('').length, 0);
  assert.equal(s.expressionDensity('1 +').length, 0, 'a refused expression: none (the solve says why)');
  assert.equal(s.expressionDensity('u - 1').length, 0, 'values that are not > 0: none');
  s.delete();
});
