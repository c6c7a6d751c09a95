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
// (`holdsSolved`, the condition for a warm start), and the panels it keeps for fabrication
// (`kept`: a solve's, once the page said it shows them; `restoring`: the result on show solved
// again in a worker that lost them). Every worker answer is matched to the job
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
  private kept: number | null = null;
  private restoreValue: { job: number; solved: Solved<R> } | null = null;
  private unrestorable: Solved<R> | null = null; // solved again to other panels: not tried again

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

  // ---- the panels the worker keeps for fabrication (Session.keepPanels)

  // The page told the worker to keep solve `job`'s panels: the result on show.
  keep(job: number): void {
    this.kept = job;
  }
  get keptJob(): number | null {
    return this.kept;
  }

  // A cancel replaced the worker: the new one holds the mesh, not the panels.
  workerReplaced(): void {
    this.kept = null;
  }

  get restoring(): boolean {
    return this.restoreValue !== null;
  }
  // The result restore `job` solves again (null: `job` is no restore under way).
  restoreOf(job: number): Solved<R> | null {
    return this.restoreValue?.job === job ? this.restoreValue.solved : null;
  }

  // The result on show, when the worker should solve its chain again now, quietly, to keep its
  // panels: the worker does not keep them, nothing under way will change what it holds (a
  // solve, a load, a restore), and the chain is known (not lost to a change mid-solve) and has
  // not solved to other panels before.
  restoreTarget(): Solved<R> | null {
    const solved = this.solvedValue;
    if (!solved?.chain || this.kept === solved.job || solved === this.unrestorable) return null;
    if (this.restoreValue || this.solvingValue || this.loadingInWorker || !this.meshValue || this.solverGone) return null;
    return solved;
  }
  startRestore(job: number, solved: Solved<R>): void {
    this.restoreValue = { job, solved };
  }
  // A solve or a load sent to the worker replaces the restore under way.
  dropRestore(): void {
    this.restoreValue = null;
  }
  // Restore `job` was refused (its worker answers no more for it): another may be tried.
  restoreFailed(job: number): boolean {
    if (!this.restoreOf(job)) return false;
    this.restoreValue = null;
    return true;
  }
  // Restore `job` ended with panels. With the very panels on show and the
  // design where it was, they are kept as the result on show (returned: the page tells the
  // worker) and the next change warm-starts from them; other panels are not tried again.
  restored(job: number, samePanels: boolean): Solved<R> | null {
    const solved = this.restoreOf(job);
    if (!solved) return null;
    this.restoreValue = null;
    if (!samePanels) {
      this.unrestorable = solved;
      return null;
    }
    if (!this.heldAgain(solved)) return null;
    this.kept = solved.job;
    return solved;
  }

  // Whether a fabrication request can be answered now: the worker keeps the panels on show,
  // or something under way will settle it (a restore, a solve or a load: each ends in new
  // panels or in restoreTarget), or they are lost (Remesh), or no worker will answer.
  workerPanels(): 'kept' | 'pending' | 'lost' | 'dead' {
    if (this.solverGone) return 'dead';
    if (this.solvedValue && this.kept === this.solvedValue.job) return 'kept';
    if (this.restoreValue || this.solvingValue || this.opening) return 'pending';
    return 'lost';
  }

  // ---- a worker lost

  // The worker crashed and a new one took its place (with the mesh reloaded when
  // `meshKept`): nothing sent to the old one survives (an open still being read on the page
  // does), the last result stays on show. `lostRestore`: a restore was under way.
  crashed(meshKept: boolean): { lostOpening: O | null; lostSolve: boolean; lostRestore: boolean } {
    const lostOpening = this.sent[this.sent.length - 1]?.info ?? null;
    this.sent = [];
    const lostSolve = this.solvingValue !== null;
    const lostRestore = this.restoreValue !== null;
    this.solvingValue = null;
    this.restoreValue = null;
    this.kept = null;
    this.holdsSolved = false;
    this.pristine = false;
    if (!meshKept) this.meshValue = null;
    return { lostOpening, lostSolve, lostRestore };
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
