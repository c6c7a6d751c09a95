// Preparation on the page (issue 7): the coarse Yas Island grid shell (976 quads) is refined
// for its panels when opened and the Surface section says so; "Subdivide levels" opens it again
// subdivided (Catmull-Clark on its quads); a share link carries the preparation, so a fresh
// context prepares the same mesh and exports the very same OBJ. Run after `npm run build`.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { browserSuite, download, maxPlanarity, parseObj, screenshot, selectExample, solveAfter, waitForDone } from './harness.mjs';

const suite = browserSuite();

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
