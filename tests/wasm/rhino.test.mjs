// Rhino files through the page's conversion (web/src/rhino/rhinoConvert.ts, compiled by
// web/tsconfig.unit.json) and the wasm Session's NURBS tessellation: a .3dm written here by
// rhino3dm (a NURBS cylinder, a capped cylinder Brep, two patches sharing an edge, a mesh, a
// curve), read back, converted, tessellated, and solved to valid panels.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import rhino3dm from 'rhino3dm';
import { json, loadModule, maxPlanarity, parseObj, root, solve } from './module.mjs';

execFileSync(process.execPath, [path.join(root, 'node_modules/typescript/bin/tsc'), '-p', path.join(root, 'web/tsconfig.unit.json')]);
const { listRhinoObjects, prepareRhino } = await import(pathToFileURL(path.join(root, 'build/web-tests/rhino/rhinoConvert.js')).href);

const started = performance.now();
const rh = await rhino3dm();
const rhinoLoadMs = performance.now() - started;
const ff = await loadModule();

const R = 2;
const H = 3;

function attributes(name) {
  const a = new rh.ObjectAttributes();
  a.name = name;
  return a;
}

// A planar bilinear patch from x0 to x1 (y 0..1, z 0).
function patch(x0, x1) {
  const s = rh.NurbsSurface.create(3, false, 2, 2, 2, 2);
  const corners = [[x0, 0], [x0, 1], [x1, 0], [x1, 1]];
  s.points().set(0, 0, [x0, 0, 0, 1]);
  s.points().set(0, 1, [x0, 1, 0, 1]);
  s.points().set(1, 0, [x1, 0, 0, 1]);
  s.points().set(1, 1, [x1, 1, 0, 1]);
  assert.equal(corners.length, 4);
  s.knotsU().set(0, 0);
  s.knotsU().set(1, 1);
  s.knotsV().set(0, 0);
  s.knotsV().set(1, 1);
  return s;
}

// A closed cylinder Brep whose three faces carry render meshes that meet (as Rhino would save
// them): a 48 x 6 grid around, fans on the caps through the same rim points.
function meshedSilo(cylinder) {
  const brep = rh.Brep.createFromCylinder(cylinder, true, true);
  const N = 48;
  const M = 6;
  const rim = (i, z) => [R * Math.cos((2 * Math.PI * i) / N), R * Math.sin((2 * Math.PI * i) / N), z];
  const side = new rh.Mesh();
  for (let j = 0; j <= M; j++) for (let i = 0; i < N; i++) side.vertices().add(...rim(i, (H * j) / M));
  for (let j = 0; j < M; j++) for (let i = 0; i < N; i++) side.faces().addQuadFace(j * N + i, j * N + ((i + 1) % N), (j + 1) * N + ((i + 1) % N), (j + 1) * N + i);
  const cap = (z) => {
    const m = new rh.Mesh();
    m.vertices().add(0, 0, z);
    for (let i = 0; i < N; i++) m.vertices().add(...rim(i, z));
    for (let i = 0; i < N; i++) m.faces().addTriFace(0, 1 + i, 1 + ((i + 1) % N));
    return m;
  };
  // rhino3dm's setMesh takes (mesh, type), whatever its .d.ts says.
  brep.faces().get(0).setMesh(side, rh.MeshType.Render);
  brep.faces().get(1).setMesh(cap(0), rh.MeshType.Render);
  brep.faces().get(2).setMesh(cap(H), rh.MeshType.Render);
  return brep;
}

function writeFile() {
  const doc = new rh.File3dm();
  const cylinder = new rh.Cylinder(new rh.Circle([0, 0, 0], R), H);
  doc.objects().add(cylinder.toNurbsSurface(), attributes('Vault'));
  doc.objects().add(rh.Brep.createFromCylinder(cylinder, true, true), attributes('Tank'));
  doc.objects().add(patch(5, 6), attributes('Left'));
  doc.objects().add(patch(6, 7), attributes('Right'));
  const mesh = new rh.Mesh();
  for (let i = 0; i < 3; i++) for (let j = 0; j < 3; j++) mesh.vertices().add(10 + i, j, 0.1 * i * j);
  for (let i = 0; i < 2; i++) for (let j = 0; j < 2; j++) mesh.faces().addQuadFace(i * 3 + j, (i + 1) * 3 + j, (i + 1) * 3 + j + 1, i * 3 + j + 1);
  doc.objects().add(mesh, attributes('Slab'));
  doc.objects().add(new rh.LineCurve([0, 0, 0], [1, 0, 0]), attributes('Axis'));
  doc.objects().add(meshedSilo(cylinder), attributes('Silo'));
  return doc.toByteArray();
}

const bytes = writeFile();
const doc = rh.File3dm.fromByteArray(bytes);

function load(pick, target = 8000) {
  const prepared = prepareRhino(rh, doc, 'test.3dm', pick, target);
  assert.equal(prepared.ok, true, prepared.message);
  const s = new ff.Session();
  const info = json(s.loadSurfaces('test.3dm', JSON.stringify(prepared.value.set), prepared.value.positions, prepared.value.indices));
  assert.equal(info.ok, true, info.message);
  return { s, info, prepared: prepared.value };
}

test('rhino3dm loads and lists the objects by name and type', () => {
  console.log(`rhino3dm: module ready in ${rhinoLoadMs.toFixed(0)} ms; the test file is ${bytes.length} bytes`);
  const objects = listRhinoObjects(rh, doc);
  assert.deepEqual(
    objects.map((o) => [o.name, o.type, o.supported]),
    [
      ['Vault', 'NURBS surface', true],
      ['Tank', 'Brep (3 faces)', true],
      ['Left', 'NURBS surface', true],
      ['Right', 'NURBS surface', true],
      ['Slab', 'Mesh (4 faces)', true],
      ['Axis', 'curve', false],
      ['Silo', 'Brep (3 faces)', true],
    ],
  );
});

test('a NURBS cylinder is tessellated on its radius, welded along its seam', () => {
  const { s, info, prepared } = load(0);
  const surface = prepared.set.surfaces[0];
  assert.equal(surface.degreeU, 2);
  assert.equal(surface.knotsU.length, surface.countU + surface.degreeU - 1); // Rhino's convention
  assert.equal(info.surfaces.length, 1);
  assert.equal(info.surfaces[0].name, "'Vault'");
  assert.ok(info.surfaces[0].seamWelded > 0);
  assert.equal(info.components, 1);
  assert.equal(info.boundaryLoops, 2); // a tube: welded along the seam
  assert.equal(info.euler, 0);
  assert.ok(info.triangles > 4000 && info.triangles < 16000, `${info.triangles} triangles for a target of 8000`);
  const p = s.inputPositions(); // float32
  for (let i = 0; i < p.length; i += 3) {
    assert.ok(Math.abs(Math.hypot(p[i], p[i + 1]) - R) < 1e-5, `vertex ${i / 3} off the radius`);
    assert.ok(p[i + 2] >= -1e-6 && p[i + 2] <= H + 1e-6);
  }
  // Then panels, valid and planar.
  assert.equal(json(s.setParams(JSON.stringify({ panels: 40, seed: 1 }))).ok, true);
  solve(s);
  const report = json(s.reportJson());
  assert.equal(report.status, 'valid');
  assert.ok(report.max_planarity <= 1e-9);
  assert.ok(maxPlanarity(parseObj(s.objText())) <= 1e-9);
  s.delete();
});

test('trimmed Brep faces without render meshes are left out by name', () => {
  const prepared = prepareRhino(rh, doc, 'test.3dm', 1, 8000);
  assert.equal(prepared.ok, true);
  const notes = prepared.value.notes.join('\n');
  assert.match(notes, /'Tank': 1 of 3 faces untrimmed, tessellated from its NURBS surface/);
  assert.match(notes, /faces 1, 2 of 'Tank' are trimmed and the file has no render mesh for them: left out/);
  assert.equal(prepared.value.set.surfaces.length, 1);
  assert.equal(prepared.value.set.surfaces[0].name, "face 0 of 'Tank'");
});

test('a Brep meshed in full by the file joins into one closed surface', () => {
  const { s, info, prepared } = load(6);
  assert.match(prepared.notes.join('\n'), /'Silo': the render meshes of its 3 faces from the file/);
  assert.equal(prepared.set.surfaces.length, 0);
  assert.equal(info.components, 1);
  assert.equal(info.boundaryLoops, 0);
  assert.equal(info.genus, 0);
  s.delete();
});

test('surfaces sharing an edge join; a curve alone is refused by name', () => {
  // Left and Right only (through the Rhino objects the same way 'All' goes).
  const left = load(2);
  const bothPrepared = prepareRhino(rh, doc, 'test.3dm', 'all', 8000);
  assert.equal(bothPrepared.ok, true);
  assert.match(bothPrepared.value.notes.join('\n'), /left out 1 object that is not a surface \(curve\)/);
  const set = { ...bothPrepared.value.set, surfaces: bothPrepared.value.set.surfaces.filter((x) => x.name === "'Left'" || x.name === "'Right'") };
  const s = new ff.Session();
  const info = json(s.loadSurfaces('two.3dm', JSON.stringify(set), new Float64Array(0), new Uint32Array(0)));
  assert.equal(info.ok, true, info.message);
  assert.equal(info.components, 1, 'the two patches share an edge');
  assert.equal(info.boundaryLoops, 1);
  assert.equal(info.triangles, info.surfaces[0].triangles + info.surfaces[1].triangles, 'welding loses no triangle');
  assert.equal(left.info.components, 1);
  // Everything: separate objects stay separate parts, and the page says so from this.
  const all = load('all');
  assert.ok(all.info.components > 1);
  const axis = prepareRhino(rh, doc, 'test.3dm', 5, 8000);
  assert.equal(axis.ok, false);
  assert.match(axis.message, /'Axis' is a curve, not a surface: left out/);
  s.delete();
  left.s.delete();
  all.s.delete();
});

test('a bad surface description is refused by name and the previous mesh stays', () => {
  const { s, info } = load(0);
  const bad = { surfaces: [{ name: "'Roof'", degreeU: 1, degreeV: 1, countU: 2, countV: 2, knotsU: [0, 1], knotsV: [1, 0], points: [0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0] }] };
  const status = json(s.loadSurfaces('bad.3dm', JSON.stringify(bad), new Float64Array(0), new Uint32Array(0)));
  assert.equal(status.ok, false);
  assert.match(status.message, /bad\.3dm: 'Roof': v knots decrease/);
  assert.equal(s.inputIndices().length, 3 * info.triangles);
  s.delete();
});

test("the core evaluates a rational, unclamped Rhino surface where rhino3dm's own pointAt does", () => {
  // Degree 3 x 2, uneven weights, uniform unclamped knots in u (Rhino's count + degree - 1).
  const surface = rh.NurbsSurface.create(3, true, 4, 3, 7, 5);
  for (let i = 0; i < 7; i++)
    for (let j = 0; j < 5; j++) {
      const w = 0.5 + ((i * 3 + j * 7) % 5) / 4;
      surface.points().set(i, j, [i * w, j * w, Math.sin(i + j) * w, w]);
    }
  for (let k = 0; k < 9; k++) surface.knotsU().set(k, k);
  [0, 0, 1, 2, 3, 3].forEach((knot, k) => surface.knotsV().set(k, knot));
  const file = new rh.File3dm();
  file.objects().add(surface, attributes('Shell'));
  const back = rh.File3dm.fromByteArray(file.toByteArray());
  const prepared = prepareRhino(rh, back, 'shell.3dm', 0, 8000);
  assert.equal(prepared.ok, true, prepared.message);
  // One sample per knot span: the grid's points are the surface at the knots.
  const set = { ...prepared.value.set, edgeLength: 1e6 };
  delete set.targetTriangles;
  const s = new ff.Session();
  const info = json(s.loadSurfaces('shell.3dm', JSON.stringify(set), new Float64Array(0), new Uint32Array(0)));
  assert.equal(info.ok, true, info.message);
  assert.deepEqual([info.surfaces[0].samplesU, info.surfaces[0].samplesV], [4, 3]);
  const p = s.inputPositions();
  const shell = back.objects().get(0).geometry();
  const [u0, u1] = [shell.domain(0)[0], shell.domain(0)[1]];
  assert.deepEqual([u0, u1], [2, 6]);
  for (let u = 2; u <= 6; u++)
    for (const v of [0, 1, 2, 3]) {
      const expected = shell.pointAt(u, v);
      let best = Infinity;
      for (let i = 0; i < p.length; i += 3) best = Math.min(best, Math.hypot(p[i] - expected[0], p[i + 1] - expected[1], p[i + 2] - expected[2]));
      assert.ok(best < 1e-5, `(${u}, ${v}): nearest vertex ${best} from rhino3dm's point`);
    }
  s.delete();
});
