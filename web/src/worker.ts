// The solver worker: owns the wasm Session and drives it step by step. Between steps it yields
// to the event loop, so a cancel or a parameter change arrives within one step; the page
// stays free because none of this runs on its thread.
//
// Two kinds of failure: a Status the core returns (`ok: false`: bad mesh, bad parameters; the
// session is intact) is posted as `failed`; anything else a wasm call throws (out of memory,
// a trap, a deleted object) leaves the module in an unknown state, so the worker posts
// `crashed`, stops answering, and the page replaces it.
import createFlatfacet, { type FlatfacetModule, type MeshInfo, type Problems, type Progress, type Session, type Status } from '@flatfacet/wasm';
import wasmUrl from '@flatfacet/wasm-binary?url';
import { decodeField } from './brush/densityField.ts';
import { levelsOf, withPrepare } from './preparation.ts';
import { LEGACY_REFINE_BELOW, LEGACY_REFINE_ROUNDS } from './share.ts';
import { fabricationOf } from './workerFabrication.ts';
import { transferablesOf, type Carry, type MeshPayload, type MeshPrepare, type PrepareFault, type QualityReport, type SolveResult, type SolveStep, type WorkerRequest, type WorkerResponse } from './protocol.ts';

// The DOM lib types `self` as a Window; in a dedicated worker postMessage takes a transfer list.
const scope = self as unknown as {
  postMessage(message: WorkerResponse, transfer: Transferable[]): void;
  onmessage: ((event: MessageEvent<WorkerRequest>) => void) | null;
};

const CLUSTER_VIEW_INTERVAL_MS = 150;
const LOST_PANELS = 'the solver no longer holds the panels on show (it was restarted, or the mesh was read again): Remesh to make their outputs';

interface Run {
  job: number;
  cancelled: boolean;
  pendingStep: SolveStep | null;
}

let flatfacet: FlatfacetModule | null = null;
let session: Session | null = null;
// The mesh the session holds as the page shows it (the last load, with the preparation of the
// last 'prepare' since): what a load refused half-way puts back.
let shown: MeshPayload | null = null;
let currentRun: Run | null = null;
let crashed = false;
let failedToStart = false; // test hook: as if the solver could not start (?failRestart=1)
let stepDelayMs = 0; // test hook: each solve step waits so long first (?stepDelay=MS)
let crashAfterSteps: number | null = null; // test hook: counts down in the second solve
let prepareFault: PrepareFault | null = null; // test hook: `at` counts down the preparations
let solvesFinished = 0;
// The solve whose result the session holds now (null once another solve starts or a mesh
// loads), and the one whose panels it keeps for fabrication (Session.keepPanels): the result
// the page shows, kept when the page says it shows it ('keep'), so a solve finished just
// before the page cancelled it does not replace them; null after a restart or a new mesh.
let finishedJob: number | null = null;
let keptJob: number | null = null;

// A Status with ok false: the request failed, the session kept its mesh and result. A load
// refused for non-manifold edges or a far-off part says how large its largest part is.
class StatusError extends Error {
  constructor(
    message: string,
    readonly largestPart?: { faces: number; of: number },
  ) {
    super(message);
  }
}

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

// A JSON answer that must be a Status-shaped object with `ok: true`; ok false throws a
// StatusError with the core's message; anything else (not JSON, no `ok`) is a crash.
function checked<T extends Status>(text: string, what: string): T {
  const parsed = JSON.parse(text) as unknown;
  if (typeof parsed !== 'object' || parsed === null || typeof (parsed as Status).ok !== 'boolean') throw new Error(`${what}: the core answered something that is not a status`);
  const status = parsed as T;
  if (!status.ok) throw new StatusError(status.message || `${what} failed`, (status as { largestPart?: { faces: number; of: number } }).largestPart);
  return status;
}

// objText() returns a Status JSON on failure; an OBJ never starts with '{'.
function checkedText(text: string, what: string): string {
  if (text.startsWith('{')) checked<Status>(text, what);
  return text;
}

// `restore`: after a refusal half-way, put the mesh on show back (not when that is the load).
function loadInto(target: Session, mesh: MeshPayload, restore = true): MeshInfo {
  const kept = keptJob;
  // Every load sets the repair, so a previous design's never carries over.
  checked<Status>(target.setRepair(mesh.repair?.fillHoles ?? 0, mesh.repair?.largestPart ?? false), 'the repair options');
  const loaded = loadAsIs(target, mesh);
  if (!mesh.prepare) return loaded;
  try {
    // What the load said (a Rhino file's surfaces, say) stays; the counts and notes are now the
    // prepared mesh's.
    return { ...loaded, ...prepareInto(target, mesh.prepare) };
  } catch (error) {
    // Refused after the session took the new mesh: the page keeps the one before, so the
    // session gets it back (else the next Remesh would solve the refused mesh).
    if (error instanceof StatusError && restore && shown) {
      restoreShown(target, shown);
      keptJob = kept; // the session keeps the panels it kept, of this very mesh
    }
    throw error;
  }
}

function restoreShown(target: Session, mesh: MeshPayload): void {
  try {
    loadInto(target, mesh, false);
  } catch (error) {
    // Not a refusal: only a new worker, reloading the page's mesh, agrees with the page now.
    throw new Error(`the mesh on show could not be loaded again: ${error instanceof Error ? error.message : String(error)}`);
  }
}

function prepareInto(target: Session, prepare: MeshPrepare): MeshInfo {
  return checked<MeshInfo>(target.prepare(prepare.panels, prepare.subdivide, prepare.edgeLength ?? 0, prepare.refineBelow ?? LEGACY_REFINE_BELOW, prepare.refineRounds ?? LEGACY_REFINE_ROUNDS), 'preparing the mesh');
}

// The session took a new mesh: the panels it keeps are not of it.
function tookMesh(info: MeshInfo): MeshInfo {
  finishedJob = null;
  keptJob = null;
  return info;
}

function loadAsIs(target: Session, mesh: MeshPayload): MeshInfo {
  return tookMesh(readInto(target, mesh));
}

function readInto(target: Session, mesh: MeshPayload): MeshInfo {
  switch (mesh.kind) {
    case 'bytes':
      return checked<MeshInfo>(target.loadMesh(mesh.name, mesh.bytes), 'reading the mesh');
    case 'arrays':
      return checked<MeshInfo>(target.loadArrays(mesh.name, mesh.positions, mesh.indices), 'reading the mesh');
    case 'shape':
      return checked<MeshInfo>(target.loadShape(mesh.name, mesh.triangles), 'making the example');
    case 'surfaces':
      return checked<MeshInfo>(target.loadSurfaces(mesh.name, mesh.surfacesJson, mesh.positions, mesh.indices), 'tessellating the surfaces');
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
  shown = mesh;
  // Embind's getters return fresh arrays (wasm/bindings.cpp), transferred as they are.
  const positions = quiet ? new Float32Array(0) : target.inputPositions();
  const indices = quiet ? new Uint32Array(0) : target.inputIndices();
  post({ type: 'loaded', job, info, positions, indices });
}

// The mesh prepared again (for a panel count it could not serve, or another subdivision or
// edge length), and the paint and edited triangles carried to it.
function handlePrepare(job: number, prepare: MeshPrepare | null, carry: Carry): void {
  if (currentRun) currentRun.cancelled = true;
  maybePrepareFaultForTest();
  const target = requireSession();
  const info = tookMesh(prepare ? prepareInto(target, prepare) : checked<MeshInfo>(target.prepareAsLoaded(), 'opening the mesh as loaded'));
  let paint: Int8Array | null = null;
  if (carry.paint) {
    const values = target.transferField(Float64Array.from(carry.paint));
    // Not a refusal: the session holds the prepared mesh now, so only a new worker (reloading
    // the page's mesh) agrees with the page again. The page checks what it carries first.
    if (values.length !== info.vertices) throw new Error('the painted density could not be carried to the prepared mesh');
    paint = levelsOf(values);
  }
  const faces = carry.faces.length > 0 ? target.remapFaces(carry.faces) : new Int32Array(0);
  if (faces.length !== carry.faces.length) throw new Error('the panel edits could not be carried to the prepared mesh');
  if (shown) shown = withPrepare(shown, prepare);
  post({ type: 'loaded', job, info, positions: target.inputPositions(), indices: target.inputIndices(), carried: { paint, faces } });
}

function collectResult(target: Session, solveSeconds: number, steps: number): SolveResult {
  const report: QualityReport = checked<Status>(target.reportJson(), 'the quality report') as unknown as QualityReport;
  delete report.ok;
  delete report.message;
  const problems = checked<Problems>(target.problems(), 'the problem list');
  return {
    clusterIds: target.clusterIds(),
    panelPositions: target.panelPositions(),
    panelOffsets: target.panelOffsets(),
    panelIndices: target.panelIndices(),
    panelTriangles: target.panelTriangles(),
    panelTriangleIds: target.panelTriangleIds(),
    facePanels: target.facePanels(),
    cornerPositions: target.cornerPositions(),
    cornerPlanarity: target.cornerPlanarity(),
    panelDeviation: target.panelDeviation(),
    problems,
    report,
    objText: checkedText(target.objText(), 'the panels OBJ'),
    solveSeconds,
    steps,
  };
}

// The test hook ?crashAfterSteps=N: N steps into the worker's second solve (so that a result
// exists to keep), a crash.
function maybeCrashForTest(): void {
  if (crashAfterSteps === null || solvesFinished === 0) return;
  crashAfterSteps -= 1;
  if (crashAfterSteps > 0) return;
  crashAfterSteps = null;
  crashForTest();
}

// The test hooks ?crashOnPrepare=N and ?refuseOnPrepare=N: the worker's Nth 'prepare' request
// (a Remesh that prepares the mesh again, Undo or Redo across preparations, a Surface change;
// not a load) crashes, or is refused as the core refuses.
function maybePrepareFaultForTest(): void {
  if (prepareFault === null) return;
  prepareFault.at -= 1;
  if (prepareFault.at > 0) return;
  const { kind } = prepareFault;
  prepareFault = null;
  if (kind === 'refuse') throw new StatusError('the preparation was refused (test hook ?refuseOnPrepare)');
  crashForTest();
}

// A wasm getter on a deleted Session throws Embind's BindingError: a real non-Status exception
// out of the module, as running out of memory gives.
function crashForTest(): void {
  if (!flatfacet) return;
  const doomed = new flatfacet.Session();
  doomed.delete();
  doomed.clusterIds();
}

// The step's density field, then its parameters: the same calls, in the same order, whether a
// step is solved live or replayed from a link, so both give the same panels.
const NO_DENSITY = new Float64Array(0);
function applyStep(target: Session, step: SolveStep): void {
  checked(target.setDensity(step.paint ? decodeField(step.paint) : NO_DENSITY), 'the density paint');
  checked(target.setParams(JSON.stringify(step.params)), 'the parameters');
}

async function handleSolve(run: Run, fresh: boolean, chain: SolveStep[]): Promise<void> {
  const target = requireSession();
  finishedJob = null;
  // A cold start from the loaded mesh, the same result as a new Session with it.
  if (fresh) target.resetSolve();
  const started = performance.now();
  let steps = 0;
  let lastClusterView = started;
  for (const step of chain) {
    applyStep(target, step);
    while (!target.done()) {
      await yieldToEventLoop();
      if (stepDelayMs > 0) await new Promise((resolve) => setTimeout(resolve, stepDelayMs));
      if (crashed) return;
      if (run.cancelled) {
        post({ type: 'cancelled', job: run.job });
        return;
      }
      if (run.pendingStep !== null) {
        const update = run.pendingStep;
        run.pendingStep = null;
        applyStep(target, update);
      }
      const progress = checked<Progress>(target.step(), 'the solve');
      steps += 1;
      maybeCrashForTest();
      const now = performance.now();
      post({ type: 'progress', job: run.job, progress, elapsedSeconds: (now - started) / 1000 });
      if (now - lastClusterView >= CLUSTER_VIEW_INTERVAL_MS && !progress.done) {
        lastClusterView = now;
        post({ type: 'clusters', job: run.job, clusterIds: target.clusterIds() });
      }
    }
  }
  const result = collectResult(target, (performance.now() - started) / 1000, steps);
  solvesFinished += 1;
  finishedJob = run.job;
  post({ type: 'solved', job: run.job, result });
}

function failWith(job: number, error: unknown): void {
  if (crashed) return;
  if (error instanceof StatusError) {
    post({ type: 'failed', job, message: error.message, ...(error.largestPart ? { largestPart: error.largestPart } : {}) });
    return;
  }
  crashed = true;
  currentRun = null;
  const reason = error instanceof Error ? `${error.name}: ${error.message}` : String(error);
  post({ type: 'crashed', message: reason.slice(0, 300) });
}

function handle(request: WorkerRequest): void {
  switch (request.type) {
    case 'load':
      handleLoad(request.job, request.mesh, request.quiet);
      return;
    case 'prepare':
      handlePrepare(request.job, request.prepare, request.carry);
      return;
    case 'solve': {
      if (currentRun) currentRun.cancelled = true;
      const run: Run = { job: request.job, cancelled: false, pendingStep: null };
      currentRun = run;
      void handleSolve(run, request.fresh, request.chain)
        .catch((error: unknown) => failWith(request.job, error))
        .finally(() => {
          if (currentRun === run) currentRun = null;
        });
      return;
    }
    case 'update':
      if (currentRun && currentRun.job === request.job) currentRun.pendingStep = request.step;
      return;
    case 'cancel':
      if (currentRun && currentRun.job === request.job) currentRun.cancelled = true;
      else post({ type: 'cancelled', job: request.job });
      return;
    case 'keep':
      if (request.job === finishedJob) {
        requireSession().keepPanels();
        keptJob = request.as ?? request.job;
      }
      return;
    case 'fabricate': {
      if (request.panels !== keptJob) {
        post({ type: 'fabricationFailed', job: request.job, message: LOST_PANELS });
        return;
      }
      const outcome = fabricationOf(requireSession(), JSON.stringify(request.settings));
      post(outcome.ok ? { type: 'fabricated', job: request.job, result: outcome.value } : { type: 'fabricationFailed', job: request.job, message: outcome.message });
      return;
    }
    case 'expressionDensity':
      post({ type: 'expressionDensity', job: request.job, expression: request.expression, values: requireSession().expressionDensity(request.expression) });
      return;
    case 'test':
      if (request.failStart) {
        failedToStart = true;
        post({ type: 'fatal', message: 'the solver could not start: test hook ?failRestart' });
        return;
      }
      crashAfterSteps = request.crashAfterSteps ?? null;
      stepDelayMs = request.stepDelayMs ?? 0;
      prepareFault = request.prepareFault ? { ...request.prepareFault } : null;
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
    if (!ok || crashed || failedToStart) return;
    try {
      handle(event.data);
    } catch (error) {
      failWith(event.data.job, error);
    }
  });
};
