// The designer's page end to end, in headless Chromium against the built site (web/dist):
// examples, remesh, exports, uploads, bad files, cancel, a painting main thread, screenshots.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { test } from 'node:test';
import { wavyGridGlb } from './glb.mjs';
import {
  browserSuite,
  distinctColours,
  download,
  errorAfter,
  exampleLink,
  maxPlanarity,
  outcomes,
  openPage,
  parseObj,
  remesh,
  screenshot,
  selectExample,
  setPanels,
  sharedMeshes,
  solveAfter,
  viewSidePixels,
  statusText,
  viewColour,
  viewPixels,
  viewPixelsWithoutProblems,
  waitForDone,
  waitForProgress,
  waitForSolving,
  waitForStatus,
} from './harness.mjs';

const suite = browserSuite();
const CYAN = [34, 211, 238]; // the farthest point's marker (view/problemLayer.ts)
const VIOLET = [168, 85, 247]; // the sharpest corner's marker (view/problemLayer.ts)
const LIME = [163, 230, 53]; // a collapsed panel's marker (view/problemLayer.ts)
const ORANGE = [249, 115, 22]; // where panels cross (view/problemLayer.ts)
const { withPage } = suite;

test('an example remeshes to the requested count; the OBJ is planar and the parts list matches', () =>
  withPage(suite.url, async (page) => {
    assert.equal(await waitForDone(page), 300, 'the default example solves at start');
    await screenshot(page, 'hyperboloid-300');
    assert.equal(await solveAfter(page, () => selectExample(page, 'saddle')), 120);
    await setPanels(page, 80);
    assert.equal(await solveAfter(page, () => remesh(page)), 80);
    assert.match(await page.locator('#stats').textContent(), /Panels\s*80/);

    const obj = await download(page, 'Export OBJ');
    assert.equal(obj.name, 'saddle-panels.obj');
    const mesh = parseObj(obj.text);
    assert.equal(mesh.faces.length, 80, 'one f line per panel');
    assert.ok(mesh.faces.every((face) => face.length >= 3));
    const planarity = maxPlanarity(mesh);
    assert.ok(planarity <= 1e-9, `every panel planar (max ${planarity})`);

    const parts = await download(page, 'Export parts list');
    assert.equal(parts.name, 'saddle-parts.csv');
    const rows = parts.text.trim().split('\n');
    assert.match(rows[0], /^panel,/, 'a header row');
    assert.equal(rows.filter((row) => /^\d+,P\d+,/.test(row)).length, 80, 'one row per panel');
    await screenshot(page, 'saddle-80');
  }));

test('a mesh opened with "Open mesh" (OFF, then GLB) or dropped on the view is solved', () =>
  withPage(suite.url, async (page) => {
    await waitForDone(page);
    await setPanels(page, 60);
    assert.equal(await solveAfter(page, () => page.getByLabel('Open mesh').setInputFiles(join(sharedMeshes, 'bumpy.off'))), 60);
    assert.match(await page.locator('#mesh-title').textContent(), /bumpy\.off/);
    assert.match(await page.locator('#mesh-details').textContent(), /2,496 triangles/);
    const obj = await download(page, 'Export OBJ');
    assert.equal(obj.name, 'bumpy-panels.obj');
    assert.equal(parseObj(obj.text).faces.length, 60);

    // 512 triangles: 16 panels get 32 each, which the preparation keeps as they are (below 30
    // per panel it would refine the mesh, and the details would name the refined count).
    const glb = wavyGridGlb(16);
    await setPanels(page, 16);
    const open = () => page.getByLabel('Open mesh').setInputFiles({ name: 'canopy.glb', mimeType: 'model/gltf-binary', buffer: glb.bytes });
    assert.equal(await solveAfter(page, open), 16);
    assert.match(await page.locator('#mesh-details').textContent(), new RegExp(`${glb.triangles} triangles`));
    const canopy = parseObj((await download(page, 'Export OBJ')).text);
    // The node's scale (10) and translation (5, 0, -3) reach the core: x spans 5..15 (panel
    // corners where planes meet may lie a little outside the surface's own box).
    const xs = canopy.vertices.map((v) => v[0]);
    assert.ok(Math.min(...xs) > 4.5 && Math.max(...xs) < 15.5 && Math.max(...xs) - Math.min(...xs) > 9, `world coordinates (x in ${Math.min(...xs)}..${Math.max(...xs)})`);
    await screenshot(page, 'uploaded-glb');

    // Dropped on the viewport: a generated OFF (a dome over a 12 x 12 grid).
    const cells = 12;
    const lines = [];
    for (let j = 0; j <= cells; j++) for (let i = 0; i <= cells; i++) lines.push(`${i} ${j} ${(3 - ((i - 6) ** 2 + (j - 6) ** 2) / 24).toFixed(6)}`);
    const faces = [];
    for (let j = 0; j < cells; j++) {
      for (let i = 0; i < cells; i++) {
        const a = j * (cells + 1) + i;
        faces.push(`3 ${a} ${a + 1} ${a + cells + 2}`, `3 ${a} ${a + cells + 2} ${a + cells + 1}`);
      }
    }
    const off = `OFF\n${lines.length} ${faces.length} 0\n${lines.join('\n')}\n${faces.join('\n')}\n`;
    await setPanels(page, 9); // 32 triangles each: kept as they are (as the GLB above)
    const drop = async () => {
      const dataTransfer = await page.evaluateHandle((text) => {
        const transfer = new DataTransfer();
        transfer.items.add(new File([text], 'dome.off', { type: 'text/plain' }));
        return transfer;
      }, off);
      await page.dispatchEvent('#viewport', 'dragover', { dataTransfer });
      await page.dispatchEvent('#viewport', 'drop', { dataTransfer });
    };
    assert.equal(await solveAfter(page, drop), 9);
    assert.match(await page.locator('#mesh-title').textContent(), /dome\.off/);
    assert.match(await page.locator('#mesh-details').textContent(), /288 triangles/);
    assert.equal(await page.locator('#drop-hint').isHidden(), true, 'the drop hint goes away');
  }));

test('a bad file gives a clear message and the previous design keeps working', () =>
  withPage(suite.url, async (page) => {
    await waitForDone(page);
    await solveAfter(page, () => selectExample(page, 'barrel_vault'));
    const garbage = Buffer.from(Array.from({ length: 4096 }, (_, i) => (i * 7919 + 13) % 256));
    const message = await errorAfter(page, () => page.getByLabel('Open mesh').setInputFiles({ name: 'bad.obj', mimeType: 'application/octet-stream', buffer: garbage }));
    assert.match(message, /^Error/);
    assert.match(message, /bad\.obj/, 'the message names the file');
    assert.ok(message.length > 'Error: bad.obj'.length + 5, `the message says what is wrong: ${message}`);
    assert.match(await page.locator('#mesh-title').textContent(), /Barrel vault/, 'the previous mesh stays loaded');
    assert.equal(await page.getByLabel('Example', { exact: true }).inputValue(), 'barrel_vault');
    assert.equal(await page.getByRole('button', { name: 'Export OBJ' }).isEnabled(), true, 'the previous result can still be exported');
    await setPanels(page, 50);
    assert.equal(await solveAfter(page, () => remesh(page)), 50);
    // An empty file, a broken GLB, too many panels: clear messages too, and nothing is lost.
    const empty = await errorAfter(page, () => page.getByLabel('Open mesh').setInputFiles({ name: 'empty.off', mimeType: 'text/plain', buffer: Buffer.alloc(0) }));
    assert.match(empty, /^Error: empty\.off: .*empty/);
    const glb = await errorAfter(page, () => page.getByLabel('Open mesh').setInputFiles({ name: 'broken.glb', mimeType: 'model/gltf-binary', buffer: Buffer.from('glTF not really') }));
    assert.match(glb, /^Error: broken\.glb/);
    await setPanels(page, 99999);
    assert.match(await errorAfter(page, () => remesh(page)), /^Error: .*\S/);
    await setPanels(page, 50);
    assert.equal(await solveAfter(page, () => remesh(page)), 50);
  }));

// "At once" without a stopwatch (a 1 s bound failed CI on a slow machine at 1026 ms): the
// status after the click's own task, before any message from the worker could arrive. A cancel
// that waited for the worker's step to end would still show the progress line here.
async function cancelAtOnce(page) {
  return page.getByRole('button', { name: 'Cancel' }).evaluate((button) => {
    button.click();
    return document.querySelector('[role="status"]')?.textContent?.trim() ?? '';
  });
}

test('Cancel answers at once during a solve, and the page keeps working', () =>
  withPage(suite.url, async (page) => {
    await waitForDone(page);
    await setPanels(page, 500);
    await remesh(page);
    await waitForProgress(page);
    assert.match(await cancelAtOnce(page), /^Cancelled/);
    assert.equal(await page.getByRole('button', { name: 'Cancel' }).isDisabled(), true);
    const afterCancel = await outcomes(page);
    await setPanels(page, 150);
    // Enter in the field solves, like the Remesh button; Escape cancels.
    assert.equal(await solveAfter(page, () => page.getByLabel('Panels', { exact: true }).press('Enter')), 150);
    // Nothing from the cancelled solve arrived: exactly one solve finished since, the new one.
    assert.equal((await outcomes(page)).solves, afterCancel.solves + 1, 'the cancelled solve never finished on the page');
    await setPanels(page, 400);
    await remesh(page);
    await waitForSolving(page);
    await page.keyboard.press('Escape');
    await waitForStatus(page, /Cancelled/); // a solve left to run would end in "Done"
  }));

test('a cancel that replaces the worker (as for a long step) leaves the page working and deterministic', async () => {
  const { context, page, errors } = await openPage(suite.browser, `${suite.url}?cancelGrace=0`);
  try {
    assert.equal(await waitForDone(page), 300);
    const busyWorker = page.workers()[0];
    assert.ok(busyWorker, 'the solver runs in a worker');
    const first = (await download(page, 'Export OBJ')).text;
    await setPanels(page, 500);
    await remesh(page);
    await waitForProgress(page);
    const replacement = page.waitForEvent('worker', { timeout: 10_000 });
    const closed = new Promise((resolve) => busyWorker.once('close', resolve));
    assert.match(await cancelAtOnce(page), /^Cancelled/);
    await Promise.all([replacement, closed]);
    assert.equal(page.workers().length, 1, 'one solver worker');
    assert.notEqual(page.workers()[0], busyWorker, 'the busy worker was replaced by a new one');
    await setPanels(page, 300);
    assert.equal(await solveAfter(page, () => remesh(page)), 300);
    assert.equal((await download(page, 'Export OBJ')).text, first, 'the new worker solves to the identical OBJ');
    assert.deepEqual(errors, []);
  } finally {
    await context.close();
  }
});

test('a parameter change during a solve reaches the worker and warm-starts it', () =>
  withPage(suite.url, async (page) => {
    await waitForDone(page);
    // A solve of several seconds, so the change lands in it even on a loaded machine (with 20
    // iterations at 500 panels it once finished first under a parallel build: two solves).
    await page.getByText('Metric and solver').click();
    await page.getByLabel('Lloyd iterations').fill('100');
    const since = await outcomes(page);
    await setPanels(page, 1200);
    await remesh(page);
    await waitForProgress(page);
    await page.getByLabel('Panels', { exact: true }).fill('220');
    await page.getByLabel('Panels', { exact: true }).press('Enter');
    assert.equal(await waitForDone(page, since), 220, 'the running solve finished with the new count');
    assert.equal((await outcomes(page)).solves, since.solves + 1, 'one solve, not a restart after the first');
    const obj = parseObj((await download(page, 'Export OBJ')).text);
    assert.equal(obj.faces.length, 220);
  }));

test('the main thread keeps painting frames during a long solve', () =>
  withPage(suite.url, async (page) => {
    await waitForDone(page);
    await page.getByText('Metric and solver').click();
    await page.getByLabel('Lloyd iterations').fill('100');
    await setPanels(page, 1200); // a solve of several seconds
    // Frames are recorded from now on; the solve's span is from its first progress line on the
    // page to its result, so a fast machine that finishes early still measures what it ran.
    await page.evaluate(() => {
      const record = { frames: [], longTasks: [], firstProgress: null, done: null };
      window.frameRecord = record;
      // Tasks of 50 ms or more on the main thread (Long Tasks API): what our own code blocks.
      if (!PerformanceObserver.supportedEntryTypes.includes('longtask')) throw new Error('no Long Tasks API');
      new PerformanceObserver((list) => {
        for (const entry of list.getEntries()) record.longTasks.push({ start: entry.startTime, duration: entry.duration });
      }).observe({ type: 'longtask' });
      const tick = (now) => {
        record.frames.push(now);
        if (record.done === null) requestAnimationFrame(tick);
      };
      requestAnimationFrame(tick);
      const status = document.querySelector('[role="status"]');
      new MutationObserver(() => {
        const text = status.textContent ?? '';
        if (record.firstProgress === null && text.startsWith('Solving:')) record.firstProgress = performance.now();
        if (record.firstProgress !== null && record.done === null && /Done: \d+ panels$/.test(text)) record.done = performance.now();
      }).observe(status, { childList: true, characterData: true, subtree: true });
    });
    const since = await outcomes(page);
    await remesh(page);
    await waitForProgress(page);
    // Input is handled at once too: a view toggle is drawn in the next frames (time from the
    // click to the second animation frame after it, i.e. the frame its redraw went into).
    const latency = await page.evaluate(
      () =>
        new Promise((resolve) => {
          const box = document.getElementById('show-edges');
          const t = performance.now();
          box.click();
          requestAnimationFrame(() => requestAnimationFrame(() => resolve(performance.now() - t)));
        }),
    );
    await screenshot(page, 'clusters-converging');
    assert.equal(await waitForDone(page, since), 1200);
    const record = await page.evaluate(() => window.frameRecord);
    assert.ok(record.firstProgress !== null && record.done !== null, 'the solve was seen from its first progress to its result');
    const span = record.done - record.firstProgress;
    const frames = record.frames.filter((t) => t >= record.firstProgress && t <= record.done);
    const edges = [record.firstProgress, ...frames, record.done];
    const maxGap = Math.max(...edges.slice(1).map((t, i) => t - edges[i]));
    const during = record.longTasks.filter((task) => task.start + task.duration >= record.firstProgress && task.start <= record.done);
    const longest = Math.max(0, ...during.map((task) => task.duration));
    // Lenient for a software rasteriser on 2 busy cores (a GPU paints 60 a second; 6 a second
    // measured here with other work running); a solve on the main thread would paint none, and
    // would be one task of seconds.
    const perSecond = (frames.length / span) * 1000;
    if (process.env.FF_FRAME_STATS) console.log(`frames: ${frames.length} in ${span.toFixed(0)} ms (${perSecond.toFixed(1)}/s), max gap ${maxGap.toFixed(0)} ms, longest task ${longest.toFixed(0)} ms (${during.length} of 50 ms or more), toggle ${latency.toFixed(0)} ms`);
    assert.ok(perSecond >= 3, `at least 3 frames a second while solving (${frames.length} in ${span.toFixed(0)} ms)`);
    // As lenient as the frame gap below: software GL on 2 busy cores takes ~300 ms per redraw.
    assert.ok(latency < 1000, `a toggle is on screen ${latency.toFixed(0)} ms after the click`);
    assert.ok(longest < 1000, `no main-thread task of 1 s or more while solving (longest ${longest.toFixed(0)} ms)`);
    // Our longest tasks measured here are 110-310 ms (the result of 1200 panels taken in); a solve
    // on this thread would be one task of several seconds. A frame gap also counts time the machine
    // gave to other processes (a gap of 500 ms failed a CI run on 2 shared cores): a looser bound.
    assert.ok(maxGap < 1500, `no frame gap of 1.5 s or more while solving (max ${maxGap.toFixed(0)} ms)`);
  }));

test('screenshots of the page after a solve, in each view', () =>
  withPage(suite.url, async (page) => {
    await waitForDone(page);
    assert.equal(await solveAfter(page, () => selectExample(page, 'inspired_mesh')), 120);
    const shot = await screenshot(page, 'inspired-panels');
    assert.ok(readFileSync(shot).length > 20_000, 'a real picture, not a blank page');
    const panelsView = await distinctColours(page, '#viewport canvas');
    await page.getByLabel('Show panels').uncheck();
    await page.getByLabel('Show clusters').check();
    assert.notEqual(await distinctColours(page, '#viewport canvas'), panelsView, 'the clusters view differs from the panels view');
    await screenshot(page, 'inspired-clusters');
    await page.getByLabel('Show clusters').uncheck();
    await page.getByLabel('Show panels').check();
    // Before the fix: the corner polygons, coloured by how far they are from planar.
    await page.getByLabel('Show before the fix').check();
    assert.equal(await page.locator('#view-legend').isVisible(), true, 'the legend explains the colours');
    assert.notEqual(await distinctColours(page, '#viewport canvas'), panelsView, 'the before view differs from the panels view');
    assert.match(await page.locator('#stats').textContent(), /Before the fix\s*\d\.\d×10/);
    await screenshot(page, 'inspired-before-fix');
    await page.getByLabel('Show before the fix').uncheck();
    await solveAfter(page, () => selectExample(page, 'YasIsland'));
    await screenshot(page, 'yasisland-panels');
    await solveAfter(page, () => selectExample(page, 'freeform_roof'));
    await screenshot(page, 'freeform-roof-panels');
    // The viewport really draws the model (many panel colours), not just its background.
    const distinct = await distinctColours(page, '#viewport canvas');
    assert.ok(distinct > 30, `the viewport shows the panels (${distinct} distinct colours)`);
  }));

// Where the panels are farthest from the design: a cyan point in the view (with the problems)
// and a legend line giving the report's Hausdorff distance, as the Quality section does; the
// sharpest corner the same way (violet, the Quality section's "Min angle"); and
// the deviation view, each panel coloured by its own distance, with its scale.
test('the point farthest from the design and the sharpest corner are marked, with their values; the deviation view colours the panels', () =>
  withPage(suite.url, async (page) => {
    assert.equal(await waitForDone(page), 300);
    const legend = page.locator('#farthest-legend');
    await legend.waitFor({ state: 'visible' });
    const hausdorff = (await page.locator('#stats').textContent()).match(/Hausdorff\s*([\d.]+) %/);
    assert.ok(hausdorff, 'the Quality section gives the Hausdorff distance');
    assert.equal((await legend.textContent()).trim(), `Farthest from the design: ${hausdorff[1]} % of the diagonal`);
    const marked = await viewPixels(page, CYAN);
    assert.ok(marked > 20, `${marked} cyan pixels`);
    // The sharpest corner: a violet point, and a legend line giving the Quality section's angle.
    const minAngle = (await page.locator('#stats').textContent()).match(/Min angle\s*([\d.]+)°/);
    assert.ok(minAngle, 'the Quality section gives the smallest corner angle');
    assert.equal((await page.locator('#sharpest-legend').textContent()).trim(), `Sharpest corner: ${minAngle[1]}°`);
    const sharpest = await viewPixels(page, VIOLET);
    assert.ok(sharpest > 20, `${sharpest} violet pixels`);
    // Coverage: no collapsed panel in this design, so no warning.
    assert.match(await page.locator('#stats').textContent(), /Coverage\s*\d+ % \(P\d+\)/);
    assert.equal(await page.locator('#stats dd.warn').count(), 0, 'nothing to warn about');
    await screenshot(page, 'hyperboloid-300-farthest-point');
    assert.equal(await viewPixelsWithoutProblems(page, CYAN), 0, 'the marker hides with the problems');
    assert.equal(await viewPixelsWithoutProblems(page, VIOLET), 0, 'the corner marker hides with the problems');
    const panelsView = await distinctColours(page, '#viewport canvas');
    await page.getByLabel('Show deviation from the design').check();
    const scale = page.locator('#deviation-legend');
    assert.equal(await scale.isVisible(), true, 'the deviation view has its legend');
    const top = (await page.locator('#deviation-top').textContent()).match(/^([\d.]+) % of the diagonal$/);
    assert.ok(top && Math.abs(Number(top[1]) - Number(hausdorff[1])) <= 0.1 * Number(hausdorff[1]), `scale tops at ${top?.[1]}, Hausdorff ${hausdorff[1]}`);
    assert.notEqual(await distinctColours(page, '#viewport canvas'), panelsView, 'the deviation colours differ from the panel colours');
    await screenshot(page, 'hyperboloid-300-deviation');
    await page.getByLabel('Show deviation from the design').uncheck();
    assert.equal(await scale.isHidden(), true);
    // Another design: the legend follows its own solve.
    assert.equal(await solveAfter(page, () => selectExample(page, 'saddle')), 120);
    const next = (await page.locator('#stats').textContent()).match(/Hausdorff\s*([\d.]+) %/);
    assert.match(await legend.textContent(), new RegExp(`${next[1].replace('.', '\\.')} % of the diagonal`));
    const nextAngle = (await page.locator('#stats').textContent()).match(/Min angle\s*([\d.]+)°/);
    assert.equal((await page.locator('#sharpest-legend').textContent()).trim(), `Sharpest corner: ${nextAngle[1]}°`);
  }));

// A surface that passes through itself, marked as soon as it opens: cow.off's tail goes into
// its rump. While it is on show without panels (here: the solve of 2,000 panels that follows
// the open, its preparation alone seconds), an orange point marks each crossing pair (83, in 4
// places at its back, where the tail goes in and out), with a legend line that counts both.
test('a surface that passes through itself is marked in the view when it opens', async () => {
  await suite.withPage(suite.url, async (page) => {
    // The example's own solve first: a count typed while it runs would go to it (a solve of
    // 2,000 panels of the example, which the open then waits on).
    await waitForDone(page);
    await setPanels(page, 2000);
    await page.getByLabel('Open mesh').setInputFiles(join(sharedMeshes, 'cow.off'));
    // Read and prepared for 2,000 panels (115,352 triangles) before it shows: as the other
    // opens of the cow, up to 2 minutes on a loaded machine.
    await page.locator('#mesh-title', { hasText: 'cow.off' }).waitFor({ timeout: 120_000 });
    assert.equal((await page.locator('#crossing-legend').textContent()).trim(), 'The surface passes through itself: 83 pairs of its triangles in 4 places, each marked');
    assert.equal(await page.locator('#viewport').getAttribute('data-self-crossing-markers'), '83');
    assert.ok((await viewPixels(page, ORANGE)) > 10, 'an orange point where it passes through itself');
    await screenshot(page, 'cow-self-crossing-marked');
  });
});

// A collapsed panel: cow.off (uploaded) into 61 panels at seed 11 ends valid by the paper's
// checks, but panel 47 is a sliver covering 1 % of its own triangles, left by the mends of
// its long run, where the coverage rounds do not reach (the CLI's report says the same:
// min_panel_coverage_panel 46). The Coverage row warns and names it; the view marks it (a
// lime point) with a legend line whose button selects it; merged with a neighbour, it is gone.
test('a collapsed panel is named, marked and selected from its legend, then merged away', async () => {
  const params = { panels: 61, seed: 11, weights: { euclidean: 1, l2: 1, l21: 1, boundary: 1 }, lloydIterations: 20, panelRounds: 100, seeding: 'farthest', teleport: true, singlePointNodes: false, optimizePlanes: true };
  await suite.withPage(exampleLink(suite.url, 'epcot', params), async (page) => {
    assert.equal(await waitForDone(page), 61);
    assert.equal(await page.locator('#stats dd.warn').count(), 0, 'the sphere at 61 panels has no collapsed panel');
    const legend = page.locator('#collapsed-legend');
    assert.equal(await legend.isHidden(), true);
    assert.equal(await viewPixels(page, LIME), 0);
    const selfCrossing = page.locator('#mesh-self-crossing');
    assert.equal(await selfCrossing.isHidden(), true, 'the sphere does not pass through itself');
    assert.equal(await solveAfter(page, () => page.getByLabel('Open mesh').setInputFiles(join(sharedMeshes, 'cow.off')), 120_000), 61);
    // Said on load, beside what the load repaired: the model passes through itself.
    assert.equal(await selfCrossing.isVisible(), true);
    assert.match(await selfCrossing.textContent(), /^The surface passes through itself: 83 pairs of its triangles cross in 4 places, one near \(-0\.4\d*, 0\.2\d*, -0\.00\d*\)\. Panels made from it can pass through each other there, whatever their count: mend the model there before building\.$/);
    await selfCrossing.scrollIntoViewIfNeeded();
    await screenshot(page, 'cow-self-crossing-on-load');
    const row = page.locator('#stats dd.warn', { hasText: '% (P' });
    assert.equal((await row.textContent()).trim(), '1 % (P47)');
    assert.match(await row.getAttribute('title'), /1 here\. Select P47 and merge it with a neighbour/);
    // The cow's panels also pass through each other where its tail goes into its rump (the
    // model itself passes through itself there): the Crossing row warns and names the pairs.
    const crossing = page.locator('#stats dt', { hasText: 'Crossing' }).locator('xpath=following-sibling::dd[1]');
    assert.ok(Number(await crossing.textContent()) > 0);
    assert.equal(await crossing.getAttribute('class'), 'warn');
    assert.match(await crossing.getAttribute('title'), /pass through each other in space \(P\d+ and P\d+/);
    assert.match(await page.locator('#crossing-legend').textContent(), /Panels passing through each other: \d+ pairs \(the surface passes through itself there\)/);
    assert.ok((await viewPixels(page, ORANGE)) > 10, 'orange markers where they cross');
    await row.scrollIntoViewIfNeeded();  // the Quality section, beside the view
    await screenshot(page, 'cow-61-collapsed-panel');

    // The marker and its legend line, which gives the same panel and share.
    assert.equal(await legend.isVisible(), true);
    assert.match(await legend.textContent(), /Collapsed panel P47: covers 1 % of its triangles/);
    const marker = await viewColour(page, LIME);
    assert.ok(marker.count > 20, `${marker.count} lime pixels`);
    assert.equal(await viewPixelsWithoutProblems(page, LIME), 0, 'the marker hides with the problems');

    // Select it from the legend: the panel edits take it, as a click on it in the view would.
    await page.getByRole('button', { name: 'Select P47' }).click();
    assert.match(await page.locator('#edit-hint').textContent(), /^P47 selected\./);
    const merge = page.getByRole('button', { name: 'Merge with neighbour' });
    assert.equal(await merge.isDisabled(), false);
    assert.equal(await merge.evaluate((button) => button === document.activeElement), true, 'the next step has the focus');
    await screenshot(page, 'cow-61-collapsed-selected');

    // Merge it with a panel beside the marker: one panel fewer, and none collapsed.
    await merge.click();
    const since = await outcomes(page);
    const box = await page.locator('#viewport canvas').boundingBox();
    const edits = () => page.evaluate(() => Number(document.body.dataset.editCount ?? 0));
    search: for (const radius of [0.01, 0.02, 0.04])
      for (let k = 0; k < 8; k++) {
        if ((await edits()) > 0) break search;
        const angle = (k * Math.PI) / 4;
        await page.mouse.click(box.x + box.width * (marker.fx + radius * Math.cos(angle)), box.y + box.height * (marker.fy + radius * Math.sin(angle)));
      }
    assert.equal(await edits(), 1, 'a panel beside the marker was merged with it');
    assert.equal(await waitForDone(page, since), 60, 'a merge makes one panel fewer');
    assert.equal(await page.locator('#stats dd.warn', { hasText: '% (P' }).count(), 0, 'no collapsed panel after the merge');
    assert.equal(await legend.isHidden(), true);
    assert.equal(await viewPixels(page, LIME), 0, 'the marker is gone');
  });
});

// A closed sphere (epcot.off) into 4 panels at seed 1: the first solve's panels stay invalid;
// the retry from a new seeding (RemeshParams.retries, default 8) makes a valid tetrahedron.
// The progress line says so while it retries, so the progress bar going back to the start
// does not look like a fault.
test('a solve whose panels stay invalid retries from a new seeding and says so', async () => {
  const params = { panels: 5, seed: 2, weights: { euclidean: 1, l2: 1, l21: 1, boundary: 1 }, lloydIterations: 20, panelRounds: 100, seeding: 'farthest', teleport: true, singlePointNodes: false, optimizePlanes: true };
  await suite.withPage(exampleLink(suite.url, 'epcot', params), async (page) => {
    assert.equal(await waitForDone(page), 5);
    assert.ok(!/invalid|could not/.test(await statusText(page)), 'no retry note or problem after a valid solve');
    await page.evaluate(() => {
      window.statusTexts = [];
      const status = document.querySelector('[role="status"]');
      new MutationObserver(() => window.statusTexts.push(status.textContent ?? '')).observe(status, { childList: true, characterData: true, subtree: true });
    });
    await page.locator('#solver-options > summary').click();  // "Metric and solver" opens
    await page.getByLabel('Seed', { exact: true }).fill('1');
    await setPanels(page, 4);
    assert.equal(await solveAfter(page, () => remesh(page)), 4);
    assert.equal(await statusText(page), 'Done: 4 panels', 'valid after the retry');
    const texts = await page.evaluate(() => window.statusTexts);
    assert.ok(
      texts.some((text) => /^Solving: .* · panels stayed invalid: new seeding, try 2 of 9 · /.test(text)),
      `the retry is named in the progress line (${texts.length} texts)`,
    );
    await screenshot(page, 'epcot-4-after-retry');
  });
});

// bunny.off into 77 panels at seed 3 is valid after 4 rounds with a corner of 0.3 degrees: the
// needle rounds take the stage back from Optimize to Panels (tests/core/test_needle_rounds.cpp).
// The progress line says why, so the bar going back does not look like a fault.
test('the needle rounds are named in the progress line', async () => {
  await suite.withPage(suite.url, async (page) => {
    // Opened at 77 panels, so the preparation keeps its 6,966 triangles (90 per panel).
    await waitForDone(page);
    await setPanels(page, 77);
    await solveAfter(page, () => page.getByLabel('Open mesh').setInputFiles(join(sharedMeshes, 'bunny.off')), 120_000);
    assert.match(await page.locator('#mesh-details').textContent(), /^6,966 triangles/);
    await page.evaluate(() => {
      window.statusTexts = [];
      const status = document.querySelector('[role="status"]');
      new MutationObserver(() => window.statusTexts.push(status.textContent ?? '')).observe(status, { childList: true, characterData: true, subtree: true });
    });
    await page.locator('#solver-options > summary').click(); // "Metric and solver" opens
    await page.getByLabel('Seed', { exact: true }).fill('3');
    await setPanels(page, 77);
    assert.equal(await solveAfter(page, () => remesh(page), 120_000), 77);
    assert.equal(await statusText(page), 'Done: 77 panels');
    const texts = await page.evaluate(() => window.statusTexts);
    const needle = texts.findIndex((text) => /^Solving: panel round \d+ of \d+ · valid, but a corner is below 1°: more rounds to widen it · /.test(text));
    assert.ok(needle >= 0, `the needle rounds are named in the progress line (${texts.length} texts)`);
    assert.ok(!texts.slice(0, needle).some((text) => text.includes('below 1°')), 'not before');
    // A needle counts as a problem in these rounds, but the line never says "invalid" beside "valid".
    assert.ok(!texts.some((text) => text.includes('below 1°') && text.includes('invalid')), 'no "invalid" beside "valid"');
    await screenshot(page, 'bunny-77-after-needle-rounds');
  });
});

// The Yas Island grid shell into 4 panels stays invalid through every retry (seed 1): the
// status line says what is wrong with the panels shown red, that a cluster found no panel, and
// what to try; the Invalid row counts the same, with the problems in its hint.
test('panels that stay invalid are named with their problems and what to try', async () => {
  const params = { panels: 4, seed: 1, weights: { euclidean: 1, l2: 1, l21: 1, boundary: 1 }, lloydIterations: 20, panelRounds: 100, seeding: 'farthest', teleport: true, singlePointNodes: false, optimizePlanes: true };
  await suite.withPage(exampleLink(suite.url, 'YasIsland', params), async (page) => {
    await waitForDone(page);
    const text = await statusText(page);
    assert.match(
      text,
      /^(\d+) invalid panels? \(shown red: [a-z -]+ \d+(, [a-z -]+ \d+)*\); 1 cluster could not become a panel; another seed or panel count \(more or fewer\) may make every panel valid\. Done: \d+ panels$/,
      text,
    );
    const red = Number(/^(\d+)/.exec(text)[1]);
    const row = page.locator('#stats dt:text-is("Invalid") + dd');
    assert.equal(await row.getAttribute('class'), 'warn', 'the Invalid row warns');
    assert.equal((await row.textContent()).trim(), String(red + 1), 'the Invalid row counts the red panels and the cluster');
    assert.match(await row.getAttribute('title'), /: (flipped|not star-shaped|self-intersecting) \d+/);
    await screenshot(page, 'yas-4-invalid-named');
  });
});

// The view frames the model by the narrower of its two view angles (and frames it again when
// the window changes shape while the designer has not moved the view): in a narrow window
// (800 x 700: the view taller than wide) the saddle was cut off at both sides, framed by the
// vertical angle alone (a review of the page).
test('a narrow window frames the whole model', async () => {
  const { context, page, errors } = await openPage(suite.browser, suite.url, { width: 800, height: 700 });
  try {
    assert.equal(await waitForDone(page), 300);
    assert.equal(await solveAfter(page, () => selectExample(page, 'saddle')), 120);
    await screenshot(page, 'narrow-window');
    // The background is 0x24272c (viewer.ts).
    const atSides = await viewSidePixels(page, [0x24, 0x27, 0x2c]);
    assert.ok(atSides.width < atSides.height, `the view is taller than wide (${atSides.width} x ${atSides.height})`);
    assert.equal(atSides.count, 0, 'no part of the model at the view\'s left and right edges');
    assert.deepEqual(errors, []);
  } finally {
    await context.close();
  }
});

// The view takes the keyboard (it took none before): Tab reaches the canvas, which says how
// to use it; Shift and the arrow keys turn the model, the arrow keys move it.
test('the view takes the keyboard: focus, turn with Shift and the arrows, move with the arrows', async () => {
  await suite.withPage(suite.url, async (page) => {
    await waitForDone(page);
    const canvas = page.locator('#viewport canvas');
    assert.equal(await canvas.getAttribute('tabindex'), '0');
    assert.equal(await canvas.getAttribute('aria-describedby'), 'view-keys');
    assert.match(await page.locator('#view-keys').textContent(), /press Shift and the arrow keys, to turn the view; the arrow keys move it; the wheel, or \+ and -, zooms/);
    await canvas.focus();
    assert.equal(await canvas.evaluate((c) => c === document.activeElement), true);
    const before = await canvas.screenshot();
    for (let i = 0; i < 8; ++i) await page.keyboard.press('Shift+ArrowLeft');
    const turned = await canvas.screenshot();
    assert.equal(turned.equals(before), false, 'Shift and the arrows turn the view');
    for (let i = 0; i < 8; ++i) await page.keyboard.press('ArrowUp');
    const moved = await canvas.screenshot();
    assert.equal(moved.equals(turned), false, 'the arrows move it');
    // + comes closer (the model covers more of the view), - steps back past where it was.
    const background = [0x24, 0x27, 0x2c];
    const open = await viewPixels(page, background);
    for (let i = 0; i < 3; ++i) await page.keyboard.press('+');
    const closer = await viewPixels(page, background);
    assert.ok(closer < open, `+ zooms in: ${closer} background pixels, ${open} before`);
    for (let i = 0; i < 6; ++i) await page.keyboard.press('-');
    const farther = await viewPixels(page, background);
    assert.ok(farther > open, `- zooms out: ${farther} background pixels, ${open} before +`);
    await screenshot(page, 'view-keyboard');
  });
});
