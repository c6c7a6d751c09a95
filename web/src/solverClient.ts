// The page's side of the solver worker: numbers the jobs, drops answers to jobs the page has
// moved past, and makes Cancel answer at once. A worker stuck in a long step cannot read the
// cancel message, so after a short grace it is terminated and a new one reloads the mesh. A
// worker that crashed (an error event, or a wasm call that threw something other than a
// Status) is replaced the same way, and the page is told so.
import type { FabricationParams } from '@flatfacet/wasm';
import { withPrepare } from './preparation.ts';
import type { Carry, MeshPayload, MeshPrepare, PrepareFault, SolveStep, WorkerRequest, WorkerResponse } from './protocol.ts';

const CANCEL_GRACE_MS = 250;

// Said when something needs a worker that could not start ('fatal'): nothing will answer.
export const SOLVER_DEAD = 'the solver could not start; reload the page';

export interface SolverOptions {
  // How long a cancel waits for the worker before replacing it (tests set 0 to exercise the
  // replacement path deterministically).
  cancelGraceMs?: number;
  // Test hooks: the first worker crashes this many steps into its second solve; its
  // prepareFault.at-th 'prepare' request (1: the first) crashes or is refused.
  crashAfterSteps?: number;
  prepareFault?: PrepareFault;
  // Test hooks: every replacement worker fails to start (the 'fatal' path); the first worker
  // waits this long before each solve step.
  failRestart?: boolean;
  stepDelayMs?: number;
}

export interface Crash {
  message: string;
  // Whether the new worker got the last loaded mesh back (false: none was loaded, or the
  // worker crashed again while reloading it).
  meshKept: boolean;
}

export interface SolverEvents {
  // Answers to the current job, to every load (and 'ready' / 'fatal').
  onMessage(message: WorkerResponse): void;
  // The worker crashed and was replaced; every job up to now is dropped.
  onCrash(crash: Crash): void;
  // A cancel replaced the worker (it did not answer in time): the new one has the mesh back
  // (if one was loaded), not the panels, and a request sent to the old one is not answered.
  onReplaced?(): void;
}

export class SolverClient {
  private worker: Worker;
  private job = 0;
  private fabricateJob = 0;
  private densityJob = 0;
  private quietJob = 0;
  private readonly quietJobs = new Set<number>();
  private loadedMesh: MeshPayload | null = null;
  // Loads sent and not yet answered: every answer to one is passed on (the page shows the
  // mesh the worker holds, even one a later open overtook), and a loaded one is what a new
  // worker gets back.
  private readonly pendingMeshes = new Map<number, MeshPayload>();
  // Requests made while a cancel waits for its answer: sent once the worker is known to be free.
  private held: WorkerRequest[] | null = null;
  private readonly cancelGraceMs: number;
  private readonly failRestart: boolean;
  private dead = false; // the worker could not start ('fatal'): nothing is sent to it any more

  constructor(private readonly events: SolverEvents, options: SolverOptions = {}) {
    this.cancelGraceMs = options.cancelGraceMs ?? CANCEL_GRACE_MS;
    this.failRestart = options.failRestart ?? false;
    this.worker = this.startWorker();
    const { crashAfterSteps, prepareFault, stepDelayMs } = options;
    if (crashAfterSteps !== undefined || prepareFault !== undefined || stepDelayMs !== undefined) this.worker.postMessage({ type: 'test', job: 0, crashAfterSteps, prepareFault, stepDelayMs } satisfies WorkerRequest);
  }

  private startWorker(): Worker {
    const worker = new Worker(new URL('./worker.ts', import.meta.url), { type: 'module', name: 'flatfacet-solver' });
    worker.onmessage = (event: MessageEvent<WorkerResponse>) => {
      if (worker === this.worker) this.receive(event.data);
    };
    worker.onerror = (event) => {
      event.preventDefault();
      if (worker === this.worker) this.recover(event.message || 'worker error');
    };
    return worker;
  }

  private receive(message: WorkerResponse): void {
    if (message.type === 'crashed') {
      this.recover(message.message);
      return;
    }
    if (message.type === 'ready' || message.type === 'fatal') {
      if (message.type === 'fatal') this.dead = true;
      this.events.onMessage(message);
      return;
    }
    if (message.type === 'fabricated' || message.type === 'fabricationFailed') {
      if (message.job === this.fabricateJob) this.events.onMessage(message);
      return;
    }
    if (message.type === 'expressionDensity') {
      if (message.job === this.densityJob) this.events.onMessage(message);
      return;
    }
    const pendingMesh = this.pendingMeshes.get(message.job);
    if (pendingMesh && (message.type === 'loaded' || message.type === 'failed')) {
      this.pendingMeshes.delete(message.job);
      if (message.type === 'loaded') this.loadedMesh = pendingMesh;
      this.events.onMessage(message);
      return;
    }
    if (this.quietJobs.has(message.job)) {
      this.quietJobs.delete(message.job);
      if (message.type === 'failed') {
        this.loadedMesh = null;
        this.events.onCrash({ message: `the solver could not reload the mesh: ${message.message}`, meshKept: false });
      }
      return;
    }
    if (message.job !== this.job) return;
    this.events.onMessage(message);
  }

  private send(request: WorkerRequest): void {
    if (this.dead) return; // the page says so where it matters (SOLVER_DEAD)
    if (this.held) this.held.push(request);
    else this.worker.postMessage(request);
  }

  private release(): void {
    const held = this.held ?? [];
    this.held = null;
    for (const request of held) this.worker.postMessage(request);
  }

  // The mesh bytes are copied, not transferred: the page keeps them for links and restarts.
  load(mesh: MeshPayload): number {
    this.job += 1;
    this.pendingMeshes.set(this.job, mesh);
    this.send({ type: 'load', job: this.job, mesh, quiet: false });
    return this.job;
  }

  // The loaded mesh prepared again (answered like a load; null: the mesh as loaded itself); a
  // new worker gets the mesh back with this preparation. Null without a loaded mesh.
  prepare(prepare: MeshPrepare | null, carry: Carry): number | null {
    if (!this.loadedMesh) return null;
    this.job += 1;
    this.pendingMeshes.set(this.job, withPrepare(this.loadedMesh, prepare));
    this.send({ type: 'prepare', job: this.job, prepare, carry });
    return this.job;
  }

  solve(fresh: boolean, chain: SolveStep[]): number {
    this.job += 1;
    this.send({ type: 'solve', job: this.job, fresh, chain });
    return this.job;
  }

  // The page shows solve `job`'s result: the worker keeps its panels for fabrication.
  keep(job: number, as?: number): void {
    this.send(as === undefined ? { type: 'keep', job } : { type: 'keep', job, as });
  }

  // Fabrication outputs of the panels solve `panels` gave; numbered apart from loads and solves.
  fabricate(settings: FabricationParams, panels: number): number {
    this.fabricateJob += 1;
    this.send({ type: 'fabricate', job: this.fabricateJob, settings, panels });
    return this.fabricateJob;
  }

  // A density expression's values on the loaded mesh; only the latest request is answered.
  expressionDensity(expression: string): void {
    this.densityJob += 1;
    this.send({ type: 'expressionDensity', job: this.densityJob, expression });
  }

  update(job: number, step: SolveStep): void {
    if (job === this.job) this.send({ type: 'update', job, step });
  }

  // Stops the job at once as far as the page is concerned (its answers are dropped from now
  // on); the worker stops within one step, or is replaced if it does not answer in time.
  cancel(job: number): void {
    if (job !== this.job) return;
    this.job += 1;
    if (this.held) {
      // An earlier cancel is still waiting for the worker, which has not seen this job's
      // requests yet: dropping them is the whole cancel.
      this.held = this.held.filter((request) => request.type === 'fabricate' || request.type === 'expressionDensity' || request.job !== job);
      return;
    }
    const worker = this.worker;
    worker.postMessage({ type: 'cancel', job } satisfies WorkerRequest);
    this.held = [];
    const listener = (event: MessageEvent<WorkerResponse>): void => {
      const message = event.data;
      if (message.type === 'ready' || message.type === 'fatal' || message.type === 'crashed' || message.job !== job) return;
      if (this.cancelGraceMs > 0 && (message.type === 'cancelled' || message.type === 'solved' || message.type === 'failed')) finish(false);
    };
    const timer = setTimeout(() => finish(true), this.cancelGraceMs);
    const finish = (restart: boolean): void => {
      clearTimeout(timer);
      worker.removeEventListener('message', listener);
      if (worker !== this.worker) return; // replaced meanwhile (a crash): nothing is held any more
      if (restart) this.restart(true);
      this.release();
      if (restart) this.events.onReplaced?.();
    };
    worker.addEventListener('message', listener);
  }

  // A new worker with the last loaded mesh (loaded quietly: the page already shows it).
  private restart(reload: boolean): boolean {
    this.worker.terminate();
    this.worker = this.startWorker();
    if (this.failRestart) this.worker.postMessage({ type: 'test', job: 0, failStart: true } satisfies WorkerRequest);
    this.quietJobs.clear();
    if (!reload || !this.loadedMesh) return false;
    // A load still in the held queue is sent after this one and wins, as it should.
    // Negative numbers: never confused with the page's jobs, which may already be held.
    this.quietJob -= 1;
    this.quietJobs.add(this.quietJob);
    this.worker.postMessage({ type: 'load', job: this.quietJob, mesh: this.loadedMesh, quiet: true } satisfies WorkerRequest);
    return true;
  }

  // The worker crashed: every job so far is dropped (held requests too), a new worker reloads
  // the last mesh, unless it was that reload which crashed (no crash loop).
  private recover(reason: string): void {
    const crashedWhileReloading = this.quietJobs.size > 0;
    this.job += 1;
    this.held = null;
    this.pendingMeshes.clear();
    if (crashedWhileReloading) this.loadedMesh = null;
    const meshKept = this.restart(!crashedWhileReloading);
    this.events.onCrash({ message: reason, meshKept });
  }
}

// Test hooks from the page's address: ?cancelGrace=0 makes every cancel replace the worker
// (the path a long step takes); ?crashAfterSteps=N makes the first worker crash N steps into
// its second solve; ?crashOnPrepare=N or ?refuseOnPrepare=N (the latter wins when both are
// given) makes its Nth 'prepare' request crash or be refused; ?failRestart=1 makes every
// replacement worker fail to start; ?stepDelay=MS slows the first worker's solve steps. Only
// on a page served from this machine (the tests', scripts/start.sh): a link to the site
// carrying one does nothing.
const LOOPBACK_HOSTS = new Set(['127.0.0.1', 'localhost', '[::1]']);

export function solverTestHooks(): SolverOptions {
  if (!LOOPBACK_HOSTS.has(location.hostname)) return {};
  const numberFromUrl = (name: string, max: number): number | undefined => {
    const value = new URLSearchParams(location.search).get(name);
    const n = value === null ? Number.NaN : Number(value);
    return Number.isInteger(n) && n >= 0 && n <= max ? n : undefined;
  };
  const options: SolverOptions = {};
  const cancelGraceMs = numberFromUrl('cancelGrace', 10_000);
  const crashAfterSteps = numberFromUrl('crashAfterSteps', 1_000_000);
  if (cancelGraceMs !== undefined) options.cancelGraceMs = cancelGraceMs;
  if (crashAfterSteps !== undefined) options.crashAfterSteps = crashAfterSteps;
  if (numberFromUrl('failRestart', 1) === 1) options.failRestart = true;
  const stepDelayMs = numberFromUrl('stepDelay', 10_000);
  if (stepDelayMs !== undefined) options.stepDelayMs = stepDelayMs;
  for (const kind of ['crash', 'refuse'] as const) {
    const at = numberFromUrl(`${kind}OnPrepare`, 1_000);
    if (at !== undefined && at > 0) options.prepareFault = { at, kind };
  }
  return options;
}
