// Shared by the browser tests and bench/browser_bench.mjs: a static server for the built
// site (web/dist, built beforehand by `npm run build`), Debian's Chromium through
// playwright-core (never a downloaded browser), and page helpers that use the accessible
// names people use (DESIGN.md 4).
import { createReadStream, existsSync, readFileSync, statSync } from 'node:fs';
import { createServer } from 'node:http';
import { extname, join, normalize, resolve, sep } from 'node:path';
import { after, before } from 'node:test';
import { fileURLToPath } from 'node:url';
import { zlibSync } from 'fflate';
import { chromium } from 'playwright-core';

export const repo = resolve(fileURLToPath(new URL('.', import.meta.url)), '..', '..');
export const dist = join(repo, 'web', 'dist');
export const sharedMeshes = process.env.FF_SHARED_MESHES ?? resolve(repo, '..', 'shared', 'meshes');

const MIME = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.wasm': 'application/wasm',
  '.json': 'application/json',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
};

// Serves web/dist on 127.0.0.1 at a free port, like any static file server would.
export async function startServer() {
  if (!existsSync(join(dist, 'index.html'))) throw new Error('web/dist is not built: run `npm run build` first');
  const server = createServer((request, response) => {
    const path = decodeURIComponent(new URL(request.url ?? '/', 'http://localhost').pathname);
    let file = normalize(join(dist, path));
    if (file !== dist && !file.startsWith(dist + sep)) {
      response.writeHead(403).end();
      return;
    }
    if (existsSync(file) && statSync(file).isDirectory()) file = join(file, 'index.html');
    if (!existsSync(file)) {
      response.writeHead(404).end('not found');
      return;
    }
    response.writeHead(200, { 'content-type': MIME[extname(file)] ?? 'application/octet-stream', 'cache-control': 'no-store' });
    createReadStream(file).pipe(response);
  });
  await new Promise((done) => server.listen(0, '127.0.0.1', done));
  const { port } = server.address();
  return { url: `http://127.0.0.1:${port}/`, close: () => new Promise((done) => server.close(done)) };
}

export const CHROMIUM = process.env.CHROMIUM ?? '/usr/bin/chromium';
const CHROMIUM_ARGS = [
  '--no-sandbox',
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
];

export function launchBrowser() {
  return chromium.launch({ executablePath: CHROMIUM, headless: true, args: CHROMIUM_ARGS });
}

// A fresh context (own IndexedDB, clipboard) and page. Page errors and console errors are
// collected; tests assert there are none.
export async function openPage(browser, url, { width = 1440, height = 900 } = {}) {
  const context = await browser.newContext({ viewport: { width, height }, acceptDownloads: true });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (error) => errors.push(`page error: ${error.message}`));
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(`console error: ${message.text()}`);
  });
  page.on('worker', (worker) => worker.on('console', (message) => {
    if (message.type() === 'error') errors.push(`worker console error: ${message.text()}`);
  }));
  await page.goto(url);
  return { context, page, errors };
}

// One server and one browser per test file (registered as node:test before/after hooks).
// withPage gives every test a fresh context that must end with no page or console errors,
// except those matching `allowed`; run receives (page, context).
export function browserSuite() {
  let server;
  let browser;
  before(async () => {
    server = await startServer();
    browser = await launchBrowser();
  });
  after(async () => {
    await browser?.close();
    await server?.close();
  });
  const suite = {
    get url() {
      return server.url;
    },
    get browser() {
      return browser;
    },
    async withPage(url, run, { allowed = [] } = {}) {
      const { context, page, errors } = await openPage(browser, url);
      try {
        await run(page, context);
        const unexpected = errors.filter((error) => !allowed.some((pattern) => pattern.test(error)));
        if (unexpected.length > 0) throw new Error(`page or console errors:\n${unexpected.join('\n')}`);
      } finally {
        await context.close();
      }
    },
  };
  return suite;
}

// A share link (#v1=) that opens an example with these parameters: a fast start on a small
// generated surface instead of the default example (a 50k-triangle tower, slow to solve here).
export function exampleLink(url, example, params) {
  const text = new TextEncoder().encode(JSON.stringify({ v: 1, mesh: { example }, params, history: [] }));
  const payload = new Uint8Array(4 + text.length);
  new DataView(payload.buffer).setUint32(0, text.length, true);
  payload.set(text, 4);
  return `${url}#v1=${Buffer.from(zlibSync(payload)).toString('base64url')}`;
}

export const status = (page) => page.getByRole('status');

export async function statusText(page) {
  return (await status(page).textContent())?.trim() ?? '';
}

// The page counts finished solves and shown errors on <body> (data-solves, data-errors).
export async function outcomes(page) {
  return page.evaluate(() => ({ solves: Number(document.body.dataset.solves ?? 0), errors: Number(document.body.dataset.errors ?? 0), saves: Number(document.body.dataset.saves ?? 0) }));
}

// Waits until the session is written to this browser's storage after `since` (outcomes()
// taken before the action): a reload before that would restore an older design.
// `count`: the saves expected since (one per load, one per finished solve).
export async function waitForSaved(page, since, count = 1, timeoutMs = 30_000) {
  await page.waitForFunction(([since, count]) => Number(document.body.dataset.saves ?? 0) >= since.saves + count, [since, count], { timeout: timeoutMs, polling: 20 });
}

// Waits for the next finished solve after `since` (from outcomes(); default: the first) and
// returns N of the status's "Done: N panels"; throws with the status if an error comes first.
export async function waitForDone(page, since = { solves: 0, errors: Number.MAX_SAFE_INTEGER }, timeoutMs = 120_000) {
  const handle = await page.waitForFunction(
    (since) => {
      const text = document.querySelector('[role="status"]')?.textContent?.trim() ?? '';
      if (Number(document.body.dataset.errors ?? 0) > since.errors) return `Error? ${text}`;
      return Number(document.body.dataset.solves ?? 0) > since.solves && /Done: \d+ panels$/.test(text) ? text : null;
    },
    since,
    { timeout: timeoutMs, polling: 50 },
  );
  const text = await handle.jsonValue();
  if (text.startsWith('Error? ')) throw new Error(`solve failed: ${text.slice(7)}`);
  return Number(/Done: (\d+) panels$/.exec(text)[1]);
}

// Runs `action` and waits for the solve it starts.
export async function solveAfter(page, action, timeoutMs) {
  const since = await outcomes(page);
  await action();
  return waitForDone(page, since, timeoutMs);
}

// Runs `action` and waits for the error message it causes; returns the status text.
export async function errorAfter(page, action, timeoutMs = 30_000) {
  const since = await outcomes(page);
  await action();
  await page.waitForFunction((since) => Number(document.body.dataset.errors ?? 0) > since.errors, since, { timeout: timeoutMs, polling: 50 });
  return statusText(page);
}

export async function waitForStatus(page, pattern, timeoutMs = 60_000) {
  const source = pattern.source;
  const flags = pattern.flags;
  const handle = await page.waitForFunction(
    ([source, flags]) => {
      const text = document.querySelector('[role="status"]')?.textContent?.trim() ?? '';
      return new RegExp(source, flags).test(text) ? text : null;
    },
    [source, flags],
    { timeout: timeoutMs, polling: 50 },
  );
  return handle.jsonValue();
}

// Records every text the status line shows from now on, each assignment apart (a
// MutationObserver's added text nodes: records queued in one task are all kept), so a message
// overtaken within a poll is still seen. waitForStatusSeen then waits for one matching.
export async function recordStatus(page) {
  await page.evaluate(() => {
    const status = document.querySelector('[role="status"]');
    window.__statusSeen = [];
    new MutationObserver((records) => {
      for (const record of records) for (const node of record.addedNodes) window.__statusSeen.push((node.textContent ?? '').trim());
    }).observe(status, { childList: true });
  });
}

// Waits until the status line has shown a text matching `pattern` since recordStatus; on a
// timeout the error lists the last texts it showed.
export async function waitForStatusSeen(page, pattern, timeoutMs = 60_000) {
  const source = pattern.source;
  const flags = pattern.flags;
  try {
    const handle = await page.waitForFunction(([source, flags]) => window.__statusSeen.find((text) => new RegExp(source, flags).test(text)) ?? null, [source, flags], {
      timeout: timeoutMs,
      polling: 50,
    });
    return handle.jsonValue();
  } catch (error) {
    const seen = await page.evaluate(() => window.__statusSeen.slice(-12));
    throw new Error(`${error.message}: the status line showed ${JSON.stringify(seen)}`);
  }
}

export async function waitForSolving(page, timeoutMs = 30_000) {
  await page.waitForFunction(() => document.body.dataset.solving === 'true', null, { timeout: timeoutMs, polling: 20 });
}

// Waits until the solve under way has shown a progress line (the worker is stepping).
export async function waitForProgress(page, timeoutMs = 60_000) {
  await page.waitForFunction(
    () => document.body.dataset.solving === 'true' && (document.querySelector('[role="status"]')?.textContent ?? '').startsWith('Solving:'),
    null,
    { timeout: timeoutMs, polling: 20 },
  );
}

export async function setPanels(page, panels) {
  await page.getByLabel('Panels', { exact: true }).fill(String(panels));
}

export async function remesh(page) {
  await page.getByRole('button', { name: 'Remesh' }).click();
}

export async function selectExample(page, id) {
  await page.getByLabel('Example', { exact: true }).selectOption(id);
}

// Clicks an export button and returns { name, text } of the downloaded file.
export async function download(page, buttonName) {
  const [file] = await Promise.all([page.waitForEvent('download'), page.getByRole('button', { name: buttonName }).click()]);
  const path = await file.path();
  return { name: file.suggestedFilename(), text: readFileSync(path, 'utf8') };
}

// Panels OBJ -> vertices and faces (1-based indices as written).
export function parseObj(text) {
  const vertices = [];
  const faces = [];
  for (const line of text.split('\n')) {
    const parts = line.trim().split(/\s+/);
    if (parts[0] === 'v') vertices.push(parts.slice(1, 4).map(Number));
    else if (parts[0] === 'f') faces.push(parts.slice(1).map((token) => Number(token.split('/')[0]) - 1));
  }
  return { vertices, faces };
}

// Max over faces of (max distance of its vertices to the best-fit plane) / face diameter:
// the report's planarity, computed independently (smallest eigenvector of the covariance).
export function maxPlanarity({ vertices, faces }) {
  let worst = 0;
  for (const face of faces) {
    const points = face.map((index) => {
      const v = vertices[index];
      if (!v) throw new Error(`face refers to missing vertex ${index + 1}`);
      return v;
    });
    const centre = [0, 1, 2].map((axis) => points.reduce((sum, p) => sum + p[axis], 0) / points.length);
    const c = [[0, 0, 0], [0, 0, 0], [0, 0, 0]];
    for (const p of points) {
      const d = [p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]];
      for (let i = 0; i < 3; i++) for (let j = 0; j < 3; j++) c[i][j] += d[i] * d[j];
    }
    const normal = smallestEigenvector(c);
    let diameter = 0;
    for (const p of points) for (const q of points) diameter = Math.max(diameter, Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]));
    let distance = 0;
    for (const p of points) distance = Math.max(distance, Math.abs((p[0] - centre[0]) * normal[0] + (p[1] - centre[1]) * normal[1] + (p[2] - centre[2]) * normal[2]));
    if (diameter > 0) worst = Math.max(worst, distance / diameter);
  }
  return worst;
}

// Jacobi rotations on a symmetric 3x3 matrix; returns the unit eigenvector of the smallest eigenvalue.
function smallestEigenvector(input) {
  const a = input.map((row) => row.slice());
  const v = [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
  for (let sweep = 0; sweep < 50; sweep++) {
    const off = Math.abs(a[0][1]) + Math.abs(a[0][2]) + Math.abs(a[1][2]);
    if (off < 1e-300) break;
    for (const [p, q] of [[0, 1], [0, 2], [1, 2]]) {
      if (Math.abs(a[p][q]) < 1e-300) continue;
      const theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
      const t = Math.sign(theta || 1) / (Math.abs(theta) + Math.sqrt(theta * theta + 1));
      const cos = 1 / Math.sqrt(t * t + 1);
      const sin = t * cos;
      for (let k = 0; k < 3; k++) {
        const akp = a[k][p];
        const akq = a[k][q];
        a[k][p] = cos * akp - sin * akq;
        a[k][q] = sin * akp + cos * akq;
      }
      for (let k = 0; k < 3; k++) {
        const apk = a[p][k];
        const aqk = a[q][k];
        a[p][k] = cos * apk - sin * aqk;
        a[q][k] = sin * apk + cos * aqk;
      }
      for (let k = 0; k < 3; k++) {
        const vkp = v[k][p];
        const vkq = v[k][q];
        v[k][p] = cos * vkp - sin * vkq;
        v[k][q] = sin * vkp + cos * vkq;
      }
    }
  }
  let best = 0;
  for (let i = 1; i < 3; i++) if (a[i][i] < a[best][best]) best = i;
  const n = [v[0][best], v[1][best], v[2][best]];
  const length = Math.hypot(...n);
  return n.map((x) => x / length);
}

// Distinct colours (4 bits per channel) in a screenshot of `selector`: the picture is decoded
// by the page itself, since a WebGL canvas cannot be read back after it was presented.
export async function distinctColours(page, selector) {
  const png = await page.locator(selector).screenshot();
  return page.evaluate(async (base64) => {
    const image = new Image();
    image.src = `data:image/png;base64,${base64}`;
    await image.decode();
    const canvas = document.createElement('canvas');
    canvas.width = 96;
    canvas.height = 96;
    const context = canvas.getContext('2d');
    context.drawImage(image, 0, 0, 96, 96);
    const data = context.getImageData(0, 0, 96, 96).data;
    const colours = new Set();
    for (let i = 0; i < data.length; i += 4) colours.add(`${data[i] >> 4},${data[i + 1] >> 4},${data[i + 2] >> 4}`);
    return colours.size;
  }, png.toString('base64'));
}

// The view's pixels against an RGB colour, decoded by the page itself, with the legend lines
// over the view (whose swatches have marker colours) hidden for the screenshot: those within
// 24 of it per channel (their count and centre as fractions of the view's size, NaN without
// pixels), and those in the two outermost columns at each side not within 24 of it in sum
// (with the view's size).
async function matchView(page, [r, g, b]) {
  const legends = (visibility) =>
    page.evaluate((v) => document.querySelector('.view-legends').style.setProperty('visibility', v), visibility);
  await legends('hidden');
  const png = await page.locator('#viewport canvas').screenshot();
  await legends('visible');
  return page.evaluate(
    async ({ data, rgb }) => {
      const image = new Image();
      image.src = `data:image/png;base64,${data}`;
      await image.decode();
      const canvas = new OffscreenCanvas(image.width, image.height);
      const context = canvas.getContext('2d');
      context.drawImage(image, 0, 0);
      const pixels = context.getImageData(0, 0, image.width, image.height).data;
      const off = (i) => [Math.abs(pixels[i] - rgb[0]), Math.abs(pixels[i + 1] - rgb[1]), Math.abs(pixels[i + 2] - rgb[2])];
      let count = 0;
      let x = 0;
      let y = 0;
      for (let i = 0; i < pixels.length; i += 4) {
        const [dr, dg, db] = off(i);
        if (dr < 24 && dg < 24 && db < 24) {
          count++;
          x += (i / 4) % image.width;
          y += Math.floor(i / 4 / image.width);
        }
      }
      let sides = 0;
      for (let row = 0; row < image.height; row++)
        for (const column of [0, 1, image.width - 2, image.width - 1]) {
          const [dr, dg, db] = off(4 * (row * image.width + column));
          if (dr + dg + db > 24) sides++;
        }
      return { count, fx: (x / count + 0.5) / image.width, fy: (y / count + 0.5) / image.height, sides, width: image.width, height: image.height };
    },
    { data: png.toString('base64'), rgb: [r, g, b] },
  );
}

// Pixels of the view within 24 of an RGB colour per channel (markers drawn in a colour of
// their own): their count and their centre as fractions of the view's size (NaN without
// pixels), for clickView-style clicks near a marker.
export async function viewColour(page, rgb) {
  const { count, fx, fy } = await matchView(page, rgb);
  return { count, fx, fy };
}

// Pixels in the view's outermost columns that are not the background colour `rgb`: 0 when the
// model is framed whole across the view. With the view's size.
export async function viewSidePixels(page, rgb) {
  const { sides, width, height } = await matchView(page, rgb);
  return { count: sides, width, height };
}

export async function viewPixels(page, rgb) {
  return (await viewColour(page, rgb)).count;
}

// viewPixels with "Show problems" off for the screenshot (markers that go with the problems
// must be gone); the toggle is back on afterwards.
export async function viewPixelsWithoutProblems(page, rgb) {
  await page.getByLabel('Show problems').uncheck();
  await page.waitForTimeout(300);
  const count = await viewPixels(page, rgb);
  await page.getByLabel('Show problems').check();
  return count;
}

export async function screenshot(page, name) {
  const dir = join(repo, 'build', 'screenshots');
  await import('node:fs').then((fs) => fs.mkdirSync(dir, { recursive: true }));
  const path = join(dir, `${name}.png`);
  await page.screenshot({ path });
  return path;
}
