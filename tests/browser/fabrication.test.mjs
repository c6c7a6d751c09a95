// Fabrication on the page, in headless Chromium against the built site: a 20 mm thickness,
// the parts list, cut sheets (SVG, parsed by the browser's DOMParser) and solid panels
// downloaded and checked; the thick-panel view; a share link carrying the settings.
// Glass mode (convex panels, acute corners marked), a panel's own thickness set by clicking
// it (in the parts list and carried by a share link). The outputs stay those of the panels on
// show when a solve is cancelled or the solver crashes; a solver that cannot start again leaves
// the panels on show exportable.
// Screenshots: the thick panels and the cut sheets (the SVG rendered in a page).
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { test } from 'node:test';
import { browserSuite, download, errorAfter, outcomes, parseObj, remesh, repo, screenshot, selectExample, setPanels, solveAfter, viewPixels, viewPixelsWithoutProblems, waitForDone, waitForProgress, waitForStatus } from './harness.mjs';

const suite = browserSuite();
const { withPage } = suite;

const fabrications = (page) => page.evaluate(() => Number(document.body.dataset.fabrications ?? 0));

// Runs `action` and waits for the fabrication outputs it asks for. Outputs already asked for
// (a solve asks for its panels' at once) arrive first: counted after them, they cannot pass
// for the action's (CI once read the stats of the solve's outputs, without the thickness).
async function fabricatedAfter(page, action) {
  await page.waitForFunction(() => document.body.dataset.fabricating !== 'true', null, { timeout: 60_000, polling: 50 });
  const since = await fabrications(page);
  await action();
  await page.waitForFunction((since) => Number(document.body.dataset.fabrications ?? 0) > since, since, { timeout: 60_000, polling: 50 });
}

async function setThickness(page, value) {
  await fabricatedAfter(page, async () => {
    await page.getByLabel('Thickness', { exact: true }).fill(String(value));
    await page.getByLabel('Thickness', { exact: true }).press('Tab');
  });
}

// The folded parts' outline colour (thickLayer.ts, 0xe040fb).
const MAGENTA = [224, 64, 251];

async function saddle(page, panels) {
  await waitForDone(page);
  assert.equal(await solveAfter(page, () => selectExample(page, 'saddle')), 120);
  await setPanels(page, panels);
  assert.equal(await solveAfter(page, () => remesh(page)), panels);
}

function csvColumn(rows, name) {
  const index = rows[0].split(',').indexOf(name);
  assert.ok(index >= 0, `no column ${name} in ${rows[0]}`);
  return rows.slice(1).map((row) => row.split(',')[index]);
}

test('20 mm panels: parts list, cut sheets and solid panels download; the thick view toggles', () =>
  withPage(suite.url, async (page) => {
    await saddle(page, 40);
    // The generated saddle is some 30 units across: read as inches, its panels (some 110 mm)
    // fit a 600 x 400 mm board.
    await fabricatedAfter(page, () => page.locator('#fab-mesh-units').selectOption('in'));
    for (const [label, value] of [['#fab-sheet-width', 600], ['#fab-sheet-height', 400]]) {
      await fabricatedAfter(page, async () => {
        await page.locator(label).fill(String(value));
        await page.locator(label).press('Tab');
      });
    }
    await setThickness(page, 20);

    const parts = await download(page, 'Export parts list');
    assert.equal(parts.name, 'saddle-parts.csv');
    const rows = parts.text.trim().split('\n');
    const panelRows = rows.filter((row) => /^\d+,P\d+,/.test(row));
    assert.equal(panelRows.length, 40);
    assert.deepEqual([...new Set(csvColumn([rows[0], ...panelRows], 'thickness'))], ['20']);
    assert.deepEqual([...new Set(csvColumn([rows[0], ...panelRows], 'units'))], ['mm']);

    const json = JSON.parse((await download(page, 'Parts list JSON')).text);
    assert.equal(json.thickness, 20);
    assert.equal(json.totals.panels, 40);

    const sheets = await download(page, 'Export cut sheets');
    assert.equal(sheets.name, 'saddle-sheets.svg');
    const parsed = await page.evaluate((text) => {
      const doc = new DOMParser().parseFromString(text, 'image/svg+xml');
      return { error: doc.querySelector('parsererror')?.textContent ?? null, root: doc.documentElement.nodeName, outer: doc.querySelectorAll('path.outer').length, inner: doc.querySelectorAll('path.inner').length };
    }, sheets.text);
    assert.deepEqual(parsed, { error: null, root: 'svg', outer: 40, inner: 40 });
    const dxf = await download(page, 'Cut sheets DXF');
    assert.match(dxf.text, /AC1009/);

    const solid = parseObj((await download(page, 'Export solid panels')).text);
    const corners = panelRows.map((row) => Number(row.split(',')[2])).reduce((a, b) => a + b, 0);
    assert.equal(solid.faces.length, 2 * 40 + corners, 'a prism per panel');

    const stats = await page.locator('#fab-stats').textContent();
    assert.match(stats, /Max node spread\s*[\d.e-]+ mm/);
    assert.match(stats, /Folded parts\s*0(?![\d:])/);
    assert.equal(await page.locator('#fab-folded-hint').count(), 0);
    assert.deepEqual(json.folded_inner_faces, []);
    assert.match(stats, /Sheets\s*\d+/);
    assert.match(stats, /Material use\s*[\d.]+ %/);

    const canvas = page.locator('#viewport canvas');
    const flat = await canvas.screenshot();
    await page.getByLabel('Show thick panels').check();
    await page.waitForTimeout(300);
    const thick = await canvas.screenshot();
    assert.notDeepEqual(thick, flat, 'the thick panels change the view');
    await screenshot(page, 'saddle-40-thick-20mm');
    await page.getByLabel('Show thick panels').uncheck();

    // The sheets, rendered by the browser.
    const view = await page.context().newPage();
    const svg = sheets.text.replace(/<\?xml[^>]*\?>/, '').replace(/<svg([^>]*?)\swidth="[^"]*"/, '<svg$1 width="1400"').replace(/<svg([^>]*?)\sheight="[^"]*"/, '<svg$1');
    await view.setViewportSize({ width: 1440, height: 900 });
    await view.setContent(`<!doctype html><html><body style="margin:20px;background:#fff">${svg}</body></html>`);
    await view.screenshot({ path: join(repo, 'build', 'screenshots', 'saddle-40-cut-sheets.png'), fullPage: true });
    await view.close();
  }));

// Too thick for the panels (the helicoid is 20 m across, its 40 panels meet at up to 40
// degrees): at 4 m the inner faces of some fold over; the page counts and names those parts
// and says what to do. (The gentle saddle folds none even at 4 m: the chamfers decide.)
test('parts too small for the thickness are named, with what to do', () =>
  withPage(suite.url, async (page) => {
    await waitForDone(page);
    assert.equal(await solveAfter(page, () => selectExample(page, 'helicoid')), 120);
    await setPanels(page, 40);
    assert.equal(await solveAfter(page, () => remesh(page)), 40);
    await setThickness(page, 4000);
    const stats = await page.locator('#fab-stats').textContent();
    const folded = stats.match(/Folded parts\s*(\d+): P\d+/);
    assert.ok(folded && Number(folded[1]) > 0, stats);
    assert.match(await page.locator('#fab-folded-hint').textContent(), /inner face folds over on \d+ parts?: they cannot be cut as drawn/);
    const json = JSON.parse((await download(page, 'Parts list JSON')).text);
    assert.equal(json.folded_inner_faces.length, Number(folded[1]));
    // The view outlines the same parts in magenta, with a legend line; the outline goes with
    // the problems toggle and with a thickness the panels can take.
    const legend = page.locator('#folded-legend');
    await legend.waitFor({ state: 'visible' });
    assert.match(await legend.textContent(), new RegExp(`^\\s*${folded[1]} parts? whose inner face folds over`));
    const outlined = await viewPixels(page, MAGENTA);
    assert.ok(outlined > 200, `${outlined} magenta pixels`);
    await screenshot(page, 'helicoid-40-folded-parts');
    assert.equal(await viewPixelsWithoutProblems(page, MAGENTA), 0, 'the outline hides with the problems');
    // Not 20 mm: there P17's inner corner at its 184° corner next to a 9 mm boundary edge slides
    // 26 mm along, past the edge (the bevel of 7° against the square cut of a near-straight
    // corner), which is a fold too. At 0.5 mm that is 0.7 mm, within the 1 mm a cut is made to.
    await setThickness(page, 0.5);
    assert.equal(await page.locator('#fab-folded-hint').count(), 0, 'gone at a thickness the panels can take');
    assert.equal(await legend.isHidden(), true);
    await page.waitForTimeout(300);
    assert.equal(await viewPixels(page, MAGENTA), 0, 'no outline at 0.5 mm');
  }));

test('a share link carries the fabrication settings', () =>
  withPage(suite.url, async (page) => {
    await saddle(page, 30);
    await setThickness(page, 18);
    await fabricatedAfter(page, () => page.locator('#fab-side').selectOption('outside'));
    await page.getByRole('button', { name: 'Copy share link' }).click();
    await page.waitForFunction(() => location.hash.startsWith('#v1='));
    const link = await page.getByLabel('Share link').inputValue();
    await withPage(link, async (opened) => {
      assert.equal(await waitForDone(opened), 30);
      assert.equal(await opened.getByLabel('Thickness', { exact: true }).inputValue(), '18');
      assert.equal(await opened.locator('#fab-side').inputValue(), 'outside');
      const parts = JSON.parse((await download(opened, 'Parts list JSON')).text);
      assert.equal(parts.thickness, 18);
      assert.equal(parts.side, 'outside');
    });
  }));

test('nodes needing extra chamfer are marked, with a legend line', () =>
  withPage(suite.url, async (page) => {
    await waitForDone(page);
    assert.equal(await solveAfter(page, () => selectExample(page, 'barrel_vault')), 120);
    const legend = page.locator('#spread-legend');
    assert.equal(await legend.isHidden(), true, 'no legend without thickness');
    await setThickness(page, 20);
    await legend.waitFor({ state: 'visible' });
    assert.match(await legend.textContent(), /\d+ nodes? needing extra chamfer/);
    assert.match(await page.locator('#fab-stats').textContent(), /Max node spread\s*0\.\d+ mm/);
    await page.getByLabel('Show thick panels').check();
    await page.waitForTimeout(300);
    await screenshot(page, 'barrel-vault-120-thick-spread-nodes');
  }));

// Every face of a panels OBJ is convex in its own plane (Newell normal; collinear corners
// allowed).
function allConvex({ vertices, faces }) {
  for (const face of faces) {
    const p = face.map((i) => vertices[i]);
    const n = [0, 0, 0];
    for (let i = 0; i < p.length; i++) {
      const a = p[i];
      const b = p[(i + 1) % p.length];
      n[0] += (a[1] - b[1]) * (a[2] + b[2]);
      n[1] += (a[2] - b[2]) * (a[0] + b[0]);
      n[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    const size = Math.hypot(...n);
    for (let i = 0; i < p.length; i++) {
      const a = p[(i + p.length - 1) % p.length];
      const b = p[i];
      const c = p[(i + 1) % p.length];
      const u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
      const v = [c[0] - b[0], c[1] - b[1], c[2] - b[2]];
      const turn = (u[1] * v[2] - u[2] * v[1]) * n[0] + (u[2] * v[0] - u[0] * v[2]) * n[1] + (u[0] * v[1] - u[1] * v[0]) * n[2];
      if (turn < -1e-9 * size * Math.hypot(...u) * Math.hypot(...v)) return false;
    }
  }
  return true;
}

test('glass mode gives convex panels; a minimum corner angle marks the acute corners left', () =>
  withPage(suite.url, async (page) => {
    await waitForDone(page);
    assert.equal(await solveAfter(page, () => selectExample(page, 'freeform_roof')), 120);
    const plain = parseObj((await download(page, 'Export OBJ')).text);
    await page.getByLabel('Glass mode').check();
    await setPanels(page, 60);
    assert.ok((await solveAfter(page, () => remesh(page))) >= 60, 'glass pieces add panels');
    const glass = parseObj((await download(page, 'Export OBJ')).text);
    assert.ok(allConvex(glass), 'every glass panel is convex');
    assert.equal(await page.locator('#viewport').getAttribute('data-acute-corners'), '0', 'no minimum angle: nothing marked');
    // A minimum the solver cannot meet everywhere: what remains is marked and counted.
    await page.getByLabel('Min corner angle').fill('50');
    await page.getByLabel('Min corner angle').press('Tab');
    await solveAfter(page, () => remesh(page));
    const marked = Number(await page.locator('#viewport').getAttribute('data-acute-corners'));
    assert.ok(marked > 0, 'acute corners are marked');
    assert.match(await page.locator('#stats').textContent(), new RegExp(`Acute corners\\s*${marked}`));
    await screenshot(page, 'freeform-roof-glass-acute-corners');
    assert.ok(plain.faces.length > 0);
  }));

test('a clicked panel gets its own thickness, boundary edges a bevel: in the parts list and in a share link', () =>
  withPage(suite.url, async (page) => {
    await saddle(page, 30);
    await setThickness(page, 20);
    const input = page.getByLabel('Panel thickness');
    assert.equal(await input.isDisabled(), true, 'nothing selected yet');
    const box = await page.locator('#viewport canvas').boundingBox();
    await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2);
    const label = await page.waitForFunction(() => document.body.dataset.selectedPanel).then((h) => h.jsonValue());
    assert.match(label, /^P\d+$/);
    assert.equal(await input.isDisabled(), false);
    await fabricatedAfter(page, async () => {
      await input.fill('35');
      await input.press('Tab');
    });
    assert.match(await page.locator('#fab-selected-panel').textContent(), new RegExp(`${label} \\(35 mm\\)`));
    const rowsOf = (text) => text.trim().split('\n');
    const parts = rowsOf((await download(page, 'Export parts list')).text);
    const thickness = Object.fromEntries(parts.slice(1).filter((row) => /^\d+,P\d+,/.test(row)).map((row) => [row.split(',')[1], csvColumn([parts[0], row], 'thickness')[0]]));
    assert.equal(thickness[label], '35');
    assert.equal(Object.values(thickness).filter((t) => t === '20').length, 29);
    await page.getByLabel('Show thick panels').check();
    await page.waitForTimeout(300);
    await screenshot(page, 'saddle-30-one-panel-35mm');
    // Boundary edges bevelled 15 degrees from square; the interior chamfers stay.
    await fabricatedAfter(page, () => page.getByLabel('Boundary edges').selectOption('bevel'));
    await fabricatedAfter(page, async () => {
      await page.getByLabel('Boundary bevel (degrees)').fill('15');
      await page.getByLabel('Boundary bevel (degrees)').press('Tab');
    });
    const bevelled = JSON.parse((await download(page, 'Parts list JSON')).text);
    const boundary = bevelled.panels.flatMap((p) => p.edges).filter((e) => e.neighbour === null);
    assert.ok(boundary.length > 0 && boundary.every((e) => Math.abs(e.chamfer_deg - 15) < 1e-9));

    await page.getByRole('button', { name: 'Copy share link' }).click();
    await page.waitForFunction(() => location.hash.startsWith('#v1='));
    const link = await page.getByLabel('Share link').inputValue();
    await withPage(link, async (opened) => {
      assert.equal(await waitForDone(opened), 30);
      const json = JSON.parse((await download(opened, 'Parts list JSON')).text);
      assert.equal(json.panels.find((p) => p.label === label).thickness, 35);
      assert.equal(await opened.getByLabel('Boundary edges').inputValue(), 'bevel');
      assert.ok(json.panels.flatMap((p) => p.edges).some((e) => e.neighbour === null && Math.abs(e.chamfer_deg - 15) < 1e-9));
    });
  }));

// Clicks Cancel in the page's own task (the solve cannot finish between a check and the click)
// and returns the status right after it.
async function cancelAtOnce(page) {
  return page.getByRole('button', { name: 'Cancel' }).evaluate((button) => {
    button.click();
    return document.querySelector('[role="status"]')?.textContent?.trim() ?? '';
  });
}

// New outputs asked for with the settings of before (20 mm), after something happened.
async function partsListAgain(page) {
  await setThickness(page, 25);
  await setThickness(page, 20);
  return (await download(page, 'Export parts list')).text;
}

// The worker fabricates the panels the page shows (Session.keepPanels), not whatever its solver
// holds: a fresh solve cancelled half-way had left an empty parts list ("0,total,,0,0") under
// the 300 panels on show, and one that finished just before the cancel arrived its own panels.
// (?cancelGrace=60000: the worker is not replaced, next test.)
test('a solve cancelled half-way leaves the parts list of the panels on show', () =>
  withPage(`${suite.url}?cancelGrace=60000`, async (page) => {
    assert.equal(await waitForDone(page), 300);
    await setThickness(page, 20);
    const before = (await download(page, 'Export parts list')).text;
    assert.match(before, /^300,total,/m);
    // Another seed solves afresh: the solver drops its panels at once.
    await page.getByText('Metric and solver').click();
    await page.getByLabel('Seed', { exact: true }).fill('2');
    await setPanels(page, 500);
    await remesh(page);
    await waitForProgress(page);
    assert.match(await cancelAtOnce(page), /^Cancelled/);
    assert.equal(await partsListAgain(page), before);
  }));

// A worker replaced by a cancel (one that did not answer in time: ?cancelGrace=0 always) or
// by a crash holds the mesh but not the panels: it solves the design on show again, quietly,
// and fabricates those (before: an empty parts list, "0,total,,0,0", for any setting changed).
for (const how of ['cancel', 'crash'])
  test(`a solver replaced after a ${how} solves the panels on show again: the same parts list`, () =>
    withPage(`${suite.url}?${how === 'cancel' ? 'cancelGrace=0' : 'crashAfterSteps=3'}`, async (page) => {
      assert.equal(await waitForDone(page), 300);
      await setThickness(page, 20);
      const before = (await download(page, 'Export parts list')).text;
      const first = page.workers()[0];
      const replaced = page.waitForEvent('worker', { timeout: 30_000 });
      const closed = new Promise((resolve) => first.once('close', resolve));
      await setPanels(page, 200);
      if (how === 'cancel') {
        await remesh(page);
        await waitForProgress(page);
        assert.match(await cancelAtOnce(page), /^Cancelled/);
      } else {
        assert.match(await errorAfter(page, () => remesh(page), 60_000), /crashed and was restarted; the last result is kept/);
      }
      await Promise.all([replaced, closed]);
      assert.equal(page.workers().length, 1);
      assert.notEqual(page.workers()[0], first, 'a new worker');
      assert.equal(await partsListAgain(page), before);
      assert.equal(await page.evaluate(() => document.body.dataset.restoring), 'false');
      // And Remesh goes on from there.
      assert.equal(await solveAfter(page, () => remesh(page)), 200);
      assert.match((await download(page, 'Export parts list')).text, /^200,total,.*,mm,20,/m);
    }));

// A fabrication change made as the cancel replaces the worker is held and goes to the new one,
// which cannot answer it yet: it is asked again once the panels are restored (it was lost, and
// the outputs of 20 mm were offered under 33).
test('a fabrication change made with a cancel that replaces the worker is made once the panels are back', () =>
  withPage(`${suite.url}?cancelGrace=0`, async (page) => {
    assert.equal(await waitForDone(page), 300);
    await setThickness(page, 20);
    await setPanels(page, 500);
    await remesh(page);
    await waitForProgress(page);
    const since = await fabrications(page);
    const status = await page.evaluate(() => {
      document.getElementById('cancel').click();
      const thickness = document.getElementById('fab-thickness');
      thickness.value = '33';
      thickness.dispatchEvent(new Event('change', { bubbles: true }));
      return document.querySelector('[role="status"]')?.textContent?.trim() ?? '';
    });
    assert.match(status, /^Cancelled/);
    await page.waitForFunction((since) => Number(document.body.dataset.fabrications ?? 0) > since && document.body.dataset.fabricating === 'false', since, { timeout: 60_000, polling: 50 });
    assert.equal(await page.getByLabel('Thickness', { exact: true }).inputValue(), '33');
    assert.match((await download(page, 'Export parts list')).text, /^300,total,.*,mm,33,/m);
  }));

// A mesh the worker refuses while the new worker restores the panels on show: the load drops
// the restore, so the refusal starts it again (it stayed "restoring" for good, and the
// Fabrication downloads with it).
test('a mesh refused while the panels are restored: they are restored again', () =>
  withPage(`${suite.url}?cancelGrace=0`, async (page) => {
    assert.equal(await waitForDone(page), 300);
    await setThickness(page, 20);
    const before = (await download(page, 'Export parts list')).text;
    await setPanels(page, 200);
    await remesh(page);
    await waitForProgress(page);
    assert.match(await cancelAtOnce(page), /^Cancelled/);
    await page.waitForFunction(() => document.body.dataset.restoring === 'true', null, { timeout: 30_000, polling: 5 });
    const message = await errorAfter(page, () =>
      page.evaluate(() => {
        const transfer = new DataTransfer();
        transfer.items.add(new File(['OFF\n3 1 0\n0 0 0\n'], 'broken.off'));
        document.getElementById('viewport').dispatchEvent(new DragEvent('drop', { dataTransfer: transfer, bubbles: true, cancelable: true }));
      }),
    );
    assert.match(message, /broken\.off|reading the mesh|OFF/);
    assert.equal(await partsListAgain(page), before);
    assert.equal(await page.evaluate(() => document.body.dataset.restoring), 'false');
  }));

// A Remesh during the restore drops it (the worker solves that instead), and a fabrication
// change during that solve waits: the worker keeps no panels then. Cancelled (within the
// grace: the worker stays), the design on show is restored and the change made (it was
// refused, and the downloads then stayed off).
test('a fabrication change during a solve that replaced the restore is made once the panels are back', () =>
  withPage(`${suite.url}?crashAfterSteps=3`, async (page) => {
    assert.equal(await waitForDone(page), 300);
    await setThickness(page, 20);
    await setPanels(page, 200);
    assert.match(await errorAfter(page, () => remesh(page), 60_000), /crashed and was restarted/);
    await page.waitForFunction(() => document.body.dataset.restoring === 'true', null, { timeout: 30_000, polling: 5 });
    await setPanels(page, 600);
    await remesh(page);
    await waitForProgress(page);
    const since = await outcomes(page);
    const fabricated = await fabrications(page);
    await page.evaluate(() => {
      const thickness = document.getElementById('fab-thickness');
      thickness.value = '26';
      thickness.dispatchEvent(new Event('change', { bubbles: true }));
    });
    await page.waitForTimeout(300); // a refusal would have come by now
    assert.match(await cancelAtOnce(page), /^Cancelled/);
    await page.waitForFunction((since) => Number(document.body.dataset.fabrications ?? 0) > since && document.body.dataset.fabricating === 'false', fabricated, { timeout: 60_000, polling: 50 });
    assert.match((await download(page, 'Export parts list')).text, /^300,total,.*,mm,26,/m);
    assert.equal((await outcomes(page)).errors, since.errors, 'no refusal said meanwhile');
  }));

// A replacement worker that cannot start (?failRestart=1, after a crash: as running out of
// memory while instantiating the solver would): the page says so, the quiet restore ends, and a
// fabrication change is refused with what to do (the downloads had stayed off, 'fabricating'
// for good, and a later request went to the dead worker).
test('a solver that cannot start again after a crash: said, and fabrication asks for a reload', () =>
  withPage(`${suite.url}?crashAfterSteps=3&failRestart=1`, async (page) => {
    assert.equal(await waitForDone(page), 300);
    await setThickness(page, 20);
    await setPanels(page, 200);
    await remesh(page);
    await page.waitForFunction(() => (document.querySelector('[role="status"]')?.textContent ?? '').includes('could not start'), null, { timeout: 60_000, polling: 50 });
    assert.match(await page.locator('[role="status"]').textContent(), /the solver could not start: .*\. Reload the page; the panels on show can still be exported and shared\.$/);
    assert.equal(await page.evaluate(() => document.body.dataset.restoring), 'false');
    assert.equal(await page.evaluate(() => document.body.dataset.fabricating), 'false');
    const message = await errorAfter(page, async () => {
      await page.getByLabel('Thickness', { exact: true }).fill('30');
      await page.getByLabel('Thickness', { exact: true }).press('Tab');
    });
    assert.equal(message, 'Error: fabrication: the solver could not start; reload the page');
    assert.equal(await page.evaluate(() => document.body.dataset.fabricating), 'false');
    // The panels on show are still exported and shared (both made on the page); nothing more
    // is asked of the dead worker: Remesh is off, and an open is refused, by name.
    assert.match((await download(page, 'Export OBJ')).text, /^f /m);
    assert.equal(await page.getByRole('button', { name: 'Copy share link' }).isEnabled(), true);
    assert.equal(await page.getByRole('button', { name: 'Remesh' }).isEnabled(), false);
    assert.equal(await page.getByLabel('Subdivide levels').isEditable(), false);
    assert.equal(await errorAfter(page, () => page.getByLabel('Panels', { exact: true }).press('Enter')), 'Error: the solver could not start; reload the page');
    assert.equal(await errorAfter(page, () => selectExample(page, 'saddle')), 'Error: the solver could not start; reload the page');
    assert.equal(await page.getByLabel('Example', { exact: true }).inputValue(), 'hyperboloid_s4', 'the picker shows the design on show');
    await screenshot(page, 'solver-cannot-start');
  }));

// An example picked as the worker crashed, before its replacement says it cannot start: the
// open is lost with it, said, and the page shows the design on show again (the picker, Panels;
// before, the picker and the form stayed on the lost saddle under the hyperboloid's panels).
test('a solver that cannot start again drops an open made meanwhile, said, and shows the design on show', () =>
  withPage(`${suite.url}?crashAfterSteps=3&failRestart=1`, async (page) => {
    assert.equal(await waitForDone(page), 300);
    await setPanels(page, 200);
    await page.evaluate(() => {
      const status = document.querySelector('[role="status"]');
      // Picked at once when the crash is said: the replacement's answer comes in a later task.
      new MutationObserver((_, observer) => {
        if (!status.textContent.includes('crashed and was restarted')) return;
        observer.disconnect();
        const select = document.getElementById('example');
        select.value = 'saddle';
        select.dispatchEvent(new Event('change'));
      }).observe(status, { childList: true, subtree: true, characterData: true });
      document.getElementById('remesh').click();
    });
    await page.waitForFunction(() => (document.querySelector('[role="status"]')?.textContent ?? '').includes('could not start'), null, { timeout: 60_000, polling: 50 });
    assert.match(await page.locator('[role="status"]').textContent(), /the solver could not start: [^;]*; Saddle \(generated\) was not opened\. Reload the page; the panels on show can still be exported and shared\.$/);
    assert.equal(await page.getByLabel('Example', { exact: true }).inputValue(), 'hyperboloid_s4');
    assert.equal(await page.getByLabel('Panels', { exact: true }).inputValue(), '300', 'the parameters of the panels on show');
    assert.match(await page.locator('#mesh-title').textContent(), /Hyperboloid/);
    assert.equal(await page.evaluate(() => document.body.dataset.opening), 'false');
  }));

// A fabrication value refused was said only in the Solve section's status, out of sight, and
// its input looked fine while the outputs kept the value before (a review of the page): it is
// marked and said under the Fabrication inputs, until a valid value replaces it.
test('a refused fabrication value is marked and said beside its input', () =>
  withPage(suite.url, async (page) => {
    await waitForDone(page);
    await setThickness(page, 12);
    const thickness = page.getByLabel('Thickness', { exact: true });
    const error = page.locator('#fab-form-error');
    await thickness.fill('-5');
    await thickness.press('Tab');
    await page.waitForFunction(() => !document.querySelector('#fab-form-error').hidden, null, { timeout: 5000 });
    assert.match(await error.textContent(), /^Thickness .*: the outputs keep the settings before\.$/);
    assert.equal(await thickness.getAttribute('aria-invalid'), 'true');
    assert.equal(JSON.parse((await download(page, 'Parts list JSON')).text).thickness, 12, 'the settings before, as said');
    await screenshot(page, 'fabrication-refused-thickness');
    await setThickness(page, 6);
    assert.equal(await error.isVisible(), false);
    assert.equal(await thickness.getAttribute('aria-invalid'), null);
  }));
