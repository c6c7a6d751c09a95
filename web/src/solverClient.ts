// The page's side of the solver worker: numbers the jobs, drops answers to jobs the page has
// moved past, and makes Cancel answer at once. A worker stuck in a long step cannot read the
// cancel message, so after a short grace it is terminated and a new one reloads the mesh.
import type { RemeshParams } from '@flatfacet/wasm';
import type { MeshPayload, WorkerRequest, WorkerResponse } from './protocol.ts';

const CANCEL_GRACE_MS = 250;

export interface SolverOptions {
  // How long a cancel waits for the worker before replacing it (tests set 0 to exercise the
  // replacement path deterministically).
  cancelGraceMs?: number;
}

export interface SolverEvents {
  // Answers to the current job only (and 'ready' / 'fatal').
  onMessage(message: WorkerResponse): void;
}

export class SolverClient {
  private worker: Worker;
  private job = 0;
  private quietJob = 0;
  private readonly quietJobs = new Set<number>();
  private loadedMesh: MeshPayload | null = null;
  private pendingMesh: { job: number; mesh: MeshPayload } | null = null;
  // Requests made while a cancel waits for its answer: sent once the worker is known to be free.
  private held: WorkerRequest[] | null = null;

  private readonly cancelGraceMs: number;

  constructor(private readonly events: SolverEvents, options: SolverOptions = {}) {
    this.cancelGraceMs = options.cancelGraceMs ?? CANCEL_GRACE_MS;
    this.worker = this.startWorker();
  }

  private startWorker(): Worker {
    const worker = new Worker(new URL('./worker.ts', import.meta.url), { type: 'module', name: 'flatfacet-solver' });
    worker.onmessage = (event: MessageEvent<WorkerResponse>) => this.receive(event.data);
    worker.onerror = (event) => {
      event.preventDefault();
      this.events.onMessage({ type: 'fatal', message: `the solver stopped: ${event.message || 'worker error'}` });
    };
    return worker;
  }

  private receive(message: WorkerResponse): void {
    if (message.type === 'ready' || message.type === 'fatal') {
      this.events.onMessage(message);
      return;
    }
    if (message.type === 'loaded' && this.pendingMesh?.job === message.job) {
      this.loadedMesh = this.pendingMesh.mesh;
      this.pendingMesh = null;
    }
    if (this.quietJobs.has(message.job)) {
      this.quietJobs.delete(message.job);
      if (message.type === 'failed') this.events.onMessage({ type: 'fatal', message: `the solver could not reload the mesh: ${message.message}` });
      return;
    }
    if (message.job !== this.job) return;
    this.events.onMessage(message);
  }

  private send(request: WorkerRequest): void {
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
    this.pendingMesh = { job: this.job, mesh };
    this.send({ type: 'load', job: this.job, mesh, quiet: false });
    return this.job;
  }

  solve(fresh: boolean, chain: RemeshParams[]): number {
    this.job += 1;
    this.send({ type: 'solve', job: this.job, fresh, chain });
    return this.job;
  }

  update(job: number, params: RemeshParams): void {
    if (job === this.job) this.send({ type: 'update', job, params });
  }

  // Stops the job at once as far as the page is concerned (its answers are dropped from now
  // on); the worker stops within one step, or is replaced if it does not answer in time.
  cancel(job: number): void {
    if (job !== this.job || this.held) return;
    this.job += 1;
    const worker = this.worker;
    worker.postMessage({ type: 'cancel', job } satisfies WorkerRequest);
    this.held = [];
    const listener = (event: MessageEvent<WorkerResponse>): void => {
      const message = event.data;
      if (message.type === 'ready' || message.type === 'fatal' || message.job !== job) return;
      if (this.cancelGraceMs > 0 && (message.type === 'cancelled' || message.type === 'solved' || message.type === 'failed')) finish(false);
    };
    const timer = setTimeout(() => finish(true), this.cancelGraceMs);
    const finish = (restart: boolean): void => {
      clearTimeout(timer);
      worker.removeEventListener('message', listener);
      if (worker !== this.worker) return;
      if (restart) this.restart();
      this.release();
    };
    worker.addEventListener('message', listener);
  }

  private restart(): void {
    this.worker.terminate();
    this.worker = this.startWorker();
    // A load still in the held queue is sent after this one and wins, as it should.
    if (this.loadedMesh) {
      // Negative numbers: never confused with the page's jobs, which may already be held.
      this.quietJob -= 1;
      this.quietJobs.add(this.quietJob);
      this.worker.postMessage({ type: 'load', job: this.quietJob, mesh: this.loadedMesh, quiet: true } satisfies WorkerRequest);
    }
  }
}
