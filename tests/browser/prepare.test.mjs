// Preparation on the page (issue 7): the coarse Yas Island grid shell (976 quads) is refined
// for its panels when opened and the Surface section says so; "Subdivide levels" opens it again
// subdivided (Catmull-Clark on its quads); a share link carries the preparation, so a fresh
// context prepares the same mesh and exports the very same OBJ. Run after `npm run build`.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { browserSuite, download, exampleLink, maxPlanarity, parseObj, remesh, screenshot, selectExample, setPanels, solveAfter, waitForDone } from './harness.mjs';

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
