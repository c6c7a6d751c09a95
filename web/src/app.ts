// The page's controller: turns clicks into worker requests and worker answers into what the
// page shows. The design's state and its rules (what may run when, warm starts, which answer
// belongs to which request) live in designMachine.ts; opening a design and preparing its mesh
// again in designOpener.ts; downloads, links and the session note in outputs.ts; this file
// wires them to the worker, the view and the status line.
import { faceOfCollapsed } from './collapsedPanel.ts';
import { countOutcome, element } from './dom.ts';
import { DesignEditor } from './designEditor.ts';
import { DesignMachine, type ChainLoss } from './designMachine.ts';
import { DesignOpener, type LoadedMesh, type OpenInfo, type OpenOptions } from './designOpener.ts';
import { ExamplePicker } from './examplePicker.ts';
import { designStem } from './exports.ts';
import { FabricationPanel } from './fabricationPanel.ts';
import { clusterCount, newSeedNotice } from './edits/panelEdits.ts';
import { Outputs } from './outputs.ts';
import { PanelSelection } from './panelSelection.ts';
import { canWarmStart, type DesignParams } from './params.ts';
import { ParamsForm } from './paramsForm.ts';
import { PrepareControl } from './prepareControl.ts';
import { RepairControl } from './repairControl.ts';
import type { SolveResult, WorkerResponse } from './protocol.ts';
import { renderQuality } from './qualityViews.ts';
import { saveSession } from './sessionStore.ts';
import { MAX_HISTORY, type DesignState } from './share.ts';
import { SOLVER_DEAD, SolverClient, solverTestHooks, type Crash } from './solverClient.ts';
import { solvedSummary, StatusView } from './statusView.ts';
import { Viewer } from './view/viewer.ts';

export type { OpenOptions };

const CRASHED = 'the solver ran out of memory or crashed and was restarted';
export const CRASH_MESSAGE = `${CRASHED}; the last result is kept`;

// What a crash leaves: the result on show, if any (a mesh just opened has none), and the mesh
// in the new worker, unless reloading it failed.
function crashMessage(result: boolean, meshKept: boolean): string {
  if (!result) return meshKept ? `${CRASHED}; the mesh is kept: Remesh to solve it` : `${CRASHED} without the mesh: open it again`;
  return meshKept ? CRASH_MESSAGE : `${CRASH_MESSAGE}, but without the mesh: open it again`;
}

export class App {
  private readonly machine = new DesignMachine<LoadedMesh, OpenInfo, SolveResult>(MAX_HISTORY);
  // Said with the summary of solve `job` (DesignOpener: what an open or re-preparation dropped),
  // or with whatever ends it otherwise (a cancel, a refusal, a crash); a solve that replaces it
  // on the same mesh, or on the same design prepared or repaired anew, says it instead.
  private solveNotice: { job: number; mesh: LoadedMesh | null; text: string } | null = null;
  private readonly solver = new SolverClient(
    { onMessage: (message) => this.onWorkerMessage(message), onCrash: (crash) => this.onCrash(crash), onReplaced: () => this.onReplaced() },
    solverTestHooks(),
  );
  private readonly viewer = new Viewer(element('viewport', HTMLElement));
  private readonly form = new ParamsForm();
  private readonly preparation = new PrepareControl();
  private readonly repair = new RepairControl();
  private readonly status = new StatusView();
  private readonly outputs = new Outputs();
  private readonly examples = new ExamplePicker((id) => void this.opener.openExample(id));
  private readonly remeshButton = element('remesh', HTMLButtonElement);
  private readonly cancelButton = element('cancel', HTMLButtonElement);
  private readonly exportObjButton = element('export-obj', HTMLButtonElement);
  private readonly shareButton = element('share', HTMLButtonElement);
  private readonly statsBox = element('stats', HTMLDivElement);
  private readonly collapsedSelectButton = element('collapsed-select', HTMLButtonElement);
  // One selected panel for the panel edits and the per-panel thickness.
  private readonly selection = new PanelSelection();
  private readonly fabrication = new FabricationPanel({
    solver: this.solver,
    viewer: this.viewer,
    selection: this.selection,
    panels: () => (this.machine.solving ? null : (this.machine.solved?.result ?? null)),
    panelsJob: () => this.machine.solved?.job ?? null,
    workerPanels: () => this.machine.workerPanels(),
    stem: () => designStem(this.machine.mesh?.fileName ?? 'design'),
    error: (message) => this.status.error(message),
    settingsChanged: () => this.fabricationChanged(),
  });
  // Undo/redo, the density brush and the painted fields (designEditor.ts).
  private readonly editor = new DesignEditor({
    form: this.form,
    viewer: this.viewer,
    selection: this.selection,
    requestExpression: (expression) => this.solver.expressionDensity(expression),
    error: (message) => this.status.error(message),
    note: (message) => this.status.show(message),
    canEdit: () => this.machine.canRemesh,
    solvedChain: () => this.machine.solved?.chain ?? null,
    solving: () => this.machine.solving !== null,
    result: () => this.machine.solved?.result ?? null,
    remesh: () => this.remesh(),
    replay: (chain) => this.replay(chain),
    prepared: () => this.machine.mesh?.design.prepare,
    // A design from before preparations were recorded has none: the mesh as loaded.
    reprepare: (prepare, chain) => this.opener.prepareAgain(prepare, chain[chain.length - 1]!, chain.slice(0, -1), 'replay'),
  });
  private readonly opener: DesignOpener = new DesignOpener({
    machine: this.machine,
    solver: this.solver,
    viewer: this.viewer,
    form: this.form,
    preparation: this.preparation,
    repair: this.repair,
    editor: this.editor,
    status: this.status,
    outputs: this.outputs,
    examples: this.examples,
    fabrication: this.fabrication,
    statsBox: this.statsBox,
    dropSolve: () => {
      this.dropSolve();
      this.dropRestore(); // the worker drops it for the load
    },
    startSolve: (run, fresh, chain, notice, sameDesign) => this.startSolve(run, fresh, chain, null, notice, sameDesign),
    save: (state) => this.save(state),
    updateButtons: () => this.updateButtons(),
    openFailed: () => this.restorePanels(), // an open sent meanwhile had dropped a restore
  });

  constructor() {
    this.remeshButton.addEventListener('click', () => this.remesh());
    this.cancelButton.addEventListener('click', () => this.cancel());
    this.exportObjButton.addEventListener('click', () => this.exportFile('obj'));
    this.shareButton.addEventListener('click', () => void this.share());
    this.collapsedSelectButton.addEventListener('click', () => this.selectCollapsedPanel());
    this.form.onChange(() => this.parametersChanged());
    this.preparation.onChange(() => this.opener.preparationChanged());
    this.repair.onChange(() => void this.opener.repairChanged());
    renderQuality(this.statsBox, null);
    this.updateButtons();
  }

  get isSolving(): boolean {
    return this.machine.solving !== null;
  }

  get currentHash(): string {
    return this.outputs.currentHash;
  }

  get viewerForToggles(): Viewer {
    return this.viewer;
  }

  get defaultExampleId(): string {
    return this.examples.defaultId;
  }

  setAvailableExampleFiles(files: Set<string>): void {
    this.examples.setAvailableFiles(files);
  }

  // A message about how the page was opened (a broken link): while a mesh is opening it waits
  // until that mesh is shown, so it is what the designer reads; otherwise it shows at once.
  showError(message: string): void {
    if (this.machine.opening) this.opener.pendingNotice = message;
    else this.status.error(message);
  }

  noteRestoreFailure(message: string): void {
    this.outputs.noteRestore(message);
  }

  // ---- opening a design (designOpener.ts)

  openExample(id: string, options?: OpenOptions): Promise<void> {
    return this.opener.openExample(id, options);
  }

  openFile(file: File): Promise<void> {
    return this.opener.openFile(file);
  }

  openState(state: DesignState, note: string, fromLink: boolean): Promise<void> {
    return this.opener.openState(state, note, fromLink);
  }

  private save(state: DesignState): void {
    void saveSession(this.editor.withPaint(state)).then((outcome) => {
      this.outputs.noteSave(outcome.ok ? null : outcome.message);
      if (outcome.ok) countOutcome('saves');
    });
  }

  // ---- solving

  // Remesh, and Enter in a parameter field. Refused while a mesh is opening (the button is
  // disabled then too): the worker may already hold the new mesh.
  remesh(): void {
    if (!this.machine.canRemesh) {
      if (this.machine.solverDead) this.status.error(SOLVER_DEAD);
      else if (!this.machine.mesh && !this.machine.opening) this.status.error('open a mesh or pick an example first');
      return;
    }
    const checked = this.form.read();
    if (!checked.ok) {
      this.status.error(checked.message);
      return;
    }
    if (this.opener.prepareIfNeeded(checked.value)) return;
    this.dropSolve();
    const plan = this.machine.planRemesh(checked.value);
    if (plan.kind === 'refused') return;
    this.outputs.forgetLink();
    const shown = this.machine.solved?.params;
    const notice = shown && !canWarmStart(shown, checked.value) ? newSeedNotice(checked.value.edits) : null;
    this.startSolve(plan.run, plan.fresh, plan.chain, plan.lost, notice);
  }

  // `run` is solved in order; `chain` is what reproduces the result from the loaded mesh.
  // `notice`: said with this solve's summary (what an open or a re-preparation dropped), after
  // the notice of a solve this one replaced unsaid, on this mesh or on `sameDesign` (the mesh
  // this one prepared or repaired anew).
  private startSolve(run: DesignParams[], fresh: boolean, chain: DesignParams[] | null, lost: ChainLoss | null = null, notice: string | null = null, sameDesign: LoadedMesh | null = null): void {
    const params = run[run.length - 1]!;
    this.dropRestore(); // the worker drops it for this solve
    const job = this.solver.solve(fresh, run.map((p) => this.editor.solveStep(p)));
    const unsaid = this.solveNotice;
    const replaced = unsaid && (unsaid.mesh === this.machine.mesh || (sameDesign !== null && unsaid.mesh === sameDesign)) ? unsaid.text : null;
    const text = [replaced, notice].filter((t) => t !== null).join(' ') || null;
    this.solveNotice = text ? { job, mesh: this.machine.mesh, text } : null;
    this.machine.startSolve(job, params, chain, lost);
    this.viewer.setSolving(true);
    this.status.show(`Solving ${params.panels} panels…`);
    this.status.resetProgress('starting');
    this.updateButtons();
  }

  // Undo / redo: the chain that made a result, solved afresh from the loaded mesh (the same
  // panels, as a share link replays them).
  private replay(chain: DesignParams[]): void {
    if (!this.machine.canRemesh || chain.length === 0) return;
    this.dropSolve();
    this.outputs.forgetLink();
    this.startSolve(chain, true, chain);
  }

  private dropSolve(): boolean {
    const job = this.machine.dropSolve();
    if (job === null) return false;
    this.solver.cancel(job);
    this.viewer.setSolving(false);
    return true;
  }

  cancel(): void {
    const job = this.machine.solving?.job ?? null;
    if (!this.dropSolve()) return;
    const solved = this.machine.solved;
    if (solved) this.viewer.setClusters(solved.result.clusterIds);
    this.status.resetProgress('cancelled');
    const notice = this.takeSolveNotice(job);
    this.status.show(`${notice ? `${notice} ` : ''}${solved ? 'Cancelled. The last finished design is shown.' : 'Cancelled.'}`);
    this.restorePanels(); // when the cancelled solve had replaced a restore
    this.updateButtons();
    // No panels on show: the mesh was prepared anew for the cancelled step (more panels than
    // it could serve). The design before it comes back as Undo brings it: prepared back, solved.
    if (!solved && this.editor.backToSolved()) this.status.show(`${notice ? `${notice} ` : ''}Cancelled. The last finished design is coming back…`);
  }

  // A committed change during a solve goes to the worker at once and warm-starts there.
  private parametersChanged(): void {
    if (!this.machine.solving) return;
    const checked = this.form.read();
    if (!checked.ok) {
      this.status.error(checked.message);
      return;
    }
    if (this.opener.prepareIfNeeded(checked.value)) return;
    const job = this.machine.update(checked.value);
    if (job === null) return;
    this.solver.update(job, this.editor.solveStep(checked.value));
    this.outputs.forgetLink();
  }

  private onSolved(job: number, result: SolveResult): void {
    if (this.machine.restoreOf(job)) {
      this.panelsRestored(job, result);
      return;
    }
    const solved = this.machine.finishSolve(job, result);
    const mesh = this.machine.mesh;
    if (!solved || !mesh) return;
    countOutcome('solves');
    this.solver.keep(job); // before the fabrication request below
    this.machine.keep(job);
    this.viewer.setSolving(false);
    this.viewer.setResult(result);
    renderQuality(this.statsBox, result);
    this.status.finishProgress();
    const summary = solvedSummary(result);
    const notice = this.takeSolveNotice(job);
    if (notice) this.status.show(`${notice} ${summary.text}`, 'info'); // it still ends "Done: N panels"
    else this.status.show(summary.text, summary.warning ? 'info' : 'done');
    this.fabrication.panelsChanged(result.panelTriangles.length > 0);
    this.editor.solved(solved.params, solved.chain, clusterCount(result.clusterIds));
    this.save({ mesh: mesh.design, params: solved.params, history: solved.chain ? solved.chain.slice(0, -1) : [], fabrication: this.fabrication.current });
    this.updateButtons();
  }

  private onWorkerMessage(message: WorkerResponse): void {
    switch (message.type) {
      case 'ready':
        document.body.dataset.solverVersion = message.version;
        return;
      case 'fatal':
        this.onSolverDead(message.message);
        return;
      case 'crashed': // handled by the client (onCrash)
        return;
      case 'loaded':
        this.opener.onLoaded(message.job, message.info, message.positions, message.indices, message.carried);
        return;
      case 'failed':
        this.onFailed(message.job, message.message, message.largestPart);
        return;
      case 'progress':
        if (this.machine.solving?.job === message.job) this.status.showProgress(message.progress, message.elapsedSeconds);
        return;
      case 'clusters':
        if (this.machine.solving?.job === message.job) this.viewer.showLiveClusters(message.clusterIds);
        return;
      case 'solved':
        this.onSolved(message.job, message.result);
        return;
      case 'cancelled':
        return;
      case 'fabricated':
        this.fabrication.onFabricated(message.job, message.result);
        return;
      case 'fabricationFailed':
        this.fabrication.onFailed(message.job, message.message);
        return;
      case 'expressionDensity':
        this.editor.expressionAnswered(message.expression, message.values);
        return;
    }
  }

  // The core refused a mesh or parameters: the previous design stays loaded and usable.
  private onFailed(job: number, reason: string, largestPart?: { faces: number; of: number }): void {
    if (this.machine.restoreFailed(job)) {
      this.showRestoring(); // a deferred fabrication is then refused: Remesh
      this.fabrication.sendDeferred();
      return;
    }
    const failedOpen = this.machine.sentOpening(job);
    const what = this.machine.failed(job);
    if (what === null) return; // an answer to a request the page moved past
    if (what === 'open' && largestPart && !this.machine.opening) {
      // Non-manifold edges or a stray part far off: offer the largest manifold part (issue 7).
      this.repair.showOffer(largestPart.faces, largestPart.of, () => void this.opener.openLargestPart());
      reason = `${reason}. Use the largest manifold part (${largestPart.faces.toLocaleString('en-US')} of ${largestPart.of.toLocaleString('en-US')} faces)?`;
    }
    if (what === 'open') {
      // Another open going on has written the form for its design.
      const takenBack = this.editor.repreparationLost(this.machine.opening === null);
      if (takenBack) reason = `${reason}; ${takenBackNote(takenBack)}`;
      const solved = this.machine.solved; // the open dropped a solve under way: its clusters go
      if (solved) this.viewer.setClusters(solved.result.clusterIds);
      if (!this.machine.opening) {
        this.opener.failOpen(reason, !failedOpen?.reprepare); // the Surface section too (and restorePanels)
        return;
      }
      // A later open goes on. The Surface section shows the mesh on show's (a preparation or
      // repair refused) until that open's mesh comes.
      if (this.machine.mesh) {
        this.preparation.show(this.machine.mesh.design);
        this.repair.show(this.machine.mesh.design);
      }
      this.status.error(reason);
      return;
    }
    if (what === 'solve') {
      const notice = this.takeSolveNotice(job);
      if (notice) reason = `${reason}. ${notice}`;
      this.editor.solveFailed();
      this.viewer.setSolving(false);
      const solved = this.machine.solved;
      if (solved) this.viewer.setClusters(solved.result.clusterIds);
      this.restorePanels(); // when the refused solve had replaced a restore
    }
    this.status.resetProgress();
    this.status.error(reason);
    this.updateButtons();
  }

  // The worker crashed and was replaced (with the last loaded mesh, when it could be
  // reloaded). What was under way is lost; the last result stays on show and exportable.
  private onCrash(crash: Crash): void {
    console.warn(`flatfacet: the solver worker crashed: ${crash.message}`);
    const notice = this.takeSolveNotice(this.machine.solving?.job ?? null);
    const lost = this.machine.crashed(crash.meshKept);
    this.showWorkLost();
    this.editor.workerReplaced();
    const parts = [crashMessage(this.machine.solved !== null, crash.meshKept)];
    const takenBack = this.editor.repreparationLost(this.machine.opening === null);
    if (takenBack && crash.meshKept) parts.push(takenBackNote(takenBack));
    const lostOpen = this.forgetLostOpen(lost.lostOpening, crash.meshKept);
    if (lostOpen) parts.push(lostOpen);
    this.status.error(`${parts.join('; ')}.${notice ? ` ${notice}` : ''}`);
    if (crash.meshKept && !lost.lostRestore) this.restorePanels(); // not again: no crash loop
    else this.fabrication.sendDeferred(); // a deferred request is refused: Remesh
    this.updateButtons();
  }

  // A worker that could not start ('fatal'): nothing more is asked of it (DesignMachine.solverDied),
  // what was under way is lost as in a crash, and the design on show stays, exportable.
  private onSolverDead(message: string): void {
    const notice = this.takeSolveNotice(this.machine.solving?.job ?? null);
    const lost = this.machine.solverDied();
    this.showWorkLost();
    this.fabrication.sendDeferred(); // a request waiting is told the solver is gone
    const parts = [message];
    const takenBack = this.editor.repreparationLost(true); // no answer will come
    if (takenBack && this.machine.mesh) parts.push(takenBackNote(takenBack));
    const lostOpen = this.forgetLostOpen(lost, true);
    if (lostOpen) parts.push(lostOpen);
    const exportable = this.machine.canExport ? '; the panels on show can still be exported and shared' : '';
    this.status.error(`${parts.join('; ')}. Reload the page${exportable}.${notice ? ` ${notice}` : ''}`);
    this.updateButtons();
  }

  // What a lost worker was doing is gone from the page: the solve's live view (the result on
  // show's clusters again), a message waiting for an open, a restore, a fabrication awaited.
  private showWorkLost(): void {
    this.viewer.setSolving(false);
    const solved = this.machine.solved;
    if (solved) this.viewer.setClusters(solved.result.clusterIds);
    this.opener.pendingNotice = null;
    this.showRestoring();
    this.fabrication.workerLost();
    this.status.resetProgress();
  }

  // After a worker was lost, the page shows the design on show again where an open lost with it
  // had written its own (the form, the Surface section, the example picker), unless another
  // open, still read on the page, goes on. Returns what to say of the lost open.
  private forgetLostOpen(lostOpen: OpenInfo | null, meshKept: boolean): string | null {
    const mesh = this.machine.mesh;
    if (mesh && !this.machine.opening) {
      this.preparation.show(mesh.design);
      this.repair.show(mesh.design);
      if (lostOpen && !lostOpen.reprepare && meshKept) this.editor.showCurrent(); // its parameters go with it
    }
    this.opener.syncExampleSelect();
    if (lostOpen && !lostOpen.reprepare) return `${lostOpen.label} was not opened`;
    if (lostOpen?.reprepare === 'carry' && meshKept) return 'the mesh was not prepared again';
    return null;
  }

  // A cancel replaced a worker that did not answer in time: a fabrication it was asked for
  // will not come, and the new one has the mesh but not the panels on show.
  private onReplaced(): void {
    this.machine.workerReplaced();
    this.fabrication.workerLost();
    this.restorePanels();
  }

  // A worker that does not keep the panels on show (a new one, or a solve that replaced a
  // restore was cancelled) solves their chain again, quietly (a solve is deterministic: the
  // same panels), so that fabrication, which reads the worker's panels, and the next warm start
  // work as before. Not for a result whose chain is lost (changed mid-solve, a long chain):
  // fabrication then asks for a Remesh.
  private restorePanels(): void {
    if (this.machine.restoring || this.machine.solverDead) return;
    const solved = this.machine.restoreTarget();
    if (solved?.chain) {
      this.machine.startRestore(this.solver.solve(true, solved.chain.map((p) => this.editor.solveStep(p))), solved);
      this.showRestoring();
      return;
    }
    this.fabrication.sendDeferred(); // a deferred request goes: answered, refused (Remesh), or waits again
  }

  // The very panels on show (checked by their OBJ), and the design has not moved on: the worker
  // keeps them as the result on show (else a fabrication request is refused, which is then the
  // truth).
  private panelsRestored(job: number, result: SolveResult): void {
    const restoring = this.machine.restoreOf(job)!;
    const kept = this.machine.restored(job, result.objText === restoring.result.objText);
    this.showRestoring();
    if (kept) this.solver.keep(job, kept.job); // before a deferred fabrication request
    this.fabrication.sendDeferred();
  }

  private dropRestore(): void {
    this.machine.dropRestore();
    this.showRestoring();
  }

  private showRestoring(): void {
    document.body.dataset.restoring = String(this.machine.restoring);
  }

  // The notice said with solve `job`'s end, if it has one (it is said once).
  private takeSolveNotice(job: number | null): string | null {
    const notice = this.solveNotice;
    if (!notice || notice.job !== job) return null;
    this.solveNotice = null;
    return notice.text;
  }

  // ---- outputs

  // A fabrication setting changed: the stored session follows, a link no longer describes it.
  private fabricationChanged(): void {
    this.outputs.forgetLink();
    const mesh = this.machine.mesh;
    if (!mesh || this.machine.opening) return;
    const solved = this.machine.solved;
    const formParams = this.form.read();
    const params = solved?.params ?? (formParams.ok ? formParams.value : null);
    if (!params) return;
    this.save({ mesh: mesh.design, params, history: solved?.chain ? solved.chain.slice(0, -1) : [], fabrication: this.fabrication.current });
  }

  // The collapsed panel's legend button: selects it for the panel edits, as a click on it in
  // the view would (it is usually too small to click), and moves the focus to the next step,
  // "Merge with neighbour" (which brings the Panel edits section into view).
  private selectCollapsedPanel(): void {
    const result = this.machine.solving ? null : (this.machine.solved?.result ?? null);
    const face = result ? faceOfCollapsed(result) : null;
    if (face !== null && this.editor.selectPanelFace(face)) element('merge-panel', HTMLButtonElement).focus();
  }

  private exportFile(kind: 'obj'): void {
    const mesh = this.machine.mesh;
    const solved = this.machine.solved;
    if (mesh && solved) this.outputs.exportFile(kind, mesh.fileName, solved.result);
  }

  async share(): Promise<void> {
    const mesh = this.machine.mesh;
    if (!this.machine.canShare || !mesh) return;
    const solved = this.machine.solved;
    const formParams = this.form.read();
    const params = solved?.params ?? (formParams.ok ? formParams.value : null);
    if (!params) return;
    // The history replays a warm-start chain so the link gives the identical panels.
    const state = { mesh: mesh.design, params, history: solved?.chain ? solved.chain.slice(0, -1) : [], fabrication: this.fabrication.current };
    const shared = await this.outputs.share(this.editor.withPaint(state), solved && !solved.chain ? solved.lost : null);
    if (shared.ok) this.status.show(shared.text);
    else this.status.error(shared.message);
  }

  private updateButtons(): void {
    const solving = this.machine.solving !== null;
    this.remeshButton.disabled = !this.machine.canRemesh;
    this.cancelButton.disabled = !solving;
    this.exportObjButton.disabled = !this.machine.canExport;
    this.shareButton.disabled = !this.machine.canShare;
    this.collapsedSelectButton.disabled = solving || !this.machine.canRemesh;
    document.body.dataset.solving = String(solving);
    const opening = this.machine.opening;
    // The open has read them (and writes its mesh's own), or no solver would prepare the mesh.
    this.preparation.setReadOnly(opening !== null || this.machine.solverDead);
    this.repair.setReadOnly(opening !== null || this.machine.solverDead);
    document.body.dataset.opening = opening === null ? 'false' : opening.job === null ? 'reading' : 'loading';
    this.editor.updateButtons();
  }
}

// Said when an Undo or Redo was taken back because its mesh could not be prepared again.
function takenBackNote(move: 'Undo' | 'Redo'): string {
  return `${move} was taken back (its mesh could not be prepared again)`;
}
