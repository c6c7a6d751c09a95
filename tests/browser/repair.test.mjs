// Repair on the page (issue 7): an uploaded OBJ of two cubes sharing an edge is refused with the
// edge named and a "Use largest manifold part" button; the button opens one closed cube that
// solves to valid planar panels and says what was dropped; a share link carries the choice (and
// "Fill holes up to (edges)"), so a fresh context opens and solves the very same mesh, and so
// does the stored session. A stray part far off gets the same offer. Holes are filled only when
// asked. Run after `npm run build`.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { browserSuite, download, errorAfter, exampleLink, maxPlanarity, outcomes, parseObj, screenshot, solveAfter, waitForDone, waitForSaved } from './harness.mjs';
import { cubeAndFarTriangleObj, openBoxObj, twoCubesObj } from '../fixtures/meshes.mjs';

const suite = browserSuite();

const PANELS = 6;
const params = { panels: PANELS, seed: 1, weights: { euclidean: 1, l2: 1, l21: 1, boundary: 1 }, lloydIterations: 20, panelRounds: 30, seeding: 'farthest', teleport: true, singlePointNodes: false, optimizePlanes: true };

const cleanupNote = (page) => page.locator('#mesh-cleanup').textContent();
const upload = (page, name, bytes) => page.getByLabel('Open mesh').setInputFiles({ name, mimeType: 'text/plain', buffer: Buffer.from(bytes) });

test('a non-manifold upload offers its largest manifold part, which solves, and a link reproduces it', () =>
  suite.withPage(exampleLink(suite.url, 'saddle', params), async (page) => {
    await waitForDone(page);
    const offer = page.getByRole('button', { name: 'Use largest manifold part' });
    assert.equal(await offer.isVisible(), false);
    const message = await errorAfter(page, () => upload(page, 'twocubes.obj', twoCubesObj()));
    assert.match(message, /non-manifold edge between vertices \d+ and \d+ at \(1, 1, 0\.5\): shared by 4 faces/);
    assert.match(message, /Use the largest manifold part \(12 of 24 faces\)\?/);
    assert.equal(await offer.isVisible(), true);
    await screenshot(page, 'repair-offer');

    assert.equal(await solveAfter(page, () => offer.click()), PANELS);
    assert.equal(await offer.isVisible(), false);
    assert.match(await cleanupNote(page), /kept the largest manifold part \(12 of 24 faces\): cut at 1 non-manifold edge, dropped 12 faces in 1 other part/);
    const obj = (await download(page, 'Export OBJ')).text;
    const panels = parseObj(obj);
    assert.equal(panels.faces.length, PANELS);
    assert.ok(maxPlanarity(panels) <= 1e-9);
    for (const v of panels.vertices) assert.ok(Math.max(...v) <= 1.01 && Math.min(...v) >= -0.01, `${v} is on the first cube (the second reaches 2)`);
    assert.match(await page.locator('#stats').textContent(), /Invalid\s*0\s*Topology\s*preserved/);
    await screenshot(page, 'repair-largest-part');

    await page.getByRole('button', { name: 'Copy share link' }).click();
    await page.waitForFunction(() => location.hash.startsWith('#v1='));
    const link = await page.evaluate(() => location.href);
    await suite.withPage(link, async (opened) => {
      assert.equal(await waitForDone(opened), PANELS);
      assert.match(await cleanupNote(opened), /kept the largest manifold part \(12 of 24 faces\)/);
      assert.equal((await download(opened, 'Export OBJ')).text, obj, 'the link opens the same part: the same OBJ bytes');
    });
  }));

test('a stray part far off is named and offered the largest part, which solves', () =>
  suite.withPage(exampleLink(suite.url, 'saddle', params), async (page) => {
    await waitForDone(page);
    const offer = page.getByRole('button', { name: 'Use largest manifold part' });
    const message = await errorAfter(page, () => upload(page, 'stray.obj', cubeAndFarTriangleObj()));
    assert.match(message, /a part of 1 triangle near \(1e\+08, 0\.005, 0\) lies .* times the main part's size/);
    assert.match(message, /Use the largest manifold part \(12 of 13 faces\)\?/);
    assert.equal(await offer.isVisible(), true);
    assert.equal(await solveAfter(page, () => offer.click()), PANELS);
    assert.match(await cleanupNote(page), /kept the largest part \(12 of 13 faces\): dropped 1 face in 1 other part/);
    const panels = parseObj((await download(page, 'Export OBJ')).text);
    assert.ok(maxPlanarity(panels) <= 1e-9);
    for (const v of panels.vertices) assert.ok(Math.max(...v) <= 1.01, `${v} is on the cube, not the far triangle`);
    await screenshot(page, 'repair-far-part');
  }));

test('holes are filled only when asked, and the setting travels in a link', () =>
  suite.withPage(exampleLink(suite.url, 'saddle', params), async (page) => {
    await waitForDone(page);
    const fill = page.getByLabel('Fill holes up to (edges)');
    assert.equal(await fill.inputValue(), '0');
    await solveAfter(page, () => upload(page, 'openbox.obj', openBoxObj()));
    assert.doesNotMatch((await cleanupNote(page)) ?? '', /filled/);
    const since = await outcomes(page);
    assert.equal(await solveAfter(page, () => fill.fill('4').then(() => fill.blur())), PANELS);
    assert.match(await cleanupNote(page), /filled 1 hole with 2 faces/);
    const obj = (await download(page, 'Export OBJ')).text;
    assert.ok(maxPlanarity(parseObj(obj)) <= 1e-9);
    await waitForSaved(page, since, 2); // the load and the solve

    await page.getByRole('button', { name: 'Copy share link' }).click();
    await page.waitForFunction(() => location.hash.startsWith('#v1='));
    const link = await page.evaluate(() => location.href);
    await suite.withPage(link, async (opened) => {
      assert.equal(await waitForDone(opened), PANELS);
      assert.equal(await opened.getByLabel('Fill holes up to (edges)').inputValue(), '4');
      assert.match(await cleanupNote(opened), /filled 1 hole with 2 faces/);
      assert.equal((await download(opened, 'Export OBJ')).text, obj);
    });

    // The stored session opens the same filled mesh on the next visit.
    await page.goto(suite.url);
    assert.equal(await waitForDone(page), PANELS);
    assert.equal(await page.getByLabel('Fill holes up to (edges)').inputValue(), '4');
    assert.match(await cleanupNote(page), /filled 1 hole with 2 faces/);
    assert.equal((await download(page, 'Export OBJ')).text, obj);
  }));
