// A procedural anisotropy direction through Session.setParams (core/density/
// direction_expression.h): "1, 0, 0" gives the very panels of direction x, another expression
// other panels; a vortex solves to valid panels with its isotropic triangles in the report; a
// bad expression is refused naming the component and the column, and changes nothing.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { json, loadModule, parseObj, solve } from './module.mjs';

const ff = await loadModule();

// Sum over panels of their extent along the vortex "0.5 - v, u - 0.5, 0" at their centroid
// (u v scale x and y by the plan's size) over their extent across it.
function tangentialOverRadial(objText) {
  const { vertices, faces } = parseObj(objText);
  let lo = [Infinity, Infinity];
  let hi = [-Infinity, -Infinity];
  for (const v of vertices) {
    lo = [Math.min(lo[0], v[0]), Math.min(lo[1], v[1])];
    hi = [Math.max(hi[0], v[0]), Math.max(hi[1], v[1])];
  }
  const mid = [(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2];
  let tangential = 0;
  let radial = 0;
  for (const f of faces) {
    const pts = f.map((i) => vertices[i]);
    const c = [0, 1].map((k) => pts.reduce((sum, p) => sum + p[k], 0) / pts.length);
    const r = [c[0] - mid[0], c[1] - mid[1]];
    if (Math.hypot(...r) === 0) continue;
    const d = [-r[1] / (hi[1] - lo[1]), r[0] / (hi[0] - lo[0])];
    const along = (dir) => {
      const n = Math.hypot(...dir);
      const proj = pts.map((p) => ((p[0] - c[0]) * dir[0] + (p[1] - c[1]) * dir[1]) / n);
      return Math.max(...proj) - Math.min(...proj);
    };
    tangential += along(d);
    radial += along([d[1], -d[0]]);
  }
  return tangential / radial;
}

function solved(shape, triangles, params) {
  const s = new ff.Session();
  assert.equal(json(s.loadShape(shape, triangles)).ok, true);
  const status = json(s.setParams(JSON.stringify(params)));
  assert.equal(status.ok, true, status.message);
  solve(s);
  return s;
}

test('"1, 0, 0" is direction x; "0, 1, 0" is not', () => {
  const base = { panels: 40, seed: 3 };
  const x = solved('saddle', 3000, { ...base, anisotropy: { direction: 'x', stretch: 3 } });
  const e = solved('saddle', 3000, { ...base, anisotropy: { direction: 'expression', expression: '1, 0, 0', stretch: 3 } });
  const y = solved('saddle', 3000, { ...base, anisotropy: { direction: 'expression', expression: '0, 1, 0', stretch: 3 } });
  assert.equal(e.objText(), x.objText());
  assert.notEqual(y.objText(), x.objText());
  assert.equal('anisotropy_isotropic_faces' in json(x.reportJson()), false, 'reports without an expression stay as they were');
  assert.equal(json(e.reportJson()).anisotropy_isotropic_faces, 0);
  for (const s of [x, e, y]) s.delete();
});

test('a vortex solves to valid panels, elongated around the middle; the report counts undirected triangles', () => {
  const params = { panels: 60, seed: 1, anisotropy: { direction: 'expression', expression: '0.5 - v, u - 0.5, 0', stretch: 3 } };
  const s = solved('freeform_roof', 6000, params);
  const report = json(s.reportJson());
  assert.equal(report.invalid_panels.length ?? report.invalid_panels, 0);
  assert.equal(typeof report.anisotropy_isotropic_faces, 'number');
  assert.ok(report.anisotropy_isotropic_faces < 0.05 * report.triangles, `${report.anisotropy_isotropic_faces} of ${report.triangles}`);
  // An expression that is zero everywhere leaves every triangle undirected.
  const zero = solved('freeform_roof', 6000, { ...params, anisotropy: { ...params.anisotropy, expression: 'nz * 0, 0, 0' } });
  assert.equal(json(zero.reportJson()).anisotropy_isotropic_faces, report.triangles);
  // Panels elongated around the middle of the plan: their longer extent is tangential, unlike
  // the isotropic control's.
  const control = solved('freeform_roof', 6000, { ...params, anisotropy: { direction: 'none', stretch: 1 } });
  const ratio = tangentialOverRadial(s.objText());
  const controlRatio = tangentialOverRadial(control.objText());
  console.log(`vortex on the roof: mean tangential / radial panel extent ${ratio.toFixed(2)} (isotropic ${controlRatio.toFixed(2)})`);
  assert.ok(ratio > 1.25 && ratio > controlRatio + 0.25, `${ratio.toFixed(2)} vs ${controlRatio.toFixed(2)}`);
  control.delete();
  s.delete();
  zero.delete();
});

test('a bad direction expression is refused naming the component and column, and changes nothing', () => {
  const s = solved('saddle', 2000, { panels: 20, anisotropy: { direction: 'expression', expression: '-y, x, 0', stretch: 2 } });
  const before = s.objText();
  for (const [anisotropy, pattern] of [
    [{ direction: 'expression', expression: 'x, q, 0', stretch: 2 }, /'anisotropy\.expression': direction expression, component 2 \(y\) has unknown name 'q' at column 4/],
    [{ direction: 'expression', expression: 'x, y', stretch: 2 }, /needs three components/],
    [{ direction: 'expression', expression: `x, y, ${'('.repeat(100)}1${')'.repeat(100)}`, stretch: 2 }, /component 3 \(z\) is nested too deeply/],
    [{ direction: 'expression', expression: 'x'.repeat(5000), stretch: 2 }, /too long/],
    [{ direction: 'expression', stretch: 2 }, /'anisotropy\.expression' is missing/],
    [{ direction: 'x', expression: '1, 0, 0', stretch: 2 }, /only for direction "expression"/],
    [{ direction: 'expression', expression: '1, log(x - 1e9), 0', stretch: 2 }, /component 2 \(y\) gives NaN at face \d+/],
  ]) {
    const status = json(s.setParams(JSON.stringify({ panels: 20, anisotropy })));
    assert.equal(status.ok, false, JSON.stringify(anisotropy).slice(0, 80));
    assert.match(status.message, pattern);
    assert.equal(s.done(), true);
    assert.equal(s.objText(), before, 'the design is as it was');
  }
  s.delete();
});
