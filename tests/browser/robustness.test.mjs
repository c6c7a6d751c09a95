// The page under races, crashes and hostile input, in headless Chromium against the built
// site: Remesh while a mesh opens, a cancel during an earlier cancel, a crashing worker, glTF
// files that point elsewhere, links too large to travel, stale link messages and hashes, the
// stored session, a site built without the shared example meshes, and an example that fails
// while another mesh loads.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { test } from 'node:test';
import {
  browserSuite,
  download,
  errorAfter,
  exampleLink,
  openPage,
  outcomes,
  recordStatus,
  remesh,
  screenshot,
  selectExample,
  sharedMeshes,
  setPanels,
  solveAfter,
  statusText,
  waitForDone,
  waitForProgress,
  waitForSaved,
  waitForStatus,
  waitForStatusSeen,
} from './harness.mjs';
import { movedOff } from '../fixtures/meshes.mjs';

const suite = browserSuite();
const { withPage } = suite;

// A file dropped on the view, as a designer would.
function dropFile(page, name, text) {
  return page.evaluate(
    ([name, text]) => {
      const transfer = new DataTransfer();
      transfer.items.add(new File([text], name));
      document.getElementById('viewport').dispatchEvent(new DragEvent('drop', { dataTransfer: transfer, bubbles: true, cancelable: true }));
    },
    [name, text],
  );
}

// An n x n quad saddle as OFF (large enough that its load in the worker takes a while).
function pringleOff(n) {
  const lines = [];
  for (let j = 0; j <= n; j++) for (let i = 0; i <= n; i++) lines.push(`${i} ${j} ${(((i - n / 2) ** 2 - (j - n / 2) ** 2) / (n * 10)).toFixed(4)}`);
  const faces = [];
  for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) faces.push(`4 ${j * (n + 1) + i} ${j * (n + 1) + i + 1} ${(j + 1) * (n + 1) + i + 1} ${(j + 1) * (n + 1) + i}`);
  return `OFF\n${lines.length} ${faces.length} 0\n${lines.join('\n')}\n${faces.join('\n')}\n`;
}

// The Surface inputs are read-only meanwhile: the open has read them, and a value typed then
// would give way to the opened mesh's own without a word.
test('Remesh, Enter and Share are refused while a mesh opens; the new mesh solves under its own name', () =>
  withPage(suite.url, async (page) => {
    await waitForDone(page);
    const since = await outcomes(page);
    // In one task: pick another example, then at once press Remesh, Enter and Copy share link.
    const buttons = await page.evaluate(() => {
      const select = document.getElementById('example');
      select.value = 'helicoid';
      select.dispatchEvent(new Event('change'));
      const state = {
        remesh: document.getElementById('remesh').disabled,
        share: document.getElementById('share').disabled,
        surfaceReadOnly: ['subdivide', 'edge-length', 'fill-holes'].map((id) => document.getElementById(id).readOnly),
      };
      document.getElementById('remesh').click();
      document.getElementById('share').click();
      document.getElementById('panels').dispatchEvent(new KeyboardEvent('keydown', { key: 'Enter', bubbles: true }));
      return state;
    });
    assert.deepEqual(buttons, { remesh: true, share: true, surfaceReadOnly: [true, true, true] }, 'disabled while opening');
    assert.equal(await waitForDone(page, since), 120);
    assert.equal((await outcomes(page)).solves, since.solves + 1, 'one solve: the one the open starts');
    assert.match(await page.locator('#mesh-title').textContent(), /Helicoid/);
    assert.equal(await page.evaluate(() => location.hash), '', 'no link was published');
    const obj = await download(page, 'Export OBJ');
    assert.equal(obj.name, 'helicoid-panels.obj');
    assert.equal(await page.getByRole('button', { name: 'Remesh' }).isEnabled(), true);
    for (const label of ['Subdivide levels', 'Target edge length', 'Fill holes up to (edges)']) assert.equal(await page.getByLabel(label).isEditable(), true, label);
  }));

test('a load overtaken by an open that fails: the page shows, and solves, the mesh the worker holds', () =>
  withPage(suite.url, async (page) => {
    await waitForDone(page);
    await solveAfter(page, () => selectExample(page, 'saddle'));
    await setPanels(page, 6);
    const since = await outcomes(page);
    // A large OFF goes to the worker; while it loads there, a GLB that fails on the page.
    // The load may pass between two polls (CI once missed it for 30 s polling each frame):
    // an observer records that it reached the worker.
    await page.evaluate(() => {
      window.sawLoading = false;
      new MutationObserver(() => {
        if (document.body.dataset.opening === 'loading') window.sawLoading = true;
      }).observe(document.body, { attributes: true, attributeFilter: ['data-opening'] });
    });
    await dropFile(page, 'pringle.off', pringleOff(160));
    await page.waitForFunction(() => window.sawLoading, null, { timeout: 30_000, polling: 20 });
    await dropFile(page, 'broken.glb', 'glTF not really');
    // Which finishes first is up to the browser; wait until both have, and any solve too.
    await page
      .waitForFunction(
        (since) => Number(document.body.dataset.errors ?? 0) > since.errors && document.body.dataset.opening === 'false' && document.body.dataset.solving === 'false',
        since,
        { timeout: 30_000, polling: 20 },
      )
      .catch(async (error) => {
        // Which of the three never came: say so (this wait timed out once in a full local run;
        // alone and in its file it passed 8 of 8 times, so the cause is not known yet).
        const state = await page.evaluate(() => ({ ...document.body.dataset, status: document.getElementById('status')?.textContent }));
        throw new Error(`${error.message}\nsince ${JSON.stringify(since)}, page ${JSON.stringify(state)}`);
      });
    const title = (await page.locator('#mesh-title').textContent()).trim();
    assert.ok(['Saddle (generated)', 'pringle.off'].includes(title), title);
    assert.equal(await solveAfter(page, () => remesh(page)), 6);
    const obj = await download(page, 'Export OBJ');
    const input = /^# input: (.*)$/m.exec(obj.text)?.[1];
    assert.equal(input, title === 'pringle.off' ? 'pringle.off' : 'saddle', 'the worker solved the mesh the page shows');
    assert.equal(obj.name, title === 'pringle.off' ? 'pringle-panels.obj' : 'saddle-panels.obj');
  }));

// An example that fails on the page while a file loads in the worker: the example had written
// its own panel count (100) into the form, and the file, solved with the 6 it was opened with,
// then showed 100 in Panels, so the next Remesh solved 100.
test('an example that fails while another mesh loads leaves the form to that mesh', () =>
  withPage(suite.url, async (page) => {
    await waitForDone(page);
    await solveAfter(page, () => selectExample(page, 'saddle'));
    await setPanels(page, 6);
    await page.route('**/examples/epcot.off', (route) => route.abort());
    const since = await outcomes(page);
    await page.evaluate(() => {
      window.sawLoading = false;
      window.failedWhileLoading = false;
      new MutationObserver(() => {
        if (document.body.dataset.opening === 'loading') window.sawLoading = true;
        window.failedWhileLoading ||= document.body.dataset.opening === 'loading' && /could not be fetched/.test(document.querySelector('[role="status"]')?.textContent ?? '');
      }).observe(document.body, { attributes: true, subtree: true, childList: true, characterData: true });
    });
    await dropFile(page, 'pringle.off', pringleOff(300));
    await page.waitForFunction(() => window.sawLoading, null, { timeout: 30_000, polling: 20 });
    await selectExample(page, 'epcot');
    await page.waitForFunction((since) => Number(document.body.dataset.errors ?? 0) > since.errors && document.body.dataset.opening === 'false' && document.body.dataset.solving === 'false', since, { timeout: 30_000, polling: 20 });
    assert.equal(await page.evaluate(() => window.failedWhileLoading), true, 'the example failed while the file loaded');
    assert.equal((await page.locator('#mesh-title').textContent()).trim(), 'pringle.off');
    assert.equal(await page.getByLabel('Panels', { exact: true }).inputValue(), '6');
    assert.equal(await solveAfter(page, () => remesh(page)), 6);
  }, { allowed: [/Failed to load resource/] }));

test('a fresh solve in the same worker (resetSolve) gives the panels of the first solve', () =>
  withPage(suite.url, async (page) => {
    await waitForDone(page);
    await solveAfter(page, () => selectExample(page, 'groin_vault'));
    const first = (await download(page, 'Export OBJ')).text;
    await setPanels(page, 90);
    assert.equal(await solveAfter(page, () => remesh(page)), 90); // a warm start
    await setPanels(page, 120);
    assert.equal(await solveAfter(page, () => remesh(page)), 120); // warm again: other panels
    assert.notEqual((await download(page, 'Export OBJ')).text, first);
    assert.equal(await solveAfter(page, () => remesh(page)), 120); // same parameters: from scratch
    assert.equal((await download(page, 'Export OBJ')).text, first, 'identical to the cold solve after the load');
  }));

test('a cancel during an earlier cancel still cancels', () =>
  withPage(suite.url, async (page) => {
    await waitForDone(page);
    await setPanels(page, 500);
    await remesh(page);
    await waitForProgress(page);
    const before = await outcomes(page);
    // Cancel, Remesh and Cancel again before the worker can confirm the first cancel.
    await page.evaluate(() => {
      document.getElementById('cancel').click();
      document.getElementById('remesh').click();
      document.getElementById('cancel').click();
    });
    await waitForStatus(page, /Cancelled/, 2000);
    assert.equal(await page.getByRole('button', { name: 'Cancel' }).isDisabled(), true);
    await setPanels(page, 90);
    assert.equal(await solveAfter(page, () => remesh(page)), 90);
    assert.equal((await outcomes(page)).solves, before.solves + 1, 'neither cancelled solve finished on the page');
  }));

test('a worker that crashes is replaced: the last result is kept and the page solves again', () =>
  withPage(`${suite.url}?crashAfterSteps=3`, async (page) => {
    assert.equal(await waitForDone(page), 300);
    const first = (await download(page, 'Export OBJ')).text;
    const crashed = page.workers()[0];
    const closed = new Promise((resolve) => crashed.once('close', resolve));
    const replacement = page.waitForEvent('worker', { timeout: 30_000 });
    await setPanels(page, 200);
    const message = await errorAfter(page, () => remesh(page), 60_000);
    assert.match(message, /the solver ran out of memory or crashed and was restarted; the last result is kept/);
    await Promise.all([closed, replacement]);
    assert.equal(page.workers().length, 1, 'one solver worker, the new one');
    assert.equal(await page.getByRole('button', { name: 'Cancel' }).isDisabled(), true);
    assert.match(await page.locator('#stats').textContent(), /Panels\s*300/, 'the last result is still shown');
    assert.equal((await download(page, 'Export OBJ')).text, first, 'and still exported');
    // The new worker has the mesh: a cold solve gives the panels of before the crash.
    await setPanels(page, 300);
    assert.equal(await solveAfter(page, () => remesh(page)), 300);
    assert.equal((await download(page, 'Export OBJ')).text, first, 'the same panels as before the crash');
    await setPanels(page, 200);
    assert.equal(await solveAfter(page, () => remesh(page)), 200);
  }));

function gltf(json) {
  return Buffer.from(JSON.stringify({ asset: { version: '2.0' }, ...json }));
}

// A 2 x 2 quad grid as an embedded glTF (data: buffer), with a texture from elsewhere.
function quadGltf(extra = {}) {
  const positions = new Float32Array([0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0.2, 2, 1, 0, 0, 2, 0, 1, 2, 0, 2, 2, 0]);
  const indices = new Uint32Array([0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4, 3, 4, 7, 3, 7, 6, 4, 5, 8, 4, 8, 7]);
  const bin = Buffer.concat([Buffer.from(positions.buffer), Buffer.from(indices.buffer)]);
  return gltf({
    scene: 0,
    scenes: [{ nodes: [0] }],
    nodes: [{ mesh: 0 }],
    meshes: [{ primitives: [{ attributes: { POSITION: 0 }, indices: 1, material: 0 }] }],
    materials: [{ pbrMetallicRoughness: { baseColorTexture: { index: 0 } } }],
    textures: [{ source: 0 }],
    images: [{ uri: 'https://example.invalid/texture.png' }],
    buffers: [{ uri: `data:application/octet-stream;base64,${bin.toString('base64')}`, byteLength: bin.length }],
    bufferViews: [
      { buffer: 0, byteOffset: 0, byteLength: positions.byteLength },
      { buffer: 0, byteOffset: positions.byteLength, byteLength: indices.byteLength },
    ],
    accessors: [
      { bufferView: 0, componentType: 5126, count: 9, type: 'VEC3', min: [0, 0, 0], max: [2, 2, 0.2] },
      { bufferView: 1, componentType: 5125, count: indices.length, type: 'SCALAR' },
    ],
    ...extra,
  });
}

test('a glTF never makes the page fetch: external URIs are refused, textures skipped', () =>
  withPage(suite.url, async (page) => {
    await waitForDone(page);
    const requests = [];
    page.on('request', (request) => requests.push(request.url()));
    const outside = (url) => !url.startsWith(suite.url) && !url.startsWith('data:') && !url.startsWith('blob:');
    const open = (name, buffer) => page.getByLabel('Open mesh').setInputFiles({ name, mimeType: 'model/gltf+json', buffer });
    for (const uri of ['https://example.invalid/mesh.bin', 'mesh.bin']) {
      const message = await errorAfter(page, () => open('canopy.gltf', gltf({ buffers: [{ uri, byteLength: 96 }] })));
      assert.match(message, /^Error: canopy\.gltf refers to a separate file .*does not fetch/);
    }
    await setPanels(page, 4);
    assert.equal(await solveAfter(page, () => open('grid.gltf', quadGltf())), 4, 'embedded data opens; its texture is not fetched');
    // Its 8 triangles are too few for 4 panels: refined when opened, and the page says so.
    assert.match(await page.locator('#mesh-prepared').textContent(), /refined 8 triangles to [\d,]+ .*4 panels/);
    assert.deepEqual(requests.filter(outside), [], 'no request left the page');
    assert.deepEqual(requests.filter((url) => /mesh\.bin|texture\.png/.test(url)), [], 'not even to its own server');
  }));

test('what the page leaves out of a glTF is said under the mesh', () =>
  withPage(suite.url, async (page) => {
    await waitForDone(page);
    await setPanels(page, 4);
    // The grid's vertices again as points, beside its triangles: they make no panels.
    const meshes = [{ name: 'Grid', primitives: [{ attributes: { POSITION: 0 }, indices: 1 }, { attributes: { POSITION: 0 }, mode: 0 }] }];
    const open = () => page.getByLabel('Open mesh').setInputFiles({ name: 'survey.gltf', mimeType: 'model/gltf+json', buffer: quadGltf({ meshes }) });
    assert.equal(await solveAfter(page, open), 4);
    assert.equal(await page.locator('#mesh-cleanup').textContent(), 'Read from the file: left out 1 point or line primitive (only triangles make panels).');
    assert.ok(await page.locator('#mesh-cleanup').isVisible());
    // Another file without anything left out: the sentence goes.
    await solveAfter(page, () => page.getByLabel('Open mesh').setInputFiles({ name: 'grid.gltf', mimeType: 'model/gltf+json', buffer: quadGltf() }));
    assert.equal(await page.locator('#mesh-cleanup').isVisible(), false);
  }));

test('a mesh too large for a link gets a clear message and no link', () =>
  withPage(suite.url, async (page) => {
    await waitForDone(page);
    // A small grid with 2.5 MB of noise in a comment: it loads, but cannot travel in a link.
    let x = 2463534242;
    const next = () => {
      x ^= x << 13;
      x ^= x >>> 17;
      x ^= x << 5;
      return (x >>> 0) & 63;
    };
    const alphabet = 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/';
    const lines = ['# ' + Array.from({ length: 2_500_000 }, () => alphabet[next()]).join('')];
    for (let j = 0; j < 4; j++) for (let i = 0; i < 4; i++) lines.push(`v ${i} ${j} ${((i * j) % 3) * 0.1}`);
    for (let j = 0; j < 3; j++) for (let i = 0; i < 3; i++) lines.push(`f ${j * 4 + i + 1} ${j * 4 + i + 2} ${j * 4 + i + 6} ${j * 4 + i + 5}`);
    await setPanels(page, 3);
    await solveAfter(page, () => page.getByLabel('Open mesh').setInputFiles({ name: 'noisy.obj', mimeType: 'text/plain', buffer: Buffer.from(lines.join('\n')) }));
    const message = await errorAfter(page, () => page.getByRole('button', { name: 'Copy share link' }).click());
    assert.match(message, /the mesh is too large to travel in a link; share an example or a smaller file/);
    assert.equal(await page.evaluate(() => location.hash), '', 'nothing in the address bar');
    assert.equal(await page.locator('#share-row').isHidden(), true);
  }));

test('a bad link opened later says so once: the next design does not repeat it', () =>
  withPage(suite.url, async (page) => {
    await waitForDone(page);
    const message = await errorAfter(page, () => page.evaluate(() => (location.hash = '#v1=!!broken')));
    assert.match(message, /this share link cannot be opened/);
    const since = await outcomes(page);
    assert.equal(await solveAfter(page, () => selectExample(page, 'saddle')), 120);
    assert.match(await statusText(page), /^Done: 120 panels$/);
    assert.equal((await outcomes(page)).errors, since.errors, 'no error shown again');
  }));

test('after Copy share link, a changed design is what a reload restores', () =>
  withPage(suite.url, async (page) => {
    await waitForDone(page);
    await solveAfter(page, () => selectExample(page, 'barrel_vault'));
    await page.getByRole('button', { name: 'Copy share link' }).click();
    await page.waitForFunction(() => location.hash.startsWith('#v1='));
    await setPanels(page, 70);
    const since = await outcomes(page);
    assert.equal(await solveAfter(page, () => remesh(page)), 70);
    assert.equal(await page.evaluate(() => location.hash), '', 'the stale link left the address bar');
    await waitForSaved(page, since);
    await page.reload();
    assert.equal(await waitForDone(page), 70, 'the last design, not the older link');
    assert.equal(await page.getByLabel('Example', { exact: true }).inputValue(), 'barrel_vault');
  }));

test('the stored session keeps the mesh once; one that cannot be restored says so', () =>
  withPage(suite.url, async (page) => {
    await waitForDone(page);
    const cells = 8;
    const lines = [];
    for (let j = 0; j <= cells; j++) for (let i = 0; i <= cells; i++) lines.push(`v ${i} ${j} ${(Math.sin(i) * Math.cos(j) * 0.3).toFixed(4)}`);
    for (let j = 0; j < cells; j++) for (let i = 0; i < cells; i++) lines.push(`f ${j * 9 + i + 1} ${j * 9 + i + 2} ${j * 9 + i + 11} ${j * 9 + i + 10}`);
    await setPanels(page, 10);
    await solveAfter(page, () => page.getByLabel('Open mesh').setInputFiles({ name: 'sheet.obj', mimeType: 'text/plain', buffer: Buffer.from(lines.join('\n')) }));
    await setPanels(page, 8);
    const since = await outcomes(page);
    assert.equal(await solveAfter(page, () => remesh(page)), 8);
    await waitForSaved(page, since);
    const stored = await page.evaluate(
      () =>
        new Promise((resolve, reject) => {
          const open = indexedDB.open('flatfacet');
          open.onerror = () => reject(open.error);
          open.onsuccess = () => {
            const tx = open.result.transaction(['sessions', 'meshes']);
            const meshes = tx.objectStore('meshes').getAllKeys();
            const session = tx.objectStore('sessions').get('last');
            tx.oncomplete = () => resolve({ meshKeys: meshes.result, session: session.result });
          };
        }),
    );
    assert.equal(stored.meshKeys.length, 1, 'one mesh kept');
    assert.match(stored.meshKeys[0], /^sheet\.obj:\d+:[0-9a-f]{8}$/);
    assert.equal(stored.session.mesh.key, stored.meshKeys[0], 'the session refers to it');
    assert.equal(stored.session.params.panels, 8);
    // A stored session this page cannot use: a note says so, and the default example opens.
    await page.evaluate(
      () =>
        new Promise((resolve) => {
          const open = indexedDB.open('flatfacet');
          open.onsuccess = () => {
            const tx = open.result.transaction(['sessions'], 'readwrite');
            tx.objectStore('sessions').put({ v: 2, mesh: { example: 'eiffel_tower' }, params: {}, history: [] }, 'last');
            tx.oncomplete = resolve;
          };
        }),
    );
    await page.reload();
    await waitForDone(page);
    assert.equal(await page.locator('#session-note').isVisible(), true);
    assert.match(await page.locator('#session-note').textContent(), /cannot be restored: .*unknown example/);
  }));

test('without the shared example meshes the page starts on a generated example', () =>
  withPage(suite.url, async (page, context) => {
    await context.route('**/examples/index.json', (route) => route.fulfill({ status: 404, body: 'not found' }));
    await page.reload();
    assert.equal(await waitForDone(page), 120);
    assert.equal(await page.getByLabel('Example', { exact: true }).inputValue(), 'freeform_roof');
    assert.equal(await page.locator('#example option[value="hyperboloid_s4"]').evaluate((option) => option.hidden), true);
    assert.equal(await page.locator('#example option[value="saddle"]').evaluate((option) => option.hidden), false);
  }, { allowed: [/404/] }));

test('a closed surface asked for three panels says why not and keeps the design', () =>
  withPage(exampleLink(suite.url, 'epcot', { panels: 30, seed: 1, weights: { euclidean: 1, l2: 1, l21: 1, boundary: 1 }, lloydIterations: 20, panelRounds: 100, seeding: 'farthest', teleport: true, singlePointNodes: false, optimizePlanes: true }), async (page) => {
    assert.equal(await waitForDone(page), 30);
    await setPanels(page, 3);
    const message = await errorAfter(page, () => remesh(page));
    assert.match(message, /^Error: a closed surface needs at least 4 planar panels \(each meets at least three others\); asked for 3$/);
    assert.match(await page.locator('#stats').textContent(), /Panels\s*30/, 'the last design stays');
    await screenshot(page, 'epcot-3-refused');
    await setPanels(page, 4);
    assert.equal(await solveAfter(page, () => remesh(page)), 4, 'four panels (a tetrahedron) solve');
  }));

// A model far from the origin (epcot moved 1e9 along x): its panels are valid, but the doubles
// cannot hold them flat to 1e-9; the Planarity row is marked and its hint says why.
test('a model far from the origin: the status line and the Planarity row say why its panels are not flat to 1e-9', () =>
  withPage(exampleLink(suite.url, 'epcot', { panels: 30, seed: 1, weights: { euclidean: 1, l2: 1, l21: 1, boundary: 1 }, lloydIterations: 20, panelRounds: 100, seeding: 'farthest', teleport: true, singlePointNodes: false, optimizePlanes: true }), async (page) => {
    assert.equal(await waitForDone(page), 30);
    const row = page.locator('#stats dd').nth(1);
    assert.equal(await row.evaluate((dd) => dd.classList.contains('warn')), false, 'near the origin: flat');
    const bytes = movedOff(readFileSync(join(sharedMeshes, 'epcot.off'), 'utf8'), 1e9);
    assert.equal(await solveAfter(page, () => page.getByLabel('Open mesh').setInputFiles({ name: 'epcot-far.off', mimeType: 'text/plain', buffer: Buffer.from(bytes) })), 30);
    assert.match(await statusText(page), /^panels flat to .* of their size, not 10⁻⁹: the model is far from the origin \(move it nearer\)\. Done: 30 panels$/);
    assert.equal(await page.locator('#stats dt').nth(1).textContent(), 'Planarity');
    assert.equal(await row.evaluate((dd) => dd.classList.contains('warn')), true);
    assert.match(await row.getAttribute('title'), /far from the origin .* moved near the origin, the model gives flat panels/);
    await screenshot(page, 'planarity-far-from-origin');
  }));

// Cancel during a solve on a mesh prepared for it (more panels than the mesh on show could
// serve) left the page with no panels: the clusters half-way, Export OBJ off, "Cancelled."
// (a review of the page). The design before comes back, prepared back and solved, as Undo
// brings it: the very panels of before.
test('Cancel after a preparation for more panels brings the last finished design back', () =>
  withPage(suite.url, async (page) => {
    assert.equal(await waitForDone(page), 300);
    const before = (await download(page, 'Export OBJ')).text;
    await setPanels(page, 3000);
    await remesh(page);
    await waitForProgress(page);
    const since = await outcomes(page);
    await recordStatus(page);
    await page.getByRole('button', { name: 'Cancel' }).click();
    await waitForStatusSeen(page, /^Cancelled\. The last finished design is coming back/, 30_000);
    assert.equal(await waitForDone(page, since), 300);
    assert.equal((await download(page, 'Export OBJ')).text, before);
    assert.equal(await page.getByLabel('Panels', { exact: true }).inputValue(), '300');
  }));

// An Undo to a step that was never solved (typed, no Remesh) moves only the form: it says so,
// or the move looks like it did nothing.
test('an Undo to a step never solved says that only the form moved', () =>
  withPage(suite.url, async (page) => {
    assert.equal(await waitForDone(page), 300);
    await setPanels(page, 200);
    await page.getByLabel('Panels', { exact: true }).dispatchEvent('change');
    await setPanels(page, 250);
    assert.equal(await solveAfter(page, () => remesh(page)), 250);
    await page.getByRole('button', { name: 'Undo' }).click();
    assert.equal(await page.getByLabel('Panels', { exact: true }).inputValue(), '200');
    assert.match(await statusText(page), /^Undo: the form is back to a step that was never solved; Remesh to solve it\. The panels on show stay as they are\.$/);
  }));

// A photo said "expected .obj, .off, .stl or .ply" (the core's formats), though the page reads
// glTF and Rhino too (a review of the page): the page refuses it by its own list.
test('a file of another kind is refused with the formats the page reads', () =>
  withPage(suite.url, async (page) => {
    assert.equal(await waitForDone(page), 300);
    const png = Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0, 0, 0, 13]);
    const message = await errorAfter(page, () => page.getByLabel('Open mesh').setInputFiles({ name: 'photo.png', mimeType: 'image/png', buffer: png }));
    assert.equal(message, 'Error: photo.png: not a mesh file this page reads (OBJ, OFF, STL, PLY, glTF/GLB or Rhino .3dm)');
    assert.match(await page.locator('#mesh-title').textContent(), /Hyperboloid/, 'the design on show stays');
  }));
