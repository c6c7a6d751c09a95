// The density brush, undo/redo and paint in share links and the stored session, in headless
// Chromium against the built site: a stroke over one side of the saddle, re-solved, makes the
// panels under it smaller; undo and redo give back the very same OBJ bytes; a share link with
// the paint, opened in a fresh context, reproduces the OBJ byte for byte, and so does a reload.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { browserSuite, exampleLink, download, errorAfter, outcomes, parseObj, remesh, screenshot, setPanels, solveAfter, waitForDone, waitForSaved } from './harness.mjs';

const suite = browserSuite();

const PANELS = 60;
const params = { panels: PANELS, seed: 1, weights: { euclidean: 1, l2: 1, l21: 1, boundary: 1 }, lloydIterations: 20, panelRounds: 30, seeding: 'farthest', teleport: true, singlePointNodes: false, optimizePlanes: true };

const saddleLink = () => exampleLink(suite.url, 'saddle', params);

// Panels of an OBJ: area (Newell) and centroid (vertex mean).
function panelsOf(text) {
  const { vertices, faces } = parseObj(text);
  return faces.map((face) => {
    const points = face.map((i) => vertices[i]);
    const twice = [0, 0, 0];
    for (let i = 0; i < points.length; i++) {
      const p = points[i];
      const q = points[(i + 1) % points.length];
      twice[0] += p[1] * q[2] - p[2] * q[1];
      twice[1] += p[2] * q[0] - p[0] * q[2];
      twice[2] += p[0] * q[1] - p[1] * q[0];
    }
    const centroid = [0, 1, 2].map((k) => points.reduce((s, p) => s + p[k], 0) / points.length);
    return { area: Math.hypot(...twice) / 2, centroid };
  });
}

// Mean area of the panels whose centroid lies within `reach` of the stroke's path.
function meanAreaUnder(text, stroke, reach) {
  const under = panelsOf(text).filter(({ centroid }) => stroke.points.some((p) => Math.hypot(p[0] - centroid[0], p[1] - centroid[1], p[2] - centroid[2]) <= reach));
  assert.ok(under.length >= 1, 'some panels lie under the stroke');
  return { mean: under.reduce((s, p) => s + p.area, 0) / under.length, count: under.length };
}

async function objOf(page) {
  return (await download(page, 'Export OBJ')).text;
}

test('paint a stroke: smaller panels under it; undo/redo give the same OBJ bytes; a link and a reload reproduce it', async () => {
  let link = '';
  let painted = '';
  let edited = '';
  await suite.withPage(saddleLink(), async (page) => {
    assert.equal(await waitForDone(page), PANELS);
    const before = await objOf(page);

    // Paint one stroke across the left part of the saddle.
    await page.getByRole('button', { name: 'Paint density' }).click();
    assert.equal(await page.getByRole('button', { name: 'Paint density' }).getAttribute('aria-pressed'), 'true');
    await page.getByLabel('Brush radius').fill('12');
    await page.getByLabel('Brush strength').fill('1');
    assert.equal(await page.getByLabel('Brush mode').inputValue(), 'add');
    const box = await page.locator('#viewport canvas').boundingBox();
    const y = box.y + box.height * 0.5;
    await page.mouse.move(box.x + box.width * 0.36, y);
    await screenshot(page, 'density-cursor');
    const since = await outcomes(page);
    await page.mouse.down();
    for (let i = 1; i <= 12; i++) await page.mouse.move(box.x + box.width * (0.36 + (0.14 * i) / 12), y + box.height * 0.04 * Math.sin(i / 2));
    await page.mouse.up();
    assert.equal(await waitForDone(page, since), PANELS);
    painted = await objOf(page);
    const stroke = JSON.parse(await page.evaluate(() => document.body.dataset.lastStroke));
    assert.ok(stroke.points.length >= 4, `the stroke has dabs (${stroke.points.length})`);
    await screenshot(page, 'density-painted');
    assert.notEqual(painted, before);
    const reach = stroke.radius * 0.5;
    const was = meanAreaUnder(before, stroke, reach);
    const now = meanAreaUnder(painted, stroke, reach);
    const ratio = now.mean / was.mean;
    console.log(`density: mean panel area under the stroke ${was.mean.toPrecision(4)} (${was.count} panels) -> ${now.mean.toPrecision(4)} (${now.count} panels): ratio ${ratio.toFixed(3)}`);
    assert.ok(ratio < 0.6, `panels under the stroke get smaller (ratio ${ratio.toFixed(3)})`);

    // An edit after the stroke, then undo / redo through both.
    await setPanels(page, PANELS - 15);
    assert.equal(await solveAfter(page, () => remesh(page)), PANELS - 15);
    edited = await objOf(page);
    await page.getByRole('button', { name: 'Paint density' }).click(); // off: the usual view
    assert.equal(await solveAfter(page, () => page.getByRole('button', { name: 'Undo' }).click()), PANELS);
    assert.equal(await page.getByLabel('Panels', { exact: true }).inputValue(), String(PANELS));
    assert.equal(await objOf(page), painted, 'undo the edit: the painted OBJ, byte for byte');
    assert.equal(await solveAfter(page, () => page.getByRole('button', { name: 'Undo' }).click()), PANELS);
    assert.equal(await objOf(page), before, 'undo the stroke: the OBJ before it, byte for byte');
    assert.equal(await page.getByRole('button', { name: 'Clear paint' }).isDisabled(), true, 'no paint any more');
    await page.locator('#viewport canvas').click({ position: { x: 5, y: 5 } }); // focus off the inputs
    assert.equal(await solveAfter(page, () => page.keyboard.press('Control+Shift+Z')), PANELS);
    assert.equal(await objOf(page), painted, 'redo (Ctrl+Shift+Z) the stroke: the painted OBJ');
    const sinceRedo = await outcomes(page);
    assert.equal(await solveAfter(page, () => page.getByRole('button', { name: 'Redo' }).click()), PANELS - 15);
    assert.equal(await objOf(page), edited, 'redo the edit');
    assert.equal(await page.getByRole('button', { name: 'Redo' }).isDisabled(), true);
    // Ctrl+Z while typing in a field is the field's own undo, not the design's.
    await page.getByLabel('Density expression').focus();
    await page.keyboard.press('Control+Z');
    assert.equal(await page.evaluate(() => document.body.dataset.solving), 'false');
    assert.equal(await page.getByRole('button', { name: 'Redo' }).isDisabled(), true, 'no design undo happened');

    // Share the painted design (its chain: plain, painted, edited).
    await page.getByRole('button', { name: 'Copy share link' }).click();
    await page.waitForFunction(() => location.hash.startsWith('#v1='));
    link = await page.getByLabel('Share link').inputValue();

    // The stored session brings the paint back after a reload.
    await waitForSaved(page, sinceRedo, 1);
    await page.reload();
    assert.equal(await waitForDone(page), PANELS - 15);
    assert.equal(await objOf(page), edited, 'the reload reproduces the OBJ');
    assert.equal(await page.getByRole('button', { name: 'Clear paint' }).isDisabled(), false, 'the paint came back');
    await page.getByRole('button', { name: 'Paint density' }).click();
    await screenshot(page, 'density-restored');
  });

  // The link in a fresh context (no shared storage).
  await suite.withPage(link, async (page) => {
    assert.equal(await waitForDone(page), PANELS - 15);
    assert.equal(await objOf(page), edited, 'the link reproduces the OBJ byte for byte');
  });
});

test('density presets fill the expression, undo takes it back without a solve, a hostile expression is refused on the page', async () => {
  await suite.withPage(saddleLink(), async (page) => {
    assert.equal(await waitForDone(page), PANELS);
    const expression = page.getByLabel('Density expression');
    await page.getByLabel('Density preset').selectOption({ label: 'Gradient' });
    assert.equal(await expression.inputValue(), '1 + 3 * u');
    await page.getByLabel('Density preset').selectOption({ label: 'By curvature' });
    assert.equal(await expression.inputValue(), '1 + 2 * min(curv, 4)');
    const since = await outcomes(page);
    await page.getByRole('button', { name: 'Undo' }).click();
    assert.equal(await expression.inputValue(), '1 + 3 * u');
    assert.equal(await page.getByLabel('Density preset').inputValue(), 'gradient');
    await page.getByRole('button', { name: 'Undo' }).click();
    assert.equal(await expression.inputValue(), '', 'back to no expression');
    assert.equal(await page.getByLabel('Density preset').inputValue(), '');
    assert.equal(await page.getByRole('button', { name: 'Undo' }).isDisabled(), true);
    assert.equal(await page.evaluate(() => document.body.dataset.solving), 'false', 'the panels on show are that design: no solve');
    assert.equal((await outcomes(page)).solves, since.solves);
    // Typing a preset's text selects it; anything else is "custom".
    await expression.fill('1 + 3 * u');
    assert.equal(await page.getByLabel('Density preset').inputValue(), 'gradient');
    await page.getByLabel('Anisotropy direction').selectOption('maxCurvature');
    await page.getByLabel('Stretch', { exact: true }).fill('12');
    let message = await errorAfter(page, () => remesh(page));
    assert.match(message, /Stretch must be between 1 and 10/);
    await page.getByLabel('Stretch', { exact: true }).fill('3');
    await expression.fill('alert(document.cookie)');
    assert.equal(await page.getByLabel('Density preset').inputValue(), 'custom');
    message = await errorAfter(page, () => remesh(page));
    assert.match(message, /Density expression uses an unknown name "alert"/);
    assert.equal(await expression.getAttribute('aria-invalid'), 'true');
    // Said when committed, not only at Remesh (a review of the page: an outline, no words).
    await expression.fill('1 + nope');
    message = await errorAfter(page, () => expression.press('Tab'));
    assert.match(message, /Density expression uses an unknown name "nope"/);
    assert.equal(await page.evaluate(() => document.body.dataset.solving), 'false', 'nothing went to the solver');
    await screenshot(page, 'density-expression');
  });
});

// Mean area of the panels on the border (a polygon edge no other panel shares) and of the rest.
function borderAndInnerAreas(text) {
  const { faces } = parseObj(text);
  const uses = new Map();
  const key = (a, b) => (a < b ? `${a},${b}` : `${b},${a}`);
  for (const face of faces) face.forEach((v, i) => uses.set(key(v, face[(i + 1) % face.length]), (uses.get(key(v, face[(i + 1) % face.length])) ?? 0) + 1));
  const areas = panelsOf(text).map((p) => p.area);
  const border = [], inner = [];
  faces.forEach((face, f) => (face.some((v, i) => uses.get(key(v, face[(i + 1) % face.length])) === 1) ? border : inner).push(areas[f]));
  const mean = (list) => list.reduce((s, a) => s + a, 0) / list.length;
  return { border: mean(border), inner: mean(inner), counts: [border.length, inner.length] };
}

test('the "Finer at borders" preset makes the panels along the edge smaller', async () => {
  await suite.withPage(saddleLink(), async (page) => {
    assert.equal(await waitForDone(page), PANELS);
    const uniform = borderAndInnerAreas(await objOf(page));
    await page.getByLabel('Density preset').selectOption({ label: 'Finer at borders' });
    assert.equal(await page.getByLabel('Density expression').inputValue(), '1 + 3 * exp(-border / 0.05)');
    assert.equal(await solveAfter(page, () => remesh(page), 60_000), PANELS);
    const finer = borderAndInnerAreas(await objOf(page));
    const ratio = finer.border / finer.inner;
    console.log(`finer at the border: border / inner panel area ${(uniform.border / uniform.inner).toFixed(3)} uniform -> ${ratio.toFixed(3)} (${finer.counts[0]} border, ${finer.counts[1]} inner panels)`);
    assert.ok(ratio < 0.7 * (uniform.border / uniform.inner), `border / inner panel area ${ratio.toFixed(2)} against ${(uniform.border / uniform.inner).toFixed(2)} uniform (${finer.counts})`);
    await page.getByLabel('Density preset').scrollIntoViewIfNeeded();
    await screenshot(page, 'saddle-60-finer-at-the-border');
  });
});
