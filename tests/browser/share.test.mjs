// Share links and the stored session, in headless Chromium against the built site: a link
// opened in a fresh browser context solves to the byte-identical OBJ; hostile links give a
// clear message and leave a working page; a reload restores the last design.
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { test } from 'node:test';
import { zlibSync } from 'fflate';
import {
  browserSuite,
  download,
  openPage,
  outcomes,
  remesh,
  selectExample,
  setPanels,
  sharedMeshes,
  solveAfter,
  statusText,
  waitForDone,
  waitForSaved,
} from './harness.mjs';

const suite = browserSuite();
const { withPage } = suite;

async function copyShareLink(page) {
  await page.getByRole('button', { name: 'Copy share link' }).click();
  await page.waitForFunction(() => location.hash.startsWith('#v1='));
  const link = await page.getByLabel('Share link').inputValue();
  assert.match(link, /#v1=[A-Za-z0-9_-]+$/);
  assert.equal(link, await page.evaluate(() => location.href), 'the field and the address bar agree');
  return link;
}

// Opens the link in a fresh context (no shared storage) and returns its exported OBJ.
// `restored`: further inputs the link must have set, by label.
async function objFromLink(link, expectedPanels, restored = {}) {
  let text = '';
  await withPage(link, async (page) => {
    assert.equal(await waitForDone(page), expectedPanels);
    assert.equal(await page.getByLabel('Panels', { exact: true }).inputValue(), String(expectedPanels), 'the parameters are restored');
    for (const [label, value] of Object.entries(restored)) assert.equal(await page.getByLabel(label, { exact: true }).inputValue(), value, `${label} is restored`);
    text = (await download(page, 'Export OBJ')).text;
  });
  return text;
}

test('a share link of a warm-started example design gives the identical OBJ in a fresh context', async () => {
  let link = '';
  let original = '';
  await withPage(suite.url, async (page) => {
    await waitForDone(page);
    await solveAfter(page, () => selectExample(page, 'groin_vault'));
    await page.getByText('Metric and solver').click();
    await page.getByLabel('Seed', { exact: true }).fill('7');
    await page.getByLabel('L2,1', { exact: true }).fill('2');
    await page.getByLabel('Coplanar angle', { exact: true }).fill('2.5');
    await page.getByLabel('Retries', { exact: true }).fill('3');
    await setPanels(page, 90);
    assert.equal(await solveAfter(page, () => remesh(page)), 90);
    await setPanels(page, 70); // a warm start from the 90-panel design
    assert.equal(await solveAfter(page, () => remesh(page)), 70);
    original = (await download(page, 'Export OBJ')).text;
    link = await copyShareLink(page);
  });
  const restored = await objFromLink(link, 70, { Seed: '7', 'L2,1': '2', 'Coplanar angle': '2.5', Retries: '3' });
  assert.ok(original.length > 1000);
  assert.equal(restored, original, 'byte-identical OBJ');
});

test('a share link carries a small uploaded mesh', async () => {
  let link = '';
  let original = '';
  await withPage(suite.url, async (page) => {
    await waitForDone(page);
    await setPanels(page, 40);
    assert.equal(await solveAfter(page, () => page.getByLabel('Open mesh').setInputFiles(join(sharedMeshes, 'epcot.off'))), 40);
    original = (await download(page, 'Export OBJ')).text;
    link = await copyShareLink(page);
  });
  const restored = await objFromLink(link, 40);
  assert.equal(restored, original, 'byte-identical OBJ');
});

function linkOf(json, { compress = (b) => zlibSync(b) } = {}) {
  const text = new TextEncoder().encode(JSON.stringify(json));
  const payload = new Uint8Array(4 + text.length);
  new DataView(payload.buffer).setUint32(0, text.length, true);
  payload.set(text, 4);
  return `${suite.url}#v1=${Buffer.from(compress(payload)).toString('base64url')}`;
}

test('hostile and broken links give a clear message, and the page keeps working', async () => {
  const params = { panels: 50, seed: 1, weights: { euclidean: 1, l2: 1, l21: 1, boundary: 1 }, lloydIterations: 20, panelRounds: 30, seeding: 'farthest', teleport: true, singlePointNodes: false, optimizePlanes: true };
  const bomb = `${suite.url}#v1=${Buffer.from(zlibSync(new Uint8Array(64 * 1024 * 1024), { level: 9 })).toString('base64url')}`;
  const cases = [
    [`${suite.url}#v1=%3Cscript%3Ealert(1)%3C/script%3E`, /cannot be opened: .*characters/],
    [`${suite.url}#v1=${Buffer.from('random garbage that is no zlib').toString('base64url')}`, /cannot be opened: .*damaged/],
    [bomb, /cannot be opened: .*unpacks to more than/],
    [`${suite.url}#v7=AAAA`, /cannot be opened: .*version 7/],
    [linkOf({ v: 1, mesh: { example: 'saddle' }, params: { ...params, panels: -4 } }), /cannot be opened: .*Panels must be between/],
    [linkOf({ v: 1, mesh: { example: 'saddle' }, params: { ...params, seed: 'x' } }), /cannot be opened: .*Seed must be a whole number/],
    [linkOf({ v: 1, mesh: { example: '<img src=x onerror=alert(1)>' }, params }), /cannot be opened: .*unknown example/],
  ];
  for (const [link, pattern] of cases) {
    await withPage(link, async (page) => {
      await page.waitForFunction(() => /cannot be opened/.test(document.querySelector('[role="status"]')?.textContent ?? ''), null, { timeout: 30_000 });
      // The message stays while the default surface loads behind it.
      await page.waitForFunction(() => document.querySelector('#mesh-title')?.textContent !== '', null, { timeout: 30_000 });
      const message = await statusText(page);
      assert.match(message, /^Error: this share link cannot be opened: /);
      assert.match(message, pattern);
      assert.equal(await page.locator('img').count(), 0, 'nothing from the link became markup');
      // The page works: the default example solves.
      await setPanels(page, 60);
      assert.equal(await solveAfter(page, () => remesh(page)), 60);
    });
  }
});

test('a reload restores the last design from this browser', async () => {
  const { context, page, errors } = await openPage(suite.browser, suite.url);
  try {
    await waitForDone(page);
    await solveAfter(page, () => selectExample(page, 'helicoid'));
    await setPanels(page, 64);
    let since = await outcomes(page);
    assert.equal(await solveAfter(page, () => remesh(page)), 64);
    const before = (await download(page, 'Export OBJ')).text;
    await waitForSaved(page, since);
    await page.reload();
    assert.equal(await waitForDone(page), 64);
    assert.equal(await page.getByLabel('Example', { exact: true }).inputValue(), 'helicoid');
    assert.equal(await page.getByLabel('Panels', { exact: true }).inputValue(), '64');
    assert.equal((await download(page, 'Export OBJ')).text, before, 'the same panels after the reload');
    // An uploaded mesh survives a reload too.
    await setPanels(page, 30);
    since = await outcomes(page);
    await solveAfter(page, () => page.getByLabel('Open mesh').setInputFiles(join(sharedMeshes, 'bumpy.off')));
    await waitForSaved(page, since, 2); // the load's and the solve's
    await page.reload();
    assert.equal(await waitForDone(page), 30);
    assert.match(await page.locator('#mesh-title').textContent(), /bumpy\.off/);
    assert.deepEqual(errors, []);
  } finally {
    await context.close();
  }
});

