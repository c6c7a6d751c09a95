// A Rhino file on the page: a .3dm written here by rhino3dm (a wavy NURBS roof, a NURBS
// cylinder, a curve) is opened, its objects listed in the "Rhino object" select, all of them
// prepared (the note says they do not join), then the roof alone picked, remeshed and
// exported: valid, exactly planar panels. Run after `npm run build`.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import rhino3dm from 'rhino3dm';
import { browserSuite, download, maxPlanarity, parseObj, remesh, screenshot, setPanels, solveAfter, waitForDone } from './harness.mjs';

const suite = browserSuite();

async function rhinoFile() {
  const rh = await rhino3dm();
  const doc = new rh.File3dm();
  const named = (name) => {
    const a = new rh.ObjectAttributes();
    a.name = name;
    return a;
  };
  // A 6 x 6 bicubic roof over 12 x 9 m with two bumps.
  const roof = rh.NurbsSurface.create(3, false, 4, 4, 6, 6);
  for (let i = 0; i < 6; i++)
    for (let j = 0; j < 6; j++) roof.points().set(i, j, [(12 * i) / 5, (9 * j) / 5, 2 * Math.sin(i * 1.1) * Math.cos(j * 0.9) + 4, 1]);
  const knots = [0, 0, 0, 1, 2, 3, 3, 3]; // Rhino's convention: count + degree - 1
  knots.forEach((k, index) => {
    roof.knotsU().set(index, k);
    roof.knotsV().set(index, k);
  });
  doc.objects().add(roof, named('Roof'));
  doc.objects().add(new rh.Cylinder(new rh.Circle([20, 0, 0], 2), 6).toNurbsSurface(), named('Tower'));
  doc.objects().add(new rh.LineCurve([0, 0, 0], [1, 0, 0]), named('Axis'));
  return Buffer.from(doc.toByteArray());
}

test('a Rhino file opens, its objects are listed, the roof alone panels to valid planar panels', () =>
  suite.withPage(suite.url, async (page) => {
    await waitForDone(page);
    const buffer = await rhinoFile();
    const started = Date.now();
    await setPanels(page, 40);
    await solveAfter(page, () => page.getByLabel('Open mesh').setInputFiles({ name: 'campus.3dm', mimeType: 'application/octet-stream', buffer }), 180_000);
    const openSeconds = (Date.now() - started) / 1000;
    const picker = page.getByLabel('Rhino object');
    assert.deepEqual(await picker.locator('option').allTextContents(), ['All (joined): 2 objects', 'Roof — NURBS surface', 'Tower — NURBS surface', 'Axis — curve']);
    assert.equal(await picker.inputValue(), 'all');
    const note = page.getByRole('note').filter({ hasText: 'Prepared from campus' });
    const allNote = await note.textContent();
    assert.match(allNote, /tessellated NURBS surface 'Roof' into [\d,]+ triangles/);
    assert.match(allNote, /tessellated NURBS surface 'Tower' into [\d,]+ triangles/);
    assert.match(allNote, /left out 1 object that is not a surface \(curve\)/);
    assert.match(allNote, /did not all join: 2 separate parts/);
    const loadMs = Number(await page.evaluate(() => document.body.dataset.rhinoLoadMs));
    console.log(`rhino3dm loaded in ${loadMs} ms; open + prepare + first solve ${openSeconds.toFixed(1)} s`);
    assert.ok(loadMs > 0);

    // The roof alone.
    await picker.selectOption({ label: 'Roof — NURBS surface' });
    await solveAfter(page, () => page.getByRole('button', { name: 'Use object' }).click(), 180_000);
    const roofNote = await note.textContent();
    assert.match(roofNote, /tessellated NURBS surface 'Roof' into [\d,]+ triangles/);
    assert.match(roofNote, /one connected surface of [\d,]+ triangles/);
    assert.doesNotMatch(roofNote, /Tower/);
    assert.equal(await picker.inputValue(), '0');
    assert.match(roofNote, /^Prepared from campus \[Roof\]\.3dm: /); // the pick travels in the name (links, stored session)
    await setPanels(page, 60);
    assert.equal(await solveAfter(page, () => remesh(page), 180_000), 60);
    const obj = await download(page, 'Export OBJ');
    const parsed = parseObj(obj.text);
    assert.equal(parsed.faces.length, 60);
    assert.ok(maxPlanarity(parsed) <= 1e-9, `planarity ${maxPlanarity(parsed)}`);
    // The panels cover the roof, not the tower: every vertex near the roof's 12 x 9 footprint
    // (border vertices sit where panel planes meet, a little off the surface's edge).
    const margin = 0.5;
    for (const [x, y] of parsed.vertices) assert.ok(x > -margin && x < 12 + margin && y > -margin && y < 9 + margin, `vertex ${x}, ${y}`);
    console.log(`roof: 60 panels, planarity ${maxPlanarity(parsed).toExponential(2)}`);
    const shot = await screenshot(page, 'rhino-roof');
    console.log(`screenshot: ${shot}`);
  }));
