// The procedural anisotropy direction on the page, in headless Chromium against the built
// site: choosing "Expression" shows the "Direction expression" input (starting from the vortex
// preset); a hostile expression is refused on the page, a broken one by the core naming the
// component and the column, and neither solves; a typed one solves, the stats count the
// triangles left without a direction; a reload (the stored session) and its share link, opened
// in a fresh context, restore the input and give the identical OBJ.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { browserSuite, download, errorAfter, exampleLink, outcomes, remesh, screenshot, solveAfter, waitForDone, waitForSaved } from './harness.mjs';

const suite = browserSuite();

const PANELS = 50;
const params = { panels: PANELS, seed: 1, weights: { euclidean: 1, l2: 1, l21: 1, boundary: 1 }, lloydIterations: 20, panelRounds: 30, seeding: 'farthest', teleport: true, singlePointNodes: false, optimizePlanes: true };

async function objOf(page) {
  return (await download(page, 'Export OBJ')).text;
}

test('Expression direction: refused when hostile or broken, solved when typed, and its link gives the same OBJ', async () => {
  let link = '';
  let obj = '';
  await suite.withPage(exampleLink(suite.url, 'saddle', params), async (page) => {
    assert.equal(await waitForDone(page), PANELS);
    const input = page.getByLabel('Direction expression');
    assert.equal(await input.isVisible(), false, 'hidden for the other directions');
    await page.getByLabel('Anisotropy direction').selectOption({ label: 'Expression' });
    assert.equal(await input.isVisible(), true);
    assert.equal(await input.inputValue(), '0.5 - v, u - 0.5, 0', 'starts from the vortex preset');
    await page.getByLabel('Stretch', { exact: true }).fill('3');

    // Refused on the page, token by token: nothing goes to the solver.
    await input.fill('x, y, fetch(1)');
    let message = await errorAfter(page, () => remesh(page));
    assert.match(message, /Direction expression uses an unknown name "fetch"/);
    assert.equal(await input.getAttribute('aria-invalid'), 'true');
    assert.equal(await page.evaluate(() => document.body.dataset.solving), 'false', 'nothing went to the solver');
    await input.fill('-y, x');
    message = await errorAfter(page, () => remesh(page));
    assert.match(message, /Direction expression needs three components/);
    // Tokens the page accepts, a grammar the core refuses: its message names the component and column.
    await input.fill('-y, x, 0 +');
    message = await errorAfter(page, () => remesh(page));
    assert.match(message, /component 3 \(z\) ends early: expected a value at column 11/);

    await input.fill('-y, x, 0');
    const sinceSolve = await outcomes(page);
    assert.equal(await solveAfter(page, () => remesh(page)), PANELS);
    assert.equal(await input.getAttribute('aria-invalid'), null);
    const stats = page.locator('dt', { hasText: 'No direction' });
    assert.equal(await stats.count(), 1, 'the stats count the triangles without a direction');
    obj = await objOf(page);
    await input.evaluate((el) => el.scrollIntoView({ block: 'center' }));
    await screenshot(page, 'anisotropy-expression');
    await page.getByRole('button', { name: 'Copy share link' }).click();
    await page.waitForFunction(() => location.hash.startsWith('#v1='));
    link = await page.getByLabel('Share link').inputValue();

    // The stored session brings the expression back after a reload.
    await waitForSaved(page, sinceSolve, 1);
    await page.reload();
    assert.equal(await waitForDone(page), PANELS);
    assert.equal(await page.getByLabel('Direction expression').inputValue(), '-y, x, 0');
    assert.equal(await page.getByLabel('Direction expression').isVisible(), true);
    assert.equal(await objOf(page), obj, 'the reload reproduces the OBJ');
  });
  assert.ok(obj.length > 1000);
  await suite.withPage(link, async (page) => {
    assert.equal(await waitForDone(page), PANELS);
    assert.equal(await page.getByLabel('Anisotropy direction').inputValue(), 'expression');
    assert.equal(await page.getByLabel('Direction expression').inputValue(), '-y, x, 0');
    assert.equal(await page.getByLabel('Stretch', { exact: true }).inputValue(), '3');
    assert.equal(await objOf(page), obj, 'byte-identical OBJ from the link');
  });
});
