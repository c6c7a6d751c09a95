// Unit tests of web/src/solverClient.ts (compiled to build/web-tests by `npm run test:web`)
// with a fake Worker: the mesh a replacement worker gets back is the last one loaded, with the
// preparation it was loaded or prepared with, and none after the mesh as loaded came back
// (prepare(null): undo to a design saved before preparations were recorded).
import assert from 'node:assert/strict';
import { test } from 'node:test';

// Every worker made, with what it was sent; `answer` plays the worker's reply.
const workers = [];
class FakeWorker {
  constructor() {
    this.sent = [];
    this.onmessage = null;
    this.onerror = null;
    workers.push(this);
  }
  postMessage(message) { this.sent.push(message); }
  terminate() { this.terminated = true; }
  addEventListener() {}
  removeEventListener() {}
  answer(data) { this.onmessage({ data }); }
}
globalThis.Worker = FakeWorker;
const { SolverClient, solverTestHooks } = await import('../../build/web-tests/solverClient.js');

const info = { triangles: 288 };
const loadedAnswer = (job) => ({ type: 'loaded', job, info, positions: new Float32Array(0), indices: new Uint32Array(0) });
const mesh = { kind: 'file', name: 'grid.obj', bytes: new Uint8Array([1, 2, 3]) };
const carry = { paint: null, faces: new Int32Array(0) };

test('a crash reloads the last mesh with its preparation, and without one after the mesh as loaded came back', () => {
  workers.length = 0;
  const crashes = [];
  const client = new SolverClient({ onMessage() {}, onCrash: (crash) => crashes.push(crash) });
  const first = workers[0];
  const loadJob = client.load(mesh);
  first.answer(loadedAnswer(loadJob));

  const prepared = { panels: 30, subdivide: 0, refineBelow: 30, refineRounds: 5 };
  const prepareJob = client.prepare(prepared, carry);
  assert.deepEqual(first.sent.at(-1), { type: 'prepare', job: prepareJob, prepare: prepared, carry });
  first.answer(loadedAnswer(prepareJob));
  first.answer({ type: 'crashed', message: 'out of memory' });
  const second = workers[1];
  assert.equal(crashes.at(-1).meshKept, true);
  assert.deepEqual(second.sent.at(-1).mesh, { ...mesh, prepare: prepared }, 'reloaded with its preparation');
  second.answer({ type: 'loaded', job: second.sent.at(-1).job, info, positions: new Float32Array(0), indices: new Uint32Array(0) });

  const asLoadedJob = client.prepare(null, carry);
  assert.deepEqual(second.sent.at(-1), { type: 'prepare', job: asLoadedJob, prepare: null, carry });
  second.answer(loadedAnswer(asLoadedJob));
  second.answer({ type: 'crashed', message: 'out of memory' });
  const reload = workers[2].sent.at(-1);
  assert.equal(reload.type, 'load');
  assert.ok(!('prepare' in reload.mesh), 'the mesh as loaded: no preparation to make again');
  assert.deepEqual(reload.mesh, mesh);
});

test('the test hooks in the address work only on a page served from this machine', () => {
  const hooks = (href) => {
    globalThis.location = new URL(href);
    try {
      return solverTestHooks();
    } finally {
      delete globalThis.location;
    }
  };
  const query = '?crashAfterSteps=3&cancelGrace=0&refuseOnPrepare=2&failRestart=1&stepDelay=40';
  const expected = { cancelGraceMs: 0, crashAfterSteps: 3, prepareFault: { at: 2, kind: 'refuse' }, failRestart: true, stepDelayMs: 40 };
  assert.deepEqual(hooks(`http://127.0.0.1:4173/${query}`), expected);
  assert.deepEqual(hooks(`http://localhost:5173/${query}#v1=abc`), expected);
  assert.deepEqual(hooks(`http://[::1]:8080/${query}`), expected);
  assert.deepEqual(hooks(`https://flatfacet.example/${query}`), {});
  assert.deepEqual(hooks(`http://192.168.1.20:4173/${query}`), {});
});

test('a worker that could not start is sent nothing more', () => {
  workers.length = 0;
  const messages = [];
  const client = new SolverClient({ onMessage: (message) => messages.push(message), onCrash() {} });
  const worker = workers[0];
  worker.answer({ type: 'fatal', message: 'the solver could not start: no memory' });
  assert.equal(messages.at(-1).type, 'fatal');
  client.load(mesh);
  client.solve(true, []);
  client.expressionDensity('1 + x');
  assert.deepEqual(worker.sent, []);
});
