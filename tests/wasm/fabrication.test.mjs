// Fabrication in the wasm Session (setFabrication and its outputs): errors by name, the parts
// list's totals against the quality report, cut sheets (SVG well formed, DXF through
// dxf-parser with one closed cut polyline per panel), solid panels and the thick-panel view.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import DxfParser from 'dxf-parser';
import { json, loadModule, parseObj, solve } from './module.mjs';

const ff = await loadModule();

function solved(shape = 'groin_vault', panels = 30) {
  const s = new ff.Session();
  assert.equal(json(s.loadShape(shape, 4000)).ok, true);
  assert.equal(json(s.setParams(JSON.stringify({ panels }))).ok, true);
  solve(s);
  s.keepPanels(); // as the worker does when it shows the result
  return s;
}

function isStatus(text) {
  return text.startsWith('{') && json(text).ok === false;
}

// Enough of XML to catch a broken document: balanced tags, quoted attributes, one root.
function checkWellFormed(xml) {
  const body = xml.replace(/<\?xml[^>]*\?>/, '').replace(/<!--[\s\S]*?-->/g, '');
  const stack = [];
  let roots = 0;
  for (const m of body.matchAll(/<(\/?)([A-Za-z][\w:.-]*)((?:\s+[\w:.-]+\s*=\s*(?:"[^"]*"|'[^']*'))*)\s*(\/?)>|<|>/g)) {
    if (m[0] === '<' || m[0] === '>') {
      // A bare angle bracket outside a tag: only '>' may appear in text.
      assert.notEqual(m[0], '<', `stray '<' near ${body.slice(m.index, m.index + 40)}`);
      continue;
    }
    const [, close, name, , self] = m;
    if (close) assert.equal(stack.pop(), name, `</${name}> closes the wrong element`);
    else if (!self) {
      if (stack.length === 0) roots += 1;
      stack.push(name);
    } else if (stack.length === 0) roots += 1;
  }
  assert.deepEqual(stack, [], 'unclosed elements');
  assert.equal(roots, 1, 'one root element');
}

test('setFabrication refuses bad settings by name and keeps the previous ones', () => {
  const s = solved('saddle', 20);
  assert.equal(json(s.setFabrication(JSON.stringify({ thickness: 20, units: 'mm' }))).ok, true);
  const cases = [
    [{ thickness: -1 }, /'thickness'/],
    [{ thickness: '20' }, /'thickness'/],
    [{ side: 'middle' }, /'side'/],
    [{ units: 'yd' }, /'units'/],
    [{ meshUnits: 3 }, /'meshUnits'/],
    [{ sheetWidth: 0 }, /'sheetWidth'/],
    [{ sheetHeight: -5 }, /'sheetHeight'/],
    [{ kerf: 3 }, /'kerf'/],
  ];
  for (const [settings, pattern] of cases) {
    const status = json(s.setFabrication(JSON.stringify(settings)));
    assert.equal(status.ok, false, JSON.stringify(settings));
    assert.match(status.message, pattern);
  }
  assert.equal(json(s.setFabrication('not json')).ok, false);
  // Still 20 mm.
  assert.equal(json(s.partsJson()).thickness, 20);
  s.delete();
});

test('the parts list JSON totals equal the quality report area, in the chosen units', () => {
  const s = solved();
  const report = json(s.reportJson());
  const area = report.panel_area;
  assert.equal(typeof area, 'number', `report keys: ${Object.keys(report).join(', ')}`);
  const metres = json(s.partsJson());
  assert.equal(metres.totals.panels, report.panels);
  assert.ok(Math.abs(metres.totals.area - area) <= 1e-9 * area, `${metres.totals.area} vs ${area}`);
  assert.equal(json(s.setFabrication(JSON.stringify({ units: 'mm', meshUnits: 'm', thickness: 20 }))).ok, true);
  const mm = json(s.partsJson());
  assert.equal(mm.units, 'mm');
  assert.ok(Math.abs(mm.totals.area - area * 1e6) <= 1e-6 * area * 1e6);
  const rows = s.partsCsv().trim().split('\n');
  assert.equal(rows.length, 1 + report.panels + 1);
  s.delete();
});

test('cut sheets: the SVG is well formed and the DXF has one closed cut polyline per panel', () => {
  const s = solved();
  // The vault is some 10 m across: read as centimetres, its panels fit a 2440 x 1220 mm board.
  assert.equal(json(s.setFabrication(JSON.stringify({ units: 'mm', meshUnits: 'cm', thickness: 2, sheetWidth: 2440, sheetHeight: 1220 }))).ok, true);
  const panels = json(s.reportJson()).panels;
  const svg = s.sheetsSvg();
  assert.ok(svg.includes('<svg'), svg.slice(0, 200));
  checkWellFormed(svg);
  assert.equal((svg.match(/class="outer"/g) ?? []).length, panels);
  const stats = json(s.sheetStats());
  assert.equal(stats.ok, true);
  assert.ok(stats.sheets >= 1 && stats.materialUse > 0 && stats.materialUse <= 1, JSON.stringify(stats));

  const dxf = new DxfParser().parseSync(s.sheetsDxf());
  assert.equal(dxf.header.$INSUNITS, 4, 'millimetres');
  const cuts = dxf.entities.filter((e) => (e.type === 'POLYLINE' || e.type === 'LWPOLYLINE') && /^SHEET_\d+$/.test(e.layer));
  assert.equal(cuts.length, panels);
  for (const p of cuts) assert.equal(p.shape, true, `open polyline on ${p.layer}`);

  // A sheet too small for a part: the sheets fail by themselves, with a message.
  assert.equal(json(s.setFabrication(JSON.stringify({ units: 'mm', sheetWidth: 10, sheetHeight: 10 }))).ok, true);
  assert.ok(isStatus(s.sheetsSvg()));
  assert.ok(isStatus(s.sheetsDxf()));
  assert.ok(!isStatus(s.partsCsv()));
  s.delete();
});

test('solid panels and the thick view need a thickness; nodes report their spread', () => {
  const s = solved('saddle', 24);
  assert.match(json(s.solidObj()).message, /thickness/);
  assert.equal(s.innerPositions().length, 0);
  assert.equal(json(s.setFabrication(JSON.stringify({ thickness: 20, units: 'mm', meshUnits: 'm' }))).ok, true);
  const panels = s.panelOffsets().length - 1;
  const obj = parseObj(s.solidObj());
  // A prism per panel: outer + inner + one quad per edge.
  const corners = s.panelIndices().length;
  assert.equal(obj.faces.length, 2 * panels + corners);
  const inner = s.innerPositions();
  assert.equal(inner.length, 3 * corners);
  // Inner corners lie 20 mm (0.02 m) from their panel's outer plane.
  const positions = s.panelPositions();
  const offsets = s.panelOffsets();
  const indices = s.panelIndices();
  const p0 = [0, 1, 2].map((k) => positions[3 * indices[0] + k]);
  const p1 = [0, 1, 2].map((k) => positions[3 * indices[1] + k]);
  const p2 = [0, 1, 2].map((k) => positions[3 * indices[2] + k]);
  const u = p1.map((v, k) => v - p0[k]);
  const w = p2.map((v, k) => v - p0[k]);
  const n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
  const len = Math.hypot(...n);
  for (let c = offsets[0]; c < offsets[1]; c++) {
    const d = Math.abs(n.reduce((acc, v, k) => acc + (v / len) * (inner[3 * c + k] - p0[k]), 0));
    assert.ok(Math.abs(d - 0.02) < 1e-6, `inner corner ${c} is ${d} m from the outer plane`);
  }
  const spread = json(s.spreadNodes());
  assert.equal(spread.ok, true);
  assert.equal(spread.units, 'mm');
  assert.ok(spread.maxSpread >= 0);
  for (const node of spread.nodes) {
    assert.equal(node.position.length, 3);
    assert.ok(node.spread > 0 && node.spread <= spread.maxSpread + 1e-12);
    assert.ok(node.panels.length >= 4, 'only nodes of 4+ panels spread');
  }
  s.delete();
});

// Folded parts by label (for people) and by panel index (for the view): the same parts, and
// exactly those whose inner outline, seen along the panel's outward normal, is not a
// counter-clockwise simple polygon like the outer one.
test('parts folded by a thickness too large are listed by label and by panel', () => {
  const s = solved('helicoid', 40);
  assert.equal(json(s.setFabrication(JSON.stringify({ thickness: 4000, units: 'mm', meshUnits: 'm' }))).ok, true);
  const spread = json(s.spreadNodes());
  assert.ok(spread.folded.length > 0, 'the helicoid at 4 m folds some parts');
  assert.deepEqual(spread.foldedPanels.map((p) => `P${p + 1}`), spread.folded);
  const positions = s.panelPositions();
  const offsets = s.panelOffsets();
  const indices = s.panelIndices();
  const inner = s.innerPositions();
  for (let p = 0; p + 1 < offsets.length; p++) {
    const outer = [];
    for (let c = offsets[p]; c < offsets[p + 1]; c++) outer.push([0, 1, 2].map((k) => positions[3 * indices[c] + k]));
    const innerRing = [];
    for (let c = offsets[p]; c < offsets[p + 1]; c++) innerRing.push([0, 1, 2].map((k) => inner[3 * c + k]));
    const normal = newellNormal(outer);
    // Clockwise, self-crossing, or an inner edge running against its outer edge (a thin part's
    // inner face turned half round stays simple and counter-clockwise).
    const reversed = outer.some((a, i) => {
      const b = outer[(i + 1) % outer.length];
      const c = innerRing[i];
      const d = innerRing[(i + 1) % innerRing.length];
      // By more than the 1 mm a cut is made to (the mesh is in metres).
      return !((d[0] - c[0]) * (b[0] - a[0]) + (d[1] - c[1]) * (b[1] - a[1]) + (d[2] - c[2]) * (b[2] - a[2]) > 0) && Math.hypot(d[0] - c[0], d[1] - c[1], d[2] - c[2]) > 0.001;
    });
    const folded = !(signedArea(innerRing, normal) > 0 && isSimple(innerRing, normal)) || reversed;
    assert.equal(spread.foldedPanels.includes(p), folded, `panel P${p + 1}`);
  }
  s.delete();
});

function newellNormal(ring) {
  const n = [0, 0, 0];
  ring.forEach((a, i) => {
    const b = ring[(i + 1) % ring.length];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  });
  const len = Math.hypot(...n);
  return n.map((v) => v / len);
}

// The ring in 2D coordinates of the plane with normal n (right-handed: counter-clockwise
// seen from n's side stays counter-clockwise).
function flatten(ring, n) {
  const helper = Math.abs(n[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0];
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const u = cross(helper, n);
  const ul = Math.hypot(...u);
  const e1 = u.map((v) => v / ul);
  const e2 = cross(n, e1);
  return ring.map((p) => [p[0] * e1[0] + p[1] * e1[1] + p[2] * e1[2], p[0] * e2[0] + p[1] * e2[1] + p[2] * e2[2]]);
}

function signedArea(ring, n) {
  const q = flatten(ring, n);
  let area = 0;
  q.forEach((a, i) => {
    const b = q[(i + 1) % q.length];
    area += a[0] * b[1] - b[0] * a[1];
  });
  return area / 2;
}

// No two non-adjacent edges cross (proper crossings; touching counts as crossing).
function isSimple(ring, n) {
  const q = flatten(ring, n);
  const orient = (a, b, c) => (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  const m = q.length;
  for (let i = 0; i < m; i++)
    for (let j = i + 1; j < m; j++) {
      if (j === i + 1 || (i === 0 && j === m - 1)) continue;
      const [a, b, c, d] = [q[i], q[(i + 1) % m], q[j], q[(j + 1) % m]];
      if (orient(a, b, c) * orient(a, b, d) <= 0 && orient(c, d, a) * orient(c, d, b) <= 0) return false;
    }
  return true;
}

test('fabrication reads the kept panels: a later solve, finished or cancelled half-way, or a new mesh does not change them', () => {
  const s = solved('groin_vault', 30);
  assert.equal(json(s.setFabrication('{}')).ok, true);
  const kept = s.partsCsv();
  assert.equal(json(s.partsJson()).totals.panels, 30);
  // Another count solved afresh, a few steps in (the page cancels here and shows the 30 panels).
  assert.equal(json(s.setParams(JSON.stringify({ panels: 20 }))).ok, true);
  s.resetSolve();
  for (let i = 0; i < 5; i++) json(s.step());
  assert.equal(s.done(), false, 'still solving');
  assert.equal(s.partsCsv(), kept);
  // Finished: still the kept ones until the result is kept.
  solve(s);
  assert.equal(json(s.reportJson()).panels, 20);
  assert.equal(s.partsCsv(), kept);
  s.keepPanels();
  assert.equal(json(s.partsJson()).totals.panels, 20);
  // Loads and preparations leave them (the worker knows which design they are of) until the
  // next keep.
  const twenty = s.partsCsv();
  assert.equal(json(s.loadMesh('broken.off', new TextEncoder().encode('OFF\n3 1 0\n0 0 0\n'))).ok, false);
  assert.equal(json(s.prepareAsLoaded()).ok, true);
  assert.equal(json(s.loadShape('saddle', 2000)).ok, true);
  assert.equal(s.partsCsv(), twenty);
  s.keepPanels(); // no solve on the new mesh yet: no panels
  assert.equal(json(s.partsJson()).totals.panels, 0);
  assert.equal(json(s.setParams(JSON.stringify({ panels: 12 }))).ok, true);
  solve(s);
  s.keepPanels();
  assert.equal(json(s.partsJson()).totals.panels, 12);
  s.delete();
});

test('without panels the fabrication outputs are empty, not errors', () => {
  const s = new ff.Session();
  assert.equal(json(s.setFabrication('{}')).ok, true);
  assert.equal(json(s.partsJson()).totals.panels, 0);
  assert.ok(!isStatus(s.partsCsv()));
  assert.equal(json(s.spreadNodes()).nodes.length, 0);
  assert.deepEqual(json(s.spreadNodes()).foldedPanels, []);
  assert.equal(s.innerPositions().length, 0);
  s.delete();
});
