// Per-panel edits in headless Chromium against the built site (issue 6): on the saddle at 60
// panels, click a panel and Split it (61 panels, the OBJ planar); lock a panel, change the
// panel count and re-solve (its polygon is still in the OBJ, the same vertices within 1e-9);
// merge a panel with a clicked neighbour; undo and redo give back the very same OBJ bytes;
// a reload (the stored session) and a share link with the edits, opened in a fresh context, reproduces the OBJ byte for byte.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { browserSuite, exampleLink, download, maxPlanarity, outcomes, parseObj, remesh, screenshot, setPanels, waitForDone, waitForSaved } from './harness.mjs';

const suite = browserSuite();

const PANELS = 60;
const params = { panels: PANELS, seed: 1, weights: { euclidean: 1, l2: 1, l21: 1, boundary: 1 }, lloydIterations: 20, panelRounds: 30, seeding: 'farthest', teleport: true, singlePointNodes: false, optimizePlanes: true };

const saddleLink = () => exampleLink(suite.url, 'saddle', params);

async function objOf(page) {
  return (await download(page, 'Export OBJ')).text;
}

async function after_(page, action) {
  const since = await outcomes(page);
  await action();
  return waitForDone(page, since);
}

// Clicks the view at (fx, fy) of its size; returns the selected panel ('' for none).
async function clickView(page, fx, fy) {
  const box = await page.locator('#viewport canvas').boundingBox();
  await page.mouse.click(box.x + box.width * fx, box.y + box.height * fy);
  return page.evaluate(() => document.body.dataset.editPanel ?? '');
}

// Whether `polygon` (points) is a face of the OBJ, vertex for vertex within `tolerance`.
function hasPolygon(text, polygon, tolerance) {
  const { vertices, faces } = parseObj(text);
  const near = (p, q) => Math.max(Math.abs(p[0] - q[0]), Math.abs(p[1] - q[1]), Math.abs(p[2] - q[2])) <= tolerance;
  return faces.some((face) => face.length === polygon.length && polygon.every((p) => face.some((i) => near(vertices[i], p))));
}

test('panel edits: split, lock through a re-solve, merge; undo/redo give the same bytes; a link reproduces them', async () => {
  let link = '';
  let final = '';
  await suite.withPage(saddleLink(), async (page) => {
    assert.equal(await waitForDone(page), PANELS);
    const before = await objOf(page);
    const split = page.getByRole('button', { name: 'Split panel' });
    assert.equal(await split.isDisabled(), true, 'nothing selected yet');

    // Select the panel in the middle of the view, split it.
    const selected = await clickView(page, 0.5, 0.5);
    assert.match(selected, /^\d+$/, 'a click on a panel selects it');
    await screenshot(page, 'edits-selected');
    assert.equal(await split.isDisabled(), false);
    assert.equal(await after_(page, () => split.click()), PANELS + 1, 'a split makes one panel more');
    const afterSplit = await objOf(page);
    const planarity = maxPlanarity(parseObj(afterSplit));
    assert.ok(planarity <= 1e-9, `split panels are planar (${planarity})`);
    assert.equal(parseObj(afterSplit).faces.length, PANELS + 1);
    assert.match(await page.locator('#edit-summary').textContent(), /1 edit: 1 split/);

    // Lock another panel; its polygon (OBJ face = panel id) must survive a re-solve.
    assert.match(await clickView(page, 0.3, 0.45), /^\d+$/);
    assert.equal(await after_(page, () => page.getByRole('button', { name: 'Lock panel' }).click()), PANELS + 1);
    const locked = await page.evaluate(() => document.body.dataset.lockedPanels);
    assert.match(locked, /^\d+$/, `one locked panel (${locked})`);
    const afterLock = await objOf(page);
    const lockedObj = parseObj(afterLock);
    const polygon = lockedObj.faces[Number(locked)].map((i) => lockedObj.vertices[i]);
    assert.equal(await page.getByRole('button', { name: 'Unlock panel' }).isVisible(), true, 'the selected panel offers Unlock now');
    assert.equal(await split.isDisabled(), true, 'a locked panel is not split');
    await screenshot(page, 'edits-locked');

    await setPanels(page, 70);
    assert.equal(await after_(page, () => remesh(page)), 70);
    const resolved = await objOf(page);
    assert.ok(hasPolygon(resolved, polygon, 1e-9), 'the locked panel is in the re-solved OBJ, the same vertices within 1e-9');
    assert.ok(maxPlanarity(parseObj(resolved)) <= 1e-9);
    assert.match(await page.evaluate(() => document.body.dataset.lockedPanels), /^\d+$/, 'still locked after the re-solve');

    // Merge: select a panel away from the locked one, then click around it for a neighbour.
    assert.match(await clickView(page, 0.65, 0.5), /^\d+$/);
    await page.getByRole('button', { name: 'Merge with neighbour' }).click();
    assert.equal(await page.getByRole('button', { name: 'Merge with neighbour' }).getAttribute('aria-pressed'), 'true');
    const since = await outcomes(page);
    const edits = Number(await page.evaluate(() => document.body.dataset.edits ?? 0));
    search: for (const dx of [0.03, -0.03, 0.06, -0.06, 0.09, -0.09]) {
      for (const dy of [0, 0.04, -0.04]) {
        if (Number(await page.evaluate(() => document.body.dataset.edits ?? 0)) > edits) break search;
        await clickView(page, 0.65 + dx, 0.5 + dy);
      }
    }
    assert.equal(await waitForDone(page, since), 69, 'a merge makes one panel fewer');
    final = await objOf(page);
    assert.ok(hasPolygon(final, polygon, 1e-9), 'the lock holds through the merge');
    await screenshot(page, 'edits-merged');

    // Undo the merge, the re-solve; redo both: the same bytes each way.
    assert.equal(await after_(page, () => page.getByRole('button', { name: 'Undo' }).click()), 70);
    assert.equal(await objOf(page), resolved, 'undo the merge: the OBJ before it, byte for byte');
    assert.equal(await after_(page, () => page.getByRole('button', { name: 'Undo' }).click()), PANELS + 1);
    assert.equal(await objOf(page), afterLock, 'undo the re-solve: the locked design, byte for byte');
    assert.equal(await page.getByLabel('Panels', { exact: true }).inputValue(), String(PANELS));
    assert.equal(await after_(page, () => page.getByRole('button', { name: 'Undo' }).click()), PANELS + 1);
    assert.equal(await objOf(page), afterSplit, 'undo the lock');
    assert.equal(await after_(page, () => page.getByRole('button', { name: 'Undo' }).click()), PANELS);
    assert.equal(await objOf(page), before, 'undo the split: the first OBJ');
    await page.locator('#viewport canvas').click({ position: { x: 5, y: 5 } }); // focus off the inputs
    assert.equal(await after_(page, () => page.keyboard.press('Control+Shift+Z')), PANELS + 1);
    assert.equal(await objOf(page), afterSplit, 'redo (Ctrl+Shift+Z) the split');
    let lastRedo = null;
    for (const expected of [afterLock, resolved, final]) {
      lastRedo = await outcomes(page);
      await after_(page, () => page.getByRole('button', { name: 'Redo' }).click());
      assert.equal(await objOf(page), expected, 'redo: the edited bytes');
    }
    assert.equal(await page.getByRole('button', { name: 'Redo' }).isDisabled(), true);
    assert.match(await page.locator('#edit-summary').textContent(), /3 edits: 1 split, 1 merged, 1 locked · 69 panels now/);

    // The stored session brings the edits back after a reload.
    await waitForSaved(page, lastRedo, 1);
    await page.reload();
    assert.equal(await waitForDone(page), 69);
    assert.equal(await objOf(page), final, 'the reload reproduces the OBJ');

    await page.getByRole('button', { name: 'Copy share link' }).click();
    await page.waitForFunction(() => location.hash.startsWith('#v1='));
    link = await page.getByLabel('Share link').inputValue();
  });

  await suite.withPage(link, async (page) => {
    assert.equal(await waitForDone(page), 69);
    assert.equal(await objOf(page), final, 'the link reproduces the OBJ byte for byte');
    assert.match(await page.evaluate(() => document.body.dataset.lockedPanels), /^\d+$/, 'the lock came with it');
    await screenshot(page, 'edits-shared');
  });
});
