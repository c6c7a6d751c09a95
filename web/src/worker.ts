// The solver worker: owns the wasm Session and drives it step by step. Between steps it yields
// to the event loop, so a cancel or a parameter change arrives within one step; the page
// stays free because none of this runs on its thread.
import createFlatfacet, { type FlatfacetModule, type MeshInfo, type Progress, type Session, type Status } from '@flatfacet/wasm';
import wasmUrl from '@flatfacet/wasm-binary?url';
import { transferablesOf, type MeshPayload, type QualityReport, type SolveResult, type WorkerRequest, type WorkerResponse } from './protocol.ts';

// The DOM lib types `self` as a Window; in a dedicated worker postMessage takes a transfer list.
const scope = self as unknown as {
  postMessage(message: WorkerResponse, transfer: Transferable[]): void;
  onmessage: ((event: MessageEvent<WorkerRequest>) => void) | null;
};

const CLUSTER_VIEW_INTERVAL_MS = 150;

interface Run {
  job: number;
  cancelled: boolean;
  pendingParams: string | null;
}

let flatfacet: FlatfacetModule | null = null;
let session: Session | null = null;
let loadedMesh: MeshPayload | null = null; // the last mesh the core accepted
let currentRun: Run | null = null;

function post(message: WorkerResponse): void {
  scope.postMessage(message, transferablesOf(message));
}

// A macrotask boundary that, unlike setTimeout, is not clamped to 4 ms when nested.
const yieldChannel = new MessageChannel();
const yieldWaiters: (() => void)[] = [];
yieldChannel.port1.onmessage = () => yieldWaiters.shift()?.();
function yieldToEventLoop(): Promise<void> {
  return new Promise((resolve) => {
    yieldWaiters.push(resolve);
    yieldChannel.port2.postMessage(null);
  });
}

function parseJson<T>(text: string): T {
  return JSON.parse(text) as T;
}

function loadInto(target: Session, mesh: MeshPayload): MeshInfo {
  switch (mesh.kind) {
    case 'bytes':
      return parseJson<MeshInfo>(target.loadMesh(mesh.name, mesh.bytes));
    case 'arrays':
      return parseJson<MeshInfo>(target.loadArrays(mesh.name, mesh.positions, mesh.indices));
    case 'shape':
      return parseJson<MeshInfo>(target.loadShape(mesh.name, mesh.triangles));
  }
}

function requireSession(): Session {
  if (!session) throw new Error('the solver is not ready');
  return session;
}

function handleLoad(job: number, mesh: MeshPayload, quiet: boolean): void {
  if (currentRun) currentRun.cancelled = true;
  const target = requireSession();
  const info = loadInto(target, mesh);
  if (!info.ok) {
    post({ type: 'failed', job, message: info.message });
    return;
  }
  loadedMesh = mesh;
  post({
    type: 'loaded',
    job,
    info,
    positions: quiet ? new Float32Array(0) : target.inputPositions().slice(),
    indices: quiet ? new Uint32Array(0) : target.inputIndices().slice(),
  });
}

// A new Session with the loaded mesh: a cold start that does not depend on what ran before.
function freshSession(): Status {
  if (!flatfacet || !loadedMesh) return { ok: false, message: 'no mesh is loaded' };
  const next = new flatfacet.Session();
  const info = loadInto(next, loadedMesh);
  if (!info.ok) {
    next.delete();
    return info;
  }
  session?.delete();
  session = next;
  return { ok: true, message: '' };
}

function collectResult(target: Session, solveSeconds: number, steps: number): SolveResult {
  return {
    clusterIds: target.clusterIds().slice(),
    panelPositions: target.panelPositions().slice(),
    panelOffsets: target.panelOffsets().slice(),
    panelIndices: target.panelIndices().slice(),
    panelTriangles: target.panelTriangles().slice(),
    panelTriangleIds: target.panelTriangleIds().slice(),
    cornerPositions: target.cornerPositions().slice(),
    cornerPlanarity: target.cornerPlanarity().slice(),
    problems: parseJson(target.problems()),
    report: parseJson<QualityReport>(target.reportJson()),
    objText: target.objText(),
    partsCsv: target.partsCsv(),
    solveSeconds,
    steps,
  };
}

async function handleSolve(job: number, fresh: boolean, chain: string[]): Promise<void> {
  if (currentRun) currentRun.cancelled = true;
  const run: Run = { job, cancelled: false, pendingParams: null };
  currentRun = run;
  if (fresh) {
    const status = freshSession();
    if (!status.ok) {
      post({ type: 'failed', job, message: status.message });
      currentRun = null;
      return;
    }
  }
  const started = performance.now(); // the solve itself, not the reload of a fresh start
  const target = requireSession();
  let steps = 0;
  let lastClusterView = started;
  for (const paramsJson of chain) {
    const set = parseJson<Status>(target.setParams(paramsJson));
    if (!set.ok) {
      post({ type: 'failed', job, message: set.message });
      if (currentRun === run) currentRun = null;
      return;
    }
    while (!target.done()) {
      await yieldToEventLoop();
      if (run.cancelled) {
        post({ type: 'cancelled', job });
        return;
      }
      if (run.pendingParams !== null) {
        const update = parseJson<Status>(target.setParams(run.pendingParams));
        run.pendingParams = null;
        if (!update.ok) {
          post({ type: 'failed', job, message: update.message });
          if (currentRun === run) currentRun = null;
          return;
        }
      }
      const progress = parseJson<Progress>(target.step());
      steps += 1;
      if (!progress.ok) {
        post({ type: 'failed', job, message: progress.message });
        if (currentRun === run) currentRun = null;
        return;
      }
      const now = performance.now();
      post({ type: 'progress', job, progress, elapsedSeconds: (now - started) / 1000 });
      if (now - lastClusterView >= CLUSTER_VIEW_INTERVAL_MS && !progress.done) {
        lastClusterView = now;
        post({ type: 'clusters', job, clusterIds: target.clusterIds().slice() });
      }
    }
  }
  const result = collectResult(target, (performance.now() - started) / 1000, steps);
  if (currentRun === run) currentRun = null;
  post({ type: 'solved', job, result });
}

function handle(request: WorkerRequest): void {
  switch (request.type) {
    case 'load':
      handleLoad(request.job, request.mesh, request.quiet);
      return;
    case 'solve':
      void handleSolve(
        request.job,
        request.fresh,
        request.chain.map((params) => JSON.stringify(params)),
      ).catch((error: unknown) => post({ type: 'failed', job: request.job, message: `internal error: ${String(error)}` }));
      return;
    case 'update':
      if (currentRun && currentRun.job === request.job) currentRun.pendingParams = JSON.stringify(request.params);
      return;
    case 'cancel':
      if (currentRun && currentRun.job === request.job) currentRun.cancelled = true;
      else post({ type: 'cancelled', job: request.job });
      return;
  }
}

const ready = createFlatfacet({ locateFile: (path) => (path.endsWith('.wasm') ? wasmUrl : path) }).then(
  (module) => {
    flatfacet = module;
    session = new module.Session();
    post({ type: 'ready', version: module.version() });
    return true;
  },
  (error: unknown) => {
    post({ type: 'fatal', message: `the solver could not start: ${String(error)}` });
    return false;
  },
);

scope.onmessage = (event) => {
  void ready.then((ok) => {
    if (!ok) return;
    try {
      handle(event.data);
    } catch (error) {
      post({ type: 'failed', job: event.data.job, message: `internal error: ${String(error)}` });
    }
  });
};
