// Preparation on the page (issue 7): the coarse Yas Island grid shell (976 quads) is refined
// for its panels when opened and the Surface section says so; "Subdivide levels" opens it again
// subdivided (Catmull-Clark on its quads); a share link carries the preparation, so a fresh
// context prepares the same mesh and exports the very same OBJ. Run after `npm run build`.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { unzlibSync, zlibSync } from 'fflate';
import { browserSuite, download, errorAfter, exampleLink, maxPlanarity, parseObj, recordStatus, remesh, screenshot, selectExample, setPanels, solveAfter, statusText, waitForDone, waitForStatus } from './harness.mjs';

const suite = browserSuite();
// A quick start (the default example is a 50k-triangle tower, slow to solve here).
const quick = { panels: 30, seed: 1, weights: { euclidean: 1, l2: 1, l21: 1, boundary: 1 }, lloydIterations: 20, panelRounds: 30, seeding: 'farthest', teleport: true, singlePointNodes: false, optimizePlanes: true };

const cleanupNote = (page) => page.locator('#mesh-prepared').textContent();

test('a coarse mesh is refined for its panels, subdivided on request, and a link reproduces it', () =>
  suite.withPage(suite.url, async (page) => {
    await waitForDone(page);
    assert.equal(await solveAfter(page, () => selectExample(page, 'YasIsland')), 150);
    assert.match(await cleanupNote(page), /refined 1,952 triangles to [\d,]+ \(target edge [\d.]+\) so 150 panels get about [\d.]+ triangles each/);
    const refined = parseObj((await download(page, 'Export OBJ')).text);
    assert.equal(refined.faces.length, 150);
    assert.ok(maxPlanarity(refined) <= 1e-9);
    assert.match(await page.locator('#stats').textContent(), /Invalid\s*0\s*Topology\s*preserved/);

    assert.equal(await solveAfter(page, () => page.getByLabel('Subdivide levels').fill('1').then(() => page.getByLabel('Subdivide levels').blur())), 150);
    assert.match(await cleanupNote(page), /subdivided 976 polygons 1 level \(catmull-clark\) into 7,808 triangles/);
    const subdivided = (await download(page, 'Export OBJ')).text;
    assert.ok(maxPlanarity(parseObj(subdivided)) <= 1e-9);
    await screenshot(page, 'yasisland-subdivided');

    await page.getByRole('button', { name: 'Copy share link' }).click();
    await page.waitForFunction(() => location.hash.startsWith('#v1='));
    const link = await page.evaluate(() => location.href);
    await suite.withPage(link, async (opened) => {
      assert.equal(await waitForDone(opened), 150);
      assert.equal(await opened.getByLabel('Subdivide levels').inputValue(), '1');
      assert.match(await cleanupNote(opened), /subdivided 976 polygons 1 level/);
      assert.equal((await download(opened, 'Export OBJ')).text, subdivided, 'the link prepares the same mesh: the same OBJ bytes');
    });
  }));

// Issue 7: a panel count the prepared mesh cannot serve prepares it again, from the mesh as
// loaded, as one undoable step recorded in the design.
test('raising Panels prepares the mesh again: the note, valid panels, the same OBJ from the link, and undo', () =>
  suite.withPage(exampleLink(suite.url, 'saddle', quick), async (page) => {
    await waitForDone(page);
    assert.equal(await solveAfter(page, () => selectExample(page, 'YasIsland')), 150);
    const note150 = await cleanupNote(page);
    assert.match(note150, /so 150 panels get/);
    const obj150 = (await download(page, 'Export OBJ')).text;

    await setPanels(page, 1200);
    assert.equal(await solveAfter(page, () => remesh(page), 900_000), 1200);
    const note1200 = await cleanupNote(page);
    assert.match(note1200, /refined 1,952 triangles to [\d,]+ \(target edge [\d.]+\) so 1,200 panels get about [\d.]+ triangles each/);
    const triangles = Number(/([\d,]+) triangles/.exec(await page.locator('#mesh-details').textContent())[1].replace(/,/g, ''));
    assert.ok(triangles >= 1200 * 20, `${triangles} triangles for 1,200 panels`);
    assert.match(await page.locator('#stats').textContent(), /Invalid\s*0\s*Topology\s*preserved/);
    const obj1200 = (await download(page, 'Export OBJ')).text;
    const panels = parseObj(obj1200);
    assert.equal(panels.faces.length, 1200);
    assert.ok(maxPlanarity(panels) <= 1e-9);
    await screenshot(page, 'yasisland-prepared-1200');

    await page.getByRole('button', { name: 'Copy share link' }).click();
    await page.waitForFunction(() => location.hash.startsWith('#v1='));
    const link = await page.evaluate(() => location.href);
    await suite.withPage(link, async (opened) => {
      assert.equal(await waitForDone(opened, undefined, 900_000), 1200);
      assert.equal(await cleanupNote(opened), note1200);
      assert.equal((await download(opened, 'Export OBJ')).text, obj1200, 'the link prepares the same mesh: the same OBJ bytes');
    });

    assert.equal(await solveAfter(page, () => page.getByRole('button', { name: 'Undo' }).click(), 300_000), 150);
    assert.equal(await cleanupNote(page), note150, 'the mesh prepared for 150 panels again');
    assert.equal(await page.getByLabel('Panels', { exact: true }).inputValue(), '150');
    assert.equal((await download(page, 'Export OBJ')).text, obj150, 'undo gives back the very same panels');
  }));

// A link's payload (web/src/share.ts): u32 JSON length | JSON | mesh bytes | paint bytes.
function linkOf(url, json, meshBytes, paint) {
  const text = new TextEncoder().encode(JSON.stringify(json));
  const payload = new Uint8Array(4 + text.length + meshBytes.length + paint.length);
  new DataView(payload.buffer).setUint32(0, text.length, true);
  payload.set(text, 4);
  payload.set(meshBytes, 4 + text.length);
  payload.set(new Uint8Array(paint.buffer), 4 + text.length + meshBytes.length);
  return `${url}#v1=${Buffer.from(zlibSync(payload)).toString('base64url')}`;
}

function readLink(href) {
  const payload = unzlibSync(Buffer.from(href.slice(href.indexOf('#v1=') + 4), 'base64url'));
  const length = new DataView(payload.buffer, payload.byteOffset).getUint32(0, true);
  const json = JSON.parse(new TextDecoder().decode(payload.subarray(4, 4 + length)));
  const paintAt = 4 + length + (json.mesh.size ?? 0);
  return { json, paint: new Int8Array(payload.buffer, payload.byteOffset + paintAt, payload.length - paintAt) };
}

// The design on show's share link, read (its JSON and paint), once the address holds a link
// other than `unlike` (one the page had before; none: any link).
async function shareLink(page, unlike = null) {
  await page.getByRole('button', { name: 'Copy share link' }).click();
  await page.waitForFunction((unlike) => location.hash.startsWith('#v1=') && location.href !== unlike, unlike);
  return readLink(await page.evaluate(() => location.href));
}

// web/src/brush/densityField.ts fieldKey, the content key a link's field must hash to.
function fieldKey(field) {
  let a = 0x811c9dc5 ^ field.length;
  let b = 0x01000193 ^ Math.imul(field.length, 0x9e3779b1);
  for (let i = 0; i < field.length; i++) {
    const byte = field[i] & 0xff;
    a = Math.imul(a ^ byte, 0x01000193);
    b = Math.imul(b ^ byte, 0x5bd1e995);
    b ^= b >>> 15;
  }
  return (a >>> 0).toString(16).padStart(8, '0') + (b >>> 0).toString(16).padStart(8, '0');
}

// A flat 12 x 12 grid of quads (288 triangles) and a link that opens it for 4 panels, painted
// (level 32, 4x density, where x > 6) with one lock edit. `prepare`: the preparation the link
// records (default: for `panels`, as before refineBelow; null: none, as links made before
// preparations were recorded); with one of its own the link is unpainted (the paint would
// name the prepared mesh's vertices). `hole`: without a square of hole x hole quads (1: 286
// triangles, a hole of 4 edges; 4: 256 triangles, 16 edges, and the 9 vertices inside unused,
// so the link must not be painted); `repair`: the repair the link records.
const n = 12;
function gridLink({ edits = [{ op: 'lock', face: 0 }], panels = 4, prepare, hole = 0, repair } = {}) {
  const lines = [];
  for (let j = 0; j <= n; j++) for (let i = 0; i <= n; i++) lines.push(`v ${i} ${j} 0`);
  for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) {
    const lo = hole === 1 ? 5 : 4;
    if (i >= lo && i < lo + hole && j >= lo && j < lo + hole) continue; // a hole of 4 * hole edges
    const v = (a, b) => b * (n + 1) + a + 1;
    lines.push(`f ${v(i, j)} ${v(i + 1, j)} ${v(i + 1, j + 1)} ${v(i, j + 1)}`);
  }
  const bytes = new TextEncoder().encode(`${lines.join('\n')}\n`);
  const painted = !prepare;
  const paint = painted ? Int8Array.from({ length: (n + 1) * (n + 1) }, (_, k) => (k % (n + 1) > 6 ? 32 : 0)) : new Int8Array(0);
  const key = fieldKey(paint);
  const recorded = prepare === undefined ? { panels, subdivide: 0 } : prepare;
  const mesh = { file: 'grid.obj', size: bytes.length, ...(recorded ? { prepare: recorded } : {}), ...(repair ? { repair } : {}) };
  const params = { ...quick, panels, edits, ...(painted ? { paint: key } : {}) };
  const json = { v: 1, mesh, params, history: [], ...(painted ? { paint: [{ key, vertices: paint.length }] } : {}) };
  return { paint, link: linkOf(suite.url, json, bytes, paint) };
}

// A link saved before the rule went from 20 to 30 triangles per panel (its preparation has no
// refineBelow) at 12 panels: 24 per panel, which the rule now would refine. It opens on its own
// 288 triangles, so its lock and paint name the triangle and vertices they were made on, and
// solving again does not prepare it anew.
test('a design saved before the 30 keeps its mesh between 20 and 30 triangles per panel', () => {
  const { paint, link } = gridLink({ panels: 12 });
  return suite.withPage(link, async (page) => {
    assert.equal(await waitForDone(page), 12);
    assert.match(await page.locator('#mesh-details').textContent(), /^288 triangles/);
    assert.equal(await solveAfter(page, () => remesh(page)), 12);
    assert.match(await page.locator('#mesh-details').textContent(), /^288 triangles/);
    const shared = await shareLink(page);
    assert.deepEqual(shared.json.mesh.prepare, { panels: 12, subdivide: 0 }, 'still the rule before');
    assert.deepEqual(shared.json.params.edits, [{ op: 'lock', face: 0 }]);
    assert.deepEqual([...shared.paint], [...paint]);
  });
});

// A link saved before a refinement went from 10 remeshing rounds to 5 (its preparation has no
// refineRounds) at 30 panels: the grid refined to 2,192 triangles, where 5 rounds make 2,214
// (Session.prepare(30, 0, 0, 30, 10) and (..., 5) in Node). It opens on its own mesh, so its lock
// names the triangle it was made on, and keeps it through a solve; a new design at that count
// gets 5 rounds, and records them.
test('a design saved before the 5 remeshing rounds keeps its refined mesh', () => {
  const { link } = gridLink({ panels: 30, prepare: { panels: 30, subdivide: 0, refineBelow: 30 } });
  return suite.withPage(link, async (page) => {
    assert.equal(await waitForDone(page), 30);
    assert.match(await page.locator('#mesh-details').textContent(), /^2,192 triangles/);
    assert.equal(await solveAfter(page, () => remesh(page)), 30);
    assert.match(await page.locator('#mesh-details').textContent(), /^2,192 triangles/);
    const shared = await shareLink(page);
    assert.deepEqual(shared.json.mesh.prepare, { panels: 30, subdivide: 0, refineBelow: 30 }, 'still the rounds before');
    assert.deepEqual(shared.json.params.edits, [{ op: 'lock', face: 0 }]);
  });
});

test('a new design refined below 20 triangles per panel gets 5 remeshing rounds', () => {
  const { link } = gridLink({ edits: [] });
  return suite.withPage(link, async (page) => {
    assert.equal(await waitForDone(page), 4);
    await setPanels(page, 30);
    assert.equal(await solveAfter(page, () => remesh(page), 300_000), 30);
    assert.match(await page.locator('#mesh-details').textContent(), /^2,214 triangles/);
    assert.deepEqual((await shareLink(page)).json.mesh.prepare, { panels: 30, subdivide: 0, refineBelow: 30, refineRounds: 5 });
  });
});

// A link made before preparations were recorded, at 20 panels: 14.4 triangles each, on the
// mesh as loaded. Remesh prepares it (carrying the lock and paint); Undo brings back the mesh
// as loaded, which the lock and paint of the step before name, not a preparation by the rule
// of the time (that would be 1,152 triangles, and the lock replayed on another triangle).
test('undo to a design saved before preparations were recorded opens the mesh as loaded again', () => {
  const { paint, link } = gridLink({ panels: 20, prepare: null });
  return suite.withPage(link, async (page) => {
    assert.equal(await waitForDone(page), 20);
    assert.match(await page.locator('#mesh-details').textContent(), /^288 triangles/);
    assert.equal(await solveAfter(page, () => remesh(page), 300_000), 20);
    assert.doesNotMatch(await page.locator('#mesh-details').textContent(), /^288 triangles/, 'prepared for 20 panels');
    assert.equal(await solveAfter(page, () => page.getByRole('button', { name: 'Undo' }).click()), 20);
    assert.match(await page.locator('#mesh-details').textContent(), /^288 triangles/);
    const back = await shareLink(page, link);
    assert.ok(!('prepare' in back.json.mesh), 'no preparation, as the link had');
    assert.deepEqual(back.json.params.edits, [{ op: 'lock', face: 0 }]);
    assert.deepEqual([...back.paint], [...paint]);
    await screenshot(page, 'grid-undo-to-as-loaded');
    // Redo: the prepared mesh and its record again.
    assert.equal(await solveAfter(page, () => page.getByRole('button', { name: 'Redo' }).click(), 300_000), 20);
    assert.doesNotMatch(await page.locator('#mesh-details').textContent(), /^288 triangles/);
    const undone = page.url();
    assert.deepEqual((await shareLink(page, undone)).json.mesh.prepare, { panels: 20, subdivide: 0, refineBelow: 30, refineRounds: 5 });
  });
});

// The same design, with a worker whose preparation of an Undo or a Redo crashes (as running out
// of memory would) or is refused. The mesh on show is still the step's the move left, so the
// move is taken back: the history and the form are that step's again (not the other step's,
// whose lock and paint name the other mesh: Remesh would then be refused or lock another
// triangle), Remesh solves it on its own mesh, and the move works next time (the fault comes
// once). The Redo case prepares three times: the Remesh, the Undo, the Redo.
const history = (page) => page.evaluate(() => [Number(document.body.dataset.historyIndex), Number(document.body.dataset.historySize)]);
const faults = [
  { kind: 'crash', move: 'Undo', at: 2, said: /crashed and was restarted; the last result is kept; Undo was taken back / },
  { kind: 'refuse', move: 'Redo', at: 3, said: /^Error: the preparation was refused \(test hook \?refuseOnPrepare\); Redo was taken back / },
];
for (const { kind, move, at, said } of faults) {
  test(`${move === 'Undo' ? 'an' : 'a'} ${move} whose preparation ${kind === 'crash' ? 'crashes' : 'is refused'} is taken back: the design on show stays whole`, () => {
    const { link } = gridLink({ panels: 20, prepare: null });
    return suite.withPage(link.replace('#v1=', `?${kind}OnPrepare=${at}#v1=`), async (page) => {
      assert.equal(await waitForDone(page), 20);
      assert.equal(await solveAfter(page, () => remesh(page), 300_000), 20);
      assert.doesNotMatch(await page.locator('#mesh-details').textContent(), /^288 triangles/, 'prepared for 20 panels');
      if (move === 'Redo') {
        assert.equal(await solveAfter(page, () => page.getByRole('button', { name: 'Undo' }).click(), 300_000), 20);
        assert.match(await page.locator('#mesh-details').textContent(), /^288 triangles/);
      }
      const details = await page.locator('#mesh-details').textContent();
      const before = await history(page);
      assert.deepEqual(before, move === 'Undo' ? [1, 2] : [0, 2]);

      const message = await errorAfter(page, () => page.getByRole('button', { name: move }).click(), 60_000);
      assert.match(message, said);
      assert.match(message, new RegExp(`${move} was taken back \\(its mesh could not be prepared again\\)\\.?$`));
      assert.equal(await page.locator('#mesh-details').textContent(), details, 'the mesh is still the one on show');
      assert.deepEqual(await history(page), before, 'the history is back at the step on show');
      assert.equal(await page.getByRole('button', { name: 'Undo' }).isEnabled(), move === 'Undo');
      assert.equal(await page.getByRole('button', { name: 'Redo' }).isEnabled(), move === 'Redo');
      if (kind === 'crash') await screenshot(page, 'grid-undo-crash-taken-back');

      // The form is the step's on show: Remesh solves it (another step's paint would be refused
      // for its vertex count, on this mesh or carried from it). On the prepared mesh it is solved
      // there; on the mesh as loaded, 14.4 triangles per panel, Remesh prepares it as at first.
      assert.equal(await solveAfter(page, () => remesh(page), 300_000), 20);
      if (move === 'Undo') {
        assert.equal(await page.locator('#mesh-details').textContent(), details, 'solved on its own mesh, not prepared again');
        assert.equal(await solveAfter(page, () => page.getByRole('button', { name: 'Undo' }).click(), 300_000), 20);
        assert.match(await page.locator('#mesh-details').textContent(), /^288 triangles/, 'Undo to the mesh as loaded works now');
      } else {
        assert.doesNotMatch(await page.locator('#mesh-details').textContent(), /^288 triangles/, 'prepared, with the paint carried');
      }
    });
  });
}

// A parameter committed while the Undo prepares the mesh back (in the same task as the click, so
// before the worker can answer) is not recorded against the mesh on show: the crash takes the
// Undo back with the form, and the history has no step for it.
test('a parameter typed while an Undo prepares the mesh back goes with the Undo when it is taken back', () => {
  const { link } = gridLink({ panels: 20, prepare: null });
  return suite.withPage(link.replace('#v1=', '?crashOnPrepare=2#v1='), async (page) => {
    assert.equal(await waitForDone(page), 20);
    assert.equal(await solveAfter(page, () => remesh(page), 300_000), 20);
    const message = await errorAfter(page, () =>
      page.evaluate(() => {
        document.getElementById('undo').click();
        const seed = document.getElementById('seed');
        seed.value = '7';
        seed.dispatchEvent(new Event('change'));
      }),
    );
    assert.match(message, /Undo was taken back/);
    assert.deepEqual(await history(page), [1, 2], 'no step for the seed typed meanwhile');
    assert.equal(await page.getByLabel('Seed', { exact: true }).inputValue(), '1');
    assert.equal(await page.getByRole('button', { name: 'Redo' }).isEnabled(), false);
    assert.equal(await solveAfter(page, () => remesh(page), 300_000), 20);
    // The step before is the design as loaded, nothing in between.
    assert.equal(await solveAfter(page, () => page.getByRole('button', { name: 'Undo' }).click(), 300_000), 20);
    assert.deepEqual(await history(page), [0, 2]);
    assert.match(await page.locator('#mesh-details').textContent(), /^288 triangles/);
  });
});

test('preparing again carries the paint (by position) and the panel edits to the new mesh', () => {
  const { paint, link } = gridLink();
  return suite.withPage(link, async (page) => {
    assert.equal(await waitForDone(page), 4);
    assert.match(await page.locator('#mesh-details').textContent(), /^288 triangles/);
    await setPanels(page, 20);
    assert.equal(await solveAfter(page, () => remesh(page), 300_000), 20);
    assert.match(await cleanupNote(page), /refined 288 triangles to [\d,]+ .*20 panels/);
    const details = await page.locator('#mesh-details').textContent();
    const triangles = Number(/^([\d,]+) triangles/.exec(details)[1].replace(/,/g, ''));
    const vertices = Number(/([\d,]+) vertices/.exec(details)[1].replace(/,/g, ''));
    const shared = await shareLink(page);
    assert.deepEqual(shared.json.mesh.prepare, { panels: 20, subdivide: 0, refineBelow: 30, refineRounds: 5 }, 'the new preparation is recorded, with its rule');
    assert.equal(shared.json.history.length, 0, 'solved afresh on the prepared mesh');
    const carried = shared.paint;
    assert.equal(carried.length, vertices, 'one level per vertex of the prepared mesh');
    assert.equal(shared.json.params.paint, fieldKey(carried));
    assert.ok(carried.includes(32) && carried.includes(0), 'both sides of the paint are still there');
    assert.ok(carried.every((level) => level >= 0 && level <= 32), 'nothing outside the painted range');
    const edits = shared.json.params.edits;
    assert.equal(edits.length, 1);
    assert.equal(edits[0].op, 'lock');
    assert.ok(edits[0].face >= 0 && edits[0].face < triangles, 'the lock names a triangle of the prepared mesh');

    // Undo: the 288-triangle mesh and the paint and edit as they were.
    assert.equal(await solveAfter(page, () => page.getByRole('button', { name: 'Undo' }).click()), 4);
    assert.match(await page.locator('#mesh-details').textContent(), /^288 triangles/);
    const back = await shareLink(page, link);
    assert.deepEqual(back.json.mesh.prepare, { panels: 4, subdivide: 0 });
    assert.deepEqual(back.json.params.edits, [{ op: 'lock', face: 0 }]);
    assert.deepEqual([...back.paint], [...paint]);
  });
});

test('a Target edge length prepares the mesh to it, travels in the link, and a bad one is refused', () => {
  // No edits here: a lock makes a warm-started count change keep 4 panels (the core's rule for
  // edits, not the preparation's).
  const { link } = gridLink({ edits: [] });
  return suite.withPage(link, async (page) => {
    assert.equal(await waitForDone(page), 4);
    const edge = page.getByLabel('Target edge length');
    assert.equal(await edge.inputValue(), '', 'automatic');
    assert.equal(await solveAfter(page, () => edge.fill('0.5').then(() => edge.blur())), 4);
    assert.match(await cleanupNote(page), /remeshed 288 triangles to [\d,]+ \(target edge 0\.5\).*at the edge length asked for/);
    const triangles = Number(/^([\d,]+) triangles/.exec(await page.locator('#mesh-details').textContent())[1].replace(/,/g, ''));
    assert.ok(triangles > 1000, `${triangles} triangles at edge 0.5 on a 12 x 12 square`);
    assert.deepEqual((await shareLink(page, link)).json.mesh.prepare, { panels: 4, subdivide: 0, edgeLength: 0.5, refineBelow: 30, refineRounds: 5 });
    // Raising the count keeps the designer's resolution: no new preparation.
    await setPanels(page, 8);
    assert.equal(await solveAfter(page, () => remesh(page)), 8);
    assert.match(await page.locator('#mesh-details').textContent(), new RegExp(`^${triangles.toLocaleString('en')} triangles`));
    const message = await errorAfter(page, () => edge.fill('-1').then(() => edge.blur()));
    assert.match(message, /Target edge length must be a positive number/);
    assert.equal(await edge.getAttribute('aria-invalid'), 'true');
  });
});

// Filling holes appends triangles and adds no vertex: on the mesh as loaded the paint and the
// lock still name what they named, so they stay, in the solve and in the form (a second Remesh
// gives the same panels; before, the form had lost them while the solve still used them). On
// a prepared mesh, which is made again from the filled one, they are dropped, and said to be.
test('filling holes keeps the paint and edits on the mesh as loaded, and drops them, said, on a prepared one', async () => {
  const hole = gridLink({ hole: 1, panels: 8 });
  await suite.withPage(hole.link, async (page) => {
    assert.equal(await waitForDone(page), 8);
    assert.match(await page.locator('#mesh-details').textContent(), /^286 triangles/);
    const fill = page.getByLabel('Fill holes up to (edges)');
    assert.equal(await solveAfter(page, () => fill.fill('10').then(() => fill.blur())), 8);
    assert.match(await page.locator('#mesh-details').textContent(), /^288 triangles/, 'the hole filled');
    assert.match(await statusText(page), /^Done: 8 panels/);
    const filled = (await download(page, 'Export OBJ')).text;
    assert.equal(await solveAfter(page, () => remesh(page)), 8);
    assert.equal((await download(page, 'Export OBJ')).text, filled, 'the form kept the paint and the lock the solve used');
    const shared = await shareLink(page, hole.link);
    assert.deepEqual(shared.json.params.edits, [{ op: 'lock', face: 0 }]);
    assert.deepEqual([...shared.paint], [...hole.paint]);
  });

  const prepared = gridLink({ hole: 1, panels: 20, prepare: { panels: 20, subdivide: 0, refineBelow: 30, refineRounds: 5 } });
  await suite.withPage(prepared.link, async (page) => {
    assert.equal(await waitForDone(page, undefined, 300_000), 20);
    assert.doesNotMatch(await page.locator('#mesh-details').textContent(), /^286 triangles/, 'prepared for 20 panels');
    const fill = page.getByLabel('Fill holes up to (edges)');
    assert.equal(await solveAfter(page, () => fill.fill('10').then(() => fill.blur()), 300_000), 20);
    assert.match(await statusText(page), /^1 panel edit was dropped: it named the mesh before the holes changed\. Done: 20 panels/);
    const done = (await download(page, 'Export OBJ')).text;
    assert.equal(await solveAfter(page, () => remesh(page), 300_000), 20);
    assert.equal((await download(page, 'Export OBJ')).text, done, 'the form has no lock either');
  });
});

// Edits that do not fit the mesh on show (a link's lock on triangle 5,000 of 288) are refused
// before the mesh is prepared again: the worker carries them only after it has taken the
// prepared mesh, where a refusal would leave it on another mesh than the page.
test('a preparation is refused, by name, before it starts when the edits to carry do not fit', () => {
  const { link } = gridLink({ panels: 20, prepare: null, edits: [{ op: 'lock', face: 5000 }] });
  return suite.withPage(link, async (page) => {
    await waitForStatus(page, /Panel edit 1 names triangle 5000, but the mesh has 288 triangles; not solved/);
    const message = await errorAfter(page, () => remesh(page));
    assert.equal(message, 'Error: Panel edit 1 names triangle 5000, but the mesh has 288 triangles; the mesh was not prepared again.');
    assert.match(await page.locator('#mesh-details').textContent(), /^288 triangles/);
  });
});

// Undo and Redo carry nothing: their step's edits name the mesh they prepare, not the one on
// show. A lock on triangle 287 of the mesh as loaded lands on 575 of the prepared one; Undo
// goes back to the 288 triangles, and Redo prepares the finer mesh again for its lock on 575.
test('Redo to a prepared step prepares it whatever its edits name on the mesh on show', () => {
  const { link } = gridLink({ panels: 20, prepare: null, edits: [{ op: 'lock', face: 287 }] });
  return suite.withPage(link, async (page) => {
    assert.equal(await waitForDone(page), 20);
    assert.equal(await solveAfter(page, () => remesh(page), 300_000), 20);
    const [lock] = (await shareLink(page, link)).json.params.edits;
    assert.ok(lock.face >= 288, `the lock carried past the 288 triangles as loaded (to ${lock.face})`);
    assert.equal(await solveAfter(page, () => page.getByRole('button', { name: 'Undo' }).click(), 300_000), 20);
    assert.match(await page.locator('#mesh-details').textContent(), /^288 triangles/);
    assert.equal(await solveAfter(page, () => page.getByRole('button', { name: 'Redo' }).click(), 300_000), 20);
    assert.doesNotMatch(await page.locator('#mesh-details').textContent(), /^288 triangles/, 'prepared again');
  });
});

// A link whose paint has another length than its mesh's vertices (a hand-made or damaged one:
// the key still matches its bytes) is said at once, by name, and neither solved nor saved over
// the stored session (before: the brush and the density view took it for no paint, and only
// the solve said it, in the core's words, after the design had been saved).
test('a link whose density paint does not fit its mesh is said, not solved and not saved', () => {
  const example = { v: 1, mesh: { example: 'saddle' }, params: { ...quick, panels: 12 }, history: [] };
  const painted = Int8Array.from({ length: 100 }, () => 16);
  const key = fieldKey(painted);
  const bad = linkOf(suite.url, { ...example, params: { ...example.params, paint: key }, paint: [{ key, vertices: painted.length }] }, new Uint8Array(0), painted);
  return suite.withPage(linkOf(suite.url, example, new Uint8Array(0), new Int8Array(0)), async (page) => {
    assert.equal(await waitForDone(page), 12);
    await page.waitForFunction(() => Number(document.body.dataset.saves ?? 0) >= 2, null, { timeout: 30_000 });
    const saves = await page.evaluate(() => Number(document.body.dataset.saves ?? 0));
    const message = await errorAfter(page, () => page.evaluate((href) => { location.href = href; }, bad));
    assert.match(message, /The density paint has 100 values, but the mesh has 4,0\d\d vertices; not solved\.$/);
    await page.waitForTimeout(300);
    assert.equal(await page.evaluate(() => Number(document.body.dataset.saves ?? 0)), saves, 'not saved over the stored design');
  });
});

// Which holes are filled renumbers the filled triangles: when the holes change, edits are
// dropped (said) if one names a filled triangle (all of them: an edit dropped alone could leave
// an earlier one that it undid), while the paint stays.
test('changing the holes filled drops the edits when one names a filled triangle, said, and keeps the paint', () => {
  const { paint, link } = gridLink({ hole: 1, panels: 8, repair: { fillHoles: 10, largestPart: false }, edits: [{ op: 'lock', face: 0 }, { op: 'lock', face: 287 }] });
  return suite.withPage(link, async (page) => {
    assert.equal(await waitForDone(page), 8);
    assert.match(await page.locator('#mesh-details').textContent(), /^288 triangles/, 'the hole filled: triangles 286 and 287');
    const fill = page.getByLabel('Fill holes up to (edges)');
    assert.equal(await solveAfter(page, () => fill.fill('0').then(() => fill.blur())), 8);
    assert.match(await page.locator('#mesh-details').textContent(), /^286 triangles/);
    assert.match(await statusText(page), /^2 panel edits were dropped: one named a filled triangle, which filling numbers anew\. Done: 8 panels/);
    const shared = await shareLink(page, link);
    assert.deepEqual(shared.json.params.edits, []);
    assert.deepEqual([...shared.paint], [...paint], 'the paint stays: filling adds no vertex');
  });
});

// What an open dropped is said with its solve; a solve that ends otherwise (here a crash, as
// a cancel or a refusal would) says it too: before, it was never said, and the form no longer
// held the edits to show.
test('what a hole change dropped is said even when its solve crashes', () => {
  const { link } = gridLink({ hole: 1, panels: 8, repair: { fillHoles: 10, largestPart: false }, edits: [{ op: 'lock', face: 0 }, { op: 'lock', face: 287 }] });
  return suite.withPage(link.replace('#', '?crashAfterSteps=2#'), async (page) => {
    assert.equal(await waitForDone(page), 8);
    const fill = page.getByLabel('Fill holes up to (edges)');
    const message = await errorAfter(page, () => fill.fill('0').then(() => fill.blur()), 60_000);
    assert.match(message, /crashed and was restarted; the mesh is kept: Remesh to solve it\. 2 panel edits were dropped: one named a filled triangle, which filling numbers anew\.$/);
    await screenshot(page, 'grid-fill-crash-dropped-said');
    assert.equal(await solveAfter(page, () => remesh(page)), 8);
    assert.deepEqual((await shareLink(page, link)).json.params.edits, []);
  });
});

// Enter in "Fill holes up to" with a Panels change that needs the mesh prepared anew: the
// field's change opens the mesh with the holes and the new count. Before, Enter's Remesh started
// the preparation first, the change then found the mesh opening and was dropped without a word,
// and the field showed the old value again.
test('Enter in Fill holes applies the holes even when the panel count needs the mesh prepared', () => {
  const { link } = gridLink({ hole: 1, panels: 8, repair: { fillHoles: 10, largestPart: false }, edits: [] });
  return suite.withPage(link, async (page) => {
    assert.equal(await waitForDone(page), 8);
    assert.match(await page.locator('#mesh-details').textContent(), /^288 triangles/, 'the hole filled');
    await page.getByLabel('Panels', { exact: true }).fill('20');
    await page.getByLabel('Panels', { exact: true }).press('Tab');
    const fill = page.getByLabel('Fill holes up to (edges)');
    await fill.fill('0');
    assert.equal(await solveAfter(page, () => fill.press('Enter'), 300_000), 20);
    assert.equal(await fill.inputValue(), '0');
    assert.deepEqual((await shareLink(page, link)).json.mesh.repair, undefined, 'no holes filled');
  });
});

// The solve that would say what a hole change dropped, replaced by a Subdivide change before it
// ends (?stepDelay=250: its steps slowed, so it is still running when the change lands; at 40 ms
// a busy CI machine once let it end first, and it said the notice itself): the preparation's
// solve says it instead (it was lost with the mesh it named, though the design is the same).
test('what a hole change dropped is said by the solve of a preparation that replaced its own', () => {
  const { link } = gridLink({ hole: 1, panels: 8, repair: { fillHoles: 10, largestPart: false }, edits: [{ op: 'lock', face: 0 }, { op: 'lock', face: 287 }] });
  return suite.withPage(link.replace('#', '?stepDelay=250#'), async (page) => {
    assert.equal(await waitForDone(page), 8);
    await recordStatus(page);
    const fill = page.getByLabel('Fill holes up to (edges)');
    await fill.fill('0');
    await fill.blur();
    await page.waitForFunction(() => document.body.dataset.solving === 'true' && document.body.dataset.opening === 'false', null, { timeout: 30_000, polling: 5 });
    const subdivide = page.getByLabel('Subdivide levels');
    assert.equal(await solveAfter(page, () => subdivide.fill('1').then(() => subdivide.blur()), 120_000), 8);
    assert.match(await cleanupNote(page), /subdivided 143 polygons 1 level \(catmull-clark\) into 1,144 triangles/);
    assert.match(await statusText(page), /^2 panel edits were dropped: one named a filled triangle, which filling numbers anew\. Done: 8 panels/);
    const seen = await page.evaluate(() => window.__statusSeen);
    assert.equal(seen.filter((text) => /Done: /.test(text)).length, 1, `the hole change's solve was replaced before it ended: ${JSON.stringify(seen)}`);
  });
});

// Preparation follows the triangle count, which filling changes: filled, 270 triangles serve 9
// panels as loaded (30 each); unfilled, 256 are refined. The split named the mesh as loaded, so
// it is dropped (said), not replayed on another triangle of the refined one, and "Panels" no
// longer counts it: Remesh then solves 9, not the 10 the split made.
test('a hole change that makes the mesh prepared drops the edits of the mesh as loaded, said', () => {
  const { link } = gridLink({ hole: 4, panels: 9, prepare: { panels: 9, subdivide: 0, refineBelow: 30, refineRounds: 5 }, repair: { fillHoles: 16, largestPart: false }, edits: [{ op: 'split', face: 0 }] });
  return suite.withPage(link, async (page) => {
    assert.equal(await waitForDone(page), 10, 'the split makes 10');
    assert.match(await page.locator('#mesh-details').textContent(), /^270 triangles/, 'filled, as loaded');
    const fill = page.getByLabel('Fill holes up to (edges)');
    assert.equal(await solveAfter(page, () => fill.fill('0').then(() => fill.blur()), 300_000), 9);
    assert.doesNotMatch(await page.locator('#mesh-details').textContent(), /^(256|270) triangles/, 'unfilled and refined');
    assert.match(await statusText(page), /^1 panel edit was dropped: it named the mesh before the holes changed\. Done: 9 panels/);
    assert.deepEqual((await shareLink(page, link)).json.params.edits, []);
    assert.equal(await page.getByLabel('Panels', { exact: true }).inputValue(), '9');
    assert.equal(await solveAfter(page, () => remesh(page), 300_000), 9);
  });
});

// A link whose recorded preparation the core refuses (an edge length that needs 53 million
// triangles) is refused after the worker has read its mesh: the worker then loads the design on
// show again, and the form shows that design again (the link had written its own), so Remesh
// solves the 12 x 12 grid with its paint and lock, the very panels of before, not the refused
// 24 x 24 one. Its fabrication settings are not written, and the worker still fabricates the
// panels on show.
test('a link refused while preparing its mesh leaves the worker on the design on show', () => {
  const { link } = gridLink();
  const lines = [];
  for (let j = 0; j <= n; j++) for (let i = 0; i <= n; i++) lines.push(`v ${2 * i} ${2 * j} 0`);
  for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) {
    const v = (a, b) => b * (n + 1) + a + 1;
    lines.push(`f ${v(i, j)} ${v(i + 1, j)} ${v(i + 1, j + 1)} ${v(i, j + 1)}`);
  }
  const bytes = new TextEncoder().encode(`${lines.join('\n')}\n`);
  const fabrication = { thickness: 33, side: 'inside', units: 'mm', meshUnits: 'm', sheetWidth: 2440, sheetHeight: 1220, panelThickness: {}, boundaryCut: 'square', boundaryBevelDeg: 0, upAxis: 'z' };
  const refused = linkOf(suite.url, { v: 1, mesh: { file: 'big.obj', size: bytes.length, prepare: { panels: 4, subdivide: 0, edgeLength: 0.005 } }, params: { ...quick, panels: 4, edits: [] }, history: [], fabrication }, bytes, new Int8Array(0));
  return suite.withPage(link, async (page) => {
    assert.equal(await waitForDone(page), 4);
    const before = (await download(page, 'Export OBJ')).text;
    const parts = (await download(page, 'Export parts list')).text;
    const message = await errorAfter(page, () => page.goto(refused));
    assert.match(message, /an edge length of 0\.005 needs about [\d,]+ triangles, more than the 2,000,000 the preparation makes/);
    assert.match(await page.locator('#mesh-details').textContent(), /^288 triangles/);
    // The link's fabrication settings never came; the worker still fabricates the panels on
    // show (it read the refused mesh, then the one on show again).
    assert.equal(await page.getByLabel('Thickness', { exact: true }).inputValue(), '0');
    const thickness = page.getByLabel('Thickness', { exact: true });
    await thickness.fill('1');
    await thickness.press('Tab');
    await thickness.fill('0');
    await thickness.press('Tab');
    await page.waitForFunction(() => document.body.dataset.fabricating === 'false' && !document.querySelector('#export-parts').disabled, null, { timeout: 30_000, polling: 50 });
    assert.equal((await download(page, 'Export parts list')).text, parts);
    assert.equal(await solveAfter(page, () => remesh(page)), 4);
    const after = parseObj((await download(page, 'Export OBJ')).text);
    assert.ok(after.vertices.every((v) => v.every((x) => x <= 12 + 1e-9)), 'panels of the 12 x 12 grid on show');
    assert.equal((await download(page, 'Export OBJ')).text, before, 'with its paint and lock: the same panels as before the refused link');
  });
});

// A file that fails on the page (a broken glTF) cleared the Target edge length as every new
// file does; the design on show keeps its own, so the field shows it again and Remesh solves on
// the mesh as it is instead of preparing it anew without the edge length.
test('a file that fails to open leaves the Surface section as the design on show has it', () => {
  const { link } = gridLink({ panels: 4, prepare: { panels: 4, subdivide: 0, edgeLength: 0.5 } });
  return suite.withPage(link, async (page) => {
    assert.equal(await waitForDone(page), 4);
    const edge = page.getByLabel('Target edge length');
    assert.equal(await edge.inputValue(), '0.5');
    const details = await page.locator('#mesh-details').textContent();
    const message = await errorAfter(page, () =>
      page.evaluate(() => {
        const transfer = new DataTransfer();
        transfer.items.add(new File(['glTF not really'], 'broken.glb'));
        document.getElementById('viewport').dispatchEvent(new DragEvent('drop', { dataTransfer: transfer, bubbles: true, cancelable: true }));
      }),
    );
    assert.match(message, /broken\.glb/);
    assert.equal(await edge.inputValue(), '0.5', 'the edge length of the design on show');
    assert.equal(await solveAfter(page, () => remesh(page)), 4);
    assert.equal(await page.locator('#mesh-details').textContent(), details, 'not prepared again');
  });
});
