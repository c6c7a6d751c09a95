// The page's Rhino reading (web/src/rhino/rhinoConvert.ts, compiled to build/web-tests by
// `npm run test:web`) on hostile files, with rhino3dm itself: a mesh face naming a vertex its
// mesh does not have (rhino3dm keeps such a face) is left out, said, instead of joining the
// next object's vertices, a mesh with no usable face is not said to be "used as it is", and an
// empty Brep or an extrusion with no Brep form is said, not dropped without a word.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import rhino3dm from 'rhino3dm';
import { prepareRhino } from '../../build/web-tests/rhino/rhinoConvert.js';

const rh = await rhino3dm();

function fileOf(meshes) {
  const doc = new rh.File3dm();
  for (const { vertices, faces } of meshes) {
    const mesh = new rh.Mesh();
    for (const v of vertices) mesh.vertices().add(...v);
    for (const f of faces) mesh.faces().addTriFace(...f);
    doc.objects().add(mesh, new rh.ObjectAttributes());
  }
  return rh.File3dm.fromByteArray(doc.toByteArray());
}

test('a Rhino mesh face naming a vertex its mesh lacks is left out and said', () => {
  const first = { vertices: [[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0]], faces: [[0, 1, 3], [0, 1, 7]] };
  const second = { vertices: Array.from({ length: 8 }, (_, i) => [8, 8, i]), faces: [[0, 1, 2]] };
  const prepared = prepareRhino(rh, fileOf([first, second]), 'bad.3dm', 'all', 1000);
  assert.ok(prepared.ok, prepared.message);
  assert.deepEqual([...prepared.value.indices], [0, 1, 3, 4, 5, 6], 'not 0, 1, 11: a vertex of the second mesh');
  assert.ok(prepared.value.notes.includes("'Mesh 1': 1 face naming vertices the mesh does not have: left out"), prepared.value.notes.join(' | '));
  const none = prepareRhino(rh, fileOf([{ vertices: first.vertices, faces: [[0, 1, 9]] }]), 'none.3dm', 'all', 1000);
  assert.equal(none.ok, false);
  assert.match(none.message, /none\.3dm: nothing to panel: .*'Mesh 1' is a mesh with no usable faces: left out/);
});

test('an empty Brep and an extrusion with no Brep form are said, not dropped without a word', () => {
  const doc = new rh.File3dm();
  doc.objects().add(new rh.Brep(), new rh.ObjectAttributes());
  doc.objects().add(new rh.Extrusion(), new rh.ObjectAttributes());
  const mesh = new rh.Mesh();
  for (const v of [[0, 0, 0], [1, 0, 0], [0, 1, 0]]) mesh.vertices().add(...v);
  mesh.faces().addTriFace(0, 1, 2);
  doc.objects().add(mesh, new rh.ObjectAttributes());
  const file = rh.File3dm.fromByteArray(doc.toByteArray());
  const prepared = prepareRhino(rh, file, 'hollow.3dm', 'all', 1000);
  assert.ok(prepared.ok, prepared.message);
  const notes = prepared.value.notes.join(' | ');
  assert.match(notes, /'Brep 1' is a Brep with no faces: left out/);
  assert.match(notes, /'Extrusion 1' is an extrusion rhino3dm cannot turn into a Brep: left out/);
  assert.equal(prepared.value.objects, 1);
  // Alone, they are the refusal's reason.
  const alone = prepareRhino(rh, file, 'hollow.3dm', 0, 1000);
  assert.equal(alone.ok, false);
  assert.match(alone.message, /hollow\.3dm: nothing to panel: 'Brep 1' is a Brep with no faces/);
});
