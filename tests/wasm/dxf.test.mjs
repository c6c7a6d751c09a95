// The cut sheets' DXF read by a real DXF parser (dxf-parser from npm): the native CLI
// writes it (the fabrication module is not in the wasm build yet), and every panel must
// come back as one closed polyline inside its sheet's frame.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import DxfParser from 'dxf-parser';
import { meshes, parseObj, root } from './module.mjs';

const cli = process.env.FLATFACET ?? path.join(root, 'build/release/cli/flatfacet');

function runCli(args) {
  if (!existsSync(cli)) throw new Error(`${cli} is missing: build the native CLI first (cmake --build build/release)`);
  const run = spawnSync(cli, args, { encoding: 'utf8' });
  if (run.status !== 0 && /sheet/i.test(run.stderr) && /unknown|unrecognized|not an option/i.test(run.stderr)) {
    throw new Error(`the CLI has no --sheets / --sheet-size / --units flags yet (wire cut sheets into cli/): ${run.stderr.trim()}`);
  }
  assert.equal(run.status, 0, `flatfacet ${args.join(' ')} failed: ${run.stderr}`);
  return run;
}

// Layer SHEET_n holds sheet n's cuts, SHEET_n_FRAME its border, SHEET_n_INNER / _TEXT the rest.
function sheetOf(layer) {
  const m = /^SHEET_(\d+)(?:_(INNER|FRAME|TEXT))?$/.exec(layer ?? '');
  assert.ok(m, `entity on unexpected layer ${layer}`);
  return { sheet: Number(m[1]), kind: m[2] ?? 'CUT' };
}

test('the cut sheets DXF parses, with one closed polyline per panel inside its sheet', () => {
  const dir = mkdtempSync(path.join(tmpdir(), 'ff-dxf-'));
  try {
    const dxfPath = path.join(dir, 'out.dxf');
    const objPath = path.join(dir, 'panels.obj');
    runCli(['remesh', path.join(meshes, 'epcot.off'), '--panels', '30', '--out', objPath, '--sheets', dxfPath,
            '--sheet-size', '2440,1220', '--units', 'mm']);
    const panels = parseObj(readFileSync(objPath, 'utf8')).faces.length;
    assert.ok(panels > 0 && panels <= 30, `panels in the OBJ: ${panels}`);

    const dxf = new DxfParser().parseSync(readFileSync(dxfPath, 'utf8'));
    assert.ok(dxf && Array.isArray(dxf.entities), 'dxf-parser returned no entities');
    assert.equal(dxf.header.$ACADVER, 'AC1009');
    assert.equal(dxf.header.$INSUNITS, 4, 'millimetres');

    const polylines = dxf.entities.filter((e) => e.type === 'POLYLINE' || e.type === 'LWPOLYLINE');
    for (const p of polylines) {
      assert.equal(p.shape, true, `open polyline on ${p.layer}`);
      assert.ok(p.vertices.length >= 3, `polyline on ${p.layer} has ${p.vertices.length} vertices`);
      for (const v of p.vertices) assert.ok(Number.isFinite(v.x) && Number.isFinite(v.y), 'non-finite vertex');
    }
    const frames = new Map();
    for (const p of polylines) {
      const { sheet, kind } = sheetOf(p.layer);
      if (kind === 'FRAME') frames.set(sheet, p.vertices);
    }
    const cuts = polylines.filter((p) => sheetOf(p.layer).kind === 'CUT');
    assert.equal(cuts.length, panels, 'one closed cut polyline per panel');
    for (const p of cuts) {
      const frame = frames.get(sheetOf(p.layer).sheet);
      assert.ok(frame, `no frame for ${p.layer}`);
      const xs = frame.map((v) => v.x), ys = frame.map((v) => v.y);
      for (const v of p.vertices) {
        assert.ok(v.x >= Math.min(...xs) && v.x <= Math.max(...xs) && v.y >= Math.min(...ys) && v.y <= Math.max(...ys),
          `a vertex of a cut on ${p.layer} lies outside its sheet`);
      }
    }
    const labels = dxf.entities.filter((e) => e.type === 'TEXT' && /^P\d+$/.test(e.text));
    assert.equal(labels.length, panels, 'one label per panel');
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
