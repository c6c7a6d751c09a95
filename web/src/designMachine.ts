// The design's state, as one small machine the page's controller drives (and the unit tests
// drive in Node: no DOM, no worker). It holds
//   mesh     the loaded surface (M: whatever the page keeps about it)
//   opening  meshes on their way in (O): at most one being read on the page, and those sent to
//            the worker and not yet answered. Every load the worker answers becomes the
//            design's mesh (or is refused, leaving the one before), so the page always shows
//            the mesh the worker holds, even when a later open overtook it.
//   solving  the solve under way, if any
//   solved   the last finished result (R): what the view, the stats and the exports show
// and what the worker's session holds: a just-loaded mesh (`pristine`) or exactly `solved`
// (`holdsSolved`, the condition for a warm start). Every worker answer is matched to the job
// that asked for it, so an answer to a job the page moved past changes nothing.
import { compactChain } from './edits/panelEdits.ts';
import { canWarmStart, sameParams, type DesignParams } from './params.ts';

// Why a result cannot be reproduced by replaying its chain of solves from the loaded mesh.
export type ChainLoss = 'changed-mid-solve' | 'long-chain';

export interface Solving {
  job: number;
  params: DesignParams;
  // The solves that reproduce this result from the loaded mesh; null when lost (see `lost`).
  chain: DesignParams[] | null;
  lost: ChainLoss | null;
}

export interface Solved<R> {
  job: number; // the solve that gave it (the worker keeps its panels for fabrication)
  params: DesignParams;
  chain: DesignParams[] | null;
  lost: ChainLoss | null;
  result: R;
}

export interface Opening<O> {
  token: number;
  job: number | null; // null while the page still prepares the payload
  info: O;
}

export type RemeshPlan =
  | { kind: 'refused'; reason: 'no-mesh' | 'opening' }
  // `run` is solved in order from what the session holds; `chain` reproduces the result from
  // the loaded mesh.
  | { kind: 'solve'; run: DesignParams[]; fresh: boolean; chain: DesignParams[] | null; lost: ChainLoss | null };

export class DesignMachine<M, O, R> {
  private meshValue: M | null = null;
  private preparing: Opening<O> | null = null;
  private sent: Opening<O>[] = []; // oldest first
  private solvingValue: Solving | null = null;
  private solvedValue: Solved<R> | null = null;
  private pristine = false;
  private holdsSolved = false;
  private tokens = 0;
  private solverGone = false;

  constructor(private readonly maxHistory: number) {}

  get mesh(): M | null {
    return this.meshValue;
  }
  // The newest open under way, if any.
  get opening(): Opening<O> | null {
    return this.preparing ?? this.sent[this.sent.length - 1] ?? null;
  }
  get solving(): Solving | null {
    return this.solvingValue;
  }
  get solved(): Solved<R> | null {
    return this.solvedValue;
  }
  get sessionPristine(): boolean {
    return this.pristine;
  }
  get sessionHoldsSolved(): boolean {
    return this.holdsSolved;
  }
  // Remesh, Enter and Share act on the loaded mesh: not while another one is opening, since the
  // worker may already hold the new mesh while the page still shows the old one.
  get canRemesh(): boolean {
    return this.meshValue !== null && this.opening === null && !this.solverGone;
  }
  // A link is made on the page: it works without a solver too.
  get canShare(): boolean {
    return this.meshValue !== null && this.opening === null;
  }
  get solverDead(): boolean {
    return this.solverGone;
  }
  get canExport(): boolean {
    return this.meshValue !== null && this.solvedValue !== null;
  }

  // ---- opening

  // A new open supersedes one still being read on the page (that one is never sent); loads
  // already sent are still answered. Returns its token.
  beginOpen(info: O): number {
    this.tokens += 1;
    this.preparing = { token: this.tokens, job: null, info };
    return this.tokens;
  }

  isCurrentOpen(token: number): boolean {
    return this.preparing?.token === token;
  }

  // The payload could not be prepared on the page: nothing reached the worker.
  abandonOpen(token: number): boolean {
    if (!this.isCurrentOpen(token)) return false;
    this.preparing = null;
    return true;
  }

  // The load went to the worker as `job` (the caller dropped any solve under way first: the
  // session's mesh is about to change).
  openSent(token: number, job: number): boolean {
    if (!this.preparing || this.preparing.token !== token) return false;
    this.sent.push({ ...this.preparing, job });
    this.preparing = null;
    return true;
  }

  // The worker loaded the mesh of `job`: it becomes the design's mesh, with no result yet.
  // `newest`: no later open is under way (only then does the open's own solve start).
  loaded(job: number, makeMesh: (info: O) => M): { info: O; mesh: M; newest: boolean } | null {
    const index = this.sent.findIndex((opening) => opening.job === job);
    if (index < 0) return null;
    const opening = this.sent[index]!;
    this.sent = this.sent.slice(index + 1); // the worker answers loads in order
    const mesh = makeMesh(opening.info);
    this.meshValue = mesh;
    this.solvedValue = null;
    this.pristine = true;
    this.holdsSolved = false;
    return { info: opening.info, mesh, newest: this.opening === null };
  }

  // ---- solving

  // What Remesh does with `params`. Warm start (DESIGN.md 2): the session holds the finished
  // previous result and only the count, weights or iteration limits changed. Identical
  // parameters solve afresh.
  planRemesh(params: DesignParams): RemeshPlan {
    if (this.opening) return { kind: 'refused', reason: 'opening' };
    if (!this.meshValue) return { kind: 'refused', reason: 'no-mesh' };
    const previous = this.solvedValue;
    if (previous && this.holdsSolved && !this.solvingValue && canWarmStart(previous.params, params) && !sameParams(previous.params, params)) {
      // Steps that only changed the panel edits fold into the next (edits/panelEdits.ts).
      const chain = previous.chain ? compactChain([...previous.chain, params]) : null;
      if (chain && chain.length <= this.maxHistory + 1) return { kind: 'solve', run: [params], fresh: false, chain, lost: null };
      return { kind: 'solve', run: [params], fresh: false, chain: null, lost: previous.lost ?? 'long-chain' };
    }
    return { kind: 'solve', run: [params], fresh: !this.pristine, chain: [params], lost: null };
  }

  // A solve sent to the worker as `job` (after the caller dropped any solve under way).
  startSolve(job: number, params: DesignParams, chain: DesignParams[] | null, lost: ChainLoss | null): void {
    this.solvingValue = { job, params, chain, lost };
    this.pristine = false;
    this.holdsSolved = false;
  }

  // Stops following the solve under way; returns its job for the worker's cancel.
  dropSolve(): number | null {
    const solving = this.solvingValue;
    if (!solving) return null;
    this.solvingValue = null;
    this.holdsSolved = false;
    return solving.job;
  }

  // A parameter change during the solve: returns the job to update, or null if nothing to do.
  // The result then depends on when the change arrived, so it loses its chain.
  update(params: DesignParams): number | null {
    const solving = this.solvingValue;
    if (!solving || sameParams(solving.params, params)) return null;
    this.solvingValue = { ...solving, params, chain: null, lost: 'changed-mid-solve' };
    return solving.job;
  }

  finishSolve(job: number, result: R): Solved<R> | null {
    const solving = this.solvingValue;
    if (!solving || solving.job !== job || !this.meshValue) return null;
    this.solvingValue = null;
    this.solvedValue = { job, params: solving.params, chain: solving.chain, lost: solving.lost, result };
    this.holdsSolved = true;
    return this.solvedValue;
  }

  // ---- failures

  // A mesh sent to the worker and not yet answered (one still read on the page is not there).
  get loadingInWorker(): boolean {
    return this.sent.length > 0;
  }

  // The opening sent as `job`, while its answer is awaited (null: none such).
  sentOpening(job: number): O | null {
    return this.sent.find((opening) => opening.job === job)?.info ?? null;
  }

  // The core refused job's mesh or parameters: the previous design stays. What failed.
  failed(job: number): 'open' | 'solve' | null {
    let what: 'open' | 'solve' | null = null;
    const index = this.sent.findIndex((opening) => opening.job === job);
    if (index >= 0) {
      this.sent = this.sent.slice(index + 1);
      what = 'open';
    }
    if (this.solvingValue?.job === job) {
      this.solvingValue = null;
      what = 'solve';
    }
    if (what) {
      // The core leaves its session as it was, but which result that is, is not worth guessing.
      this.holdsSolved = false;
      this.pristine = false;
    }
    return what;
  }

  // A new worker solved `solved` again (the same panels) with nothing else sent since: it holds
  // the result on show, so the next change warm-starts from it again. False when the design
  // moved on meanwhile.
  heldAgain(solved: Solved<R>): boolean {
    if (this.solvedValue !== solved || this.solvingValue || this.loadingInWorker) return false;
    this.holdsSolved = true;
    this.pristine = false;
    return true;
  }

  // The worker crashed and a new one took its place (with the mesh reloaded when
  // `meshKept`): nothing sent to the old one survives (an open still being read on the page
  // does), the last result stays on show.
  crashed(meshKept: boolean): { lostOpening: O | null; lostSolve: boolean } {
    const lostOpening = this.sent[this.sent.length - 1]?.info ?? null;
    this.sent = [];
    const lostSolve = this.solvingValue !== null;
    this.solvingValue = null;
    this.holdsSolved = false;
    this.pristine = false;
    if (!meshKept) this.meshValue = null;
    return { lostOpening, lostSolve };
  }

  // The worker could not start ('fatal'): it answers nothing, so nothing more is asked of it
  // (no Remesh, no open; one still being read on the page is dropped). The design on show
  // stays, exportable and shareable: both are made on the page. Returns the open lost (the
  // newest: sent, or still being read).
  solverDied(): O | null {
    const reading = this.preparing?.info ?? null;
    const { lostOpening } = this.crashed(true);
    this.preparing = null;
    this.solverGone = true;
    return reading ?? lostOpening;
  }
}
