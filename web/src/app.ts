// The page's controller: turns clicks into worker requests and worker answers into what the
// page shows. The design's state and its rules (what may run when, warm starts, which answer
// belongs to which request) live in designMachine.ts; downloads, links and the session note
// in outputs.ts; this file wires them to the worker, the view and the status line.
import type { MeshInfo } from '@flatfacet/wasm';
import { countOutcome, element } from './dom.ts';
import { DesignEditor } from './designEditor.ts';
import { DesignMachine, type ChainLoss } from './designMachine.ts';
import { ExamplePicker, showMeshInfo } from './examplePicker.ts';
import { designStem } from './exports.ts';
import { FabricationPanel } from './fabricationPanel.ts';
import { describeDesign, findExample } from './examples.ts';
import { checkEditsFit, clusterCount } from './edits/panelEdits.ts';
import { payloadFromExample, payloadFromFile } from './meshFiles.ts';
import { Outputs } from './outputs.ts';
import { PanelSelection } from './panelSelection.ts';
import { rhinoLoaded } from './rhino/rhinoOpen.ts';
import type { DesignParams } from './params.ts';
import { ParamsForm } from './paramsForm.ts';
import { PrepareControl } from './prepareControl.ts';
import type { MeshRepair } from './meshRepair.ts';
import { RepairControl } from './repairControl.ts';
import type { SolveResult, WorkerResponse } from './protocol.ts';
import { saveSession } from './sessionStore.ts';
import { MAX_HISTORY, type DesignMesh, type DesignState } from './share.ts';
import { SolverClient, solverTestHooks, type Crash } from './solverClient.ts';
import { renderStats } from './stats.ts';
import { solvedSummary, StatusView } from './statusView.ts';
import { guessUpAxis } from './view/upAxis.ts';
import { Viewer } from './view/viewer.ts';

interface LoadedMesh {
  design: DesignMesh;
  label: string;
  fileName: string;
  info: MeshInfo;
}

interface OpenInfo {
  design: DesignMesh;
  label: string;
  fileName: string;
  up: 'y' | 'z' | 'guess';
  params: DesignParams;
  history: DesignParams[];
  solve: boolean;
}

export interface OpenOptions {
  solve: boolean;
  note: string; // said in the status while loading, e.g. "Opening the shared design"
  fromLink?: boolean; // keeps the link in the address bar (it describes this design)
}

export const CRASH_MESSAGE = 'the solver ran out of memory or crashed and was restarted; the last result is kept';

export class App {
  private readonly machine = new DesignMachine<LoadedMesh, OpenInfo, SolveResult>(MAX_HISTORY);
  private readonly solver = new SolverClient(
    { onMessage: (message) => this.onWorkerMessage(message), onCrash: (crash) => this.onCrash(crash) },
    solverTestHooks(),
  );
  private readonly viewer = new Viewer(element('viewport', HTMLElement));
  private readonly form = new ParamsForm();
  private readonly preparation = new PrepareControl();
  private readonly repair = new RepairControl();
  // The last open sent to the worker: what "Use largest manifold part" opens again.
  private lastOpen: { design: DesignMesh; params: DesignParams; history: DesignParams[]; options: OpenOptions } | null = null;
  private readonly status = new StatusView();
  private readonly outputs = new Outputs();
  private readonly examples = new ExamplePicker((id) => void this.openExample(id));
  private readonly remeshButton = element('remesh', HTMLButtonElement);
  private readonly cancelButton = element('cancel', HTMLButtonElement);
  private readonly exportObjButton = element('export-obj', HTMLButtonElement);
  private readonly shareButton = element('share', HTMLButtonElement);
  private readonly statsBox = element('stats', HTMLDivElement);
  // One selected panel for the panel edits and the per-panel thickness.
  private readonly selection = new PanelSelection();
  private readonly fabrication = new FabricationPanel({
    solver: this.solver,
    viewer: this.viewer,
    selection: this.selection,
    panels: () => (this.machine.solving ? null : (this.machine.solved?.result ?? null)),
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
    canEdit: () => this.machine.canRemesh,
    solvedChain: () => this.machine.solved?.chain ?? null,
    solving: () => this.machine.solving !== null,
    result: () => this.machine.solved?.result ?? null,
    remesh: () => this.remesh(),
    replay: (chain) => this.replay(chain),
  });
  // A message to show once the mesh being opened has loaded (set only while opening).
  private pendingNotice: string | null = null;

  constructor() {
    this.remeshButton.addEventListener('click', () => this.remesh());
    this.cancelButton.addEventListener('click', () => this.cancel());
    this.exportObjButton.addEventListener('click', () => this.exportFile('obj'));
    this.shareButton.addEventListener('click', () => void this.share());
    this.form.onChange(() => this.parametersChanged());
    this.preparation.onChange(() => void this.reopenPrepared());
    this.repair.onChange(() => void this.reopenRepaired());
    renderStats(this.statsBox, null);
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
    if (this.machine.opening) this.pendingNotice = message;
    else this.status.error(message);
  }

  noteRestoreFailure(message: string): void {
    this.outputs.noteRestore(message);
  }

  // ---- opening a design

  async openExample(id: string, options: OpenOptions = { solve: true, note: '' }): Promise<void> {
    const example = findExample(id) ?? findExample(this.examples.defaultId)!;
    this.form.setPanels(example.panels); // each example comes with a count that suits it
    this.editor.forgetPaint(); // painted on the previous mesh
    const checked = this.form.read();
    if (!checked.ok) {
      this.status.error(checked.message);
      return;
    }
    const prepare = this.preparation.read(checked.value);
    if (!prepare.ok) {
      this.status.error(prepare.message);
      return;
    }
    const repair = this.repair.read();
    if (!repair.ok) {
      this.status.error(repair.message);
      return;
    }
    await this.open(withRepair({ kind: 'example', id: example.id, prepare: prepare.value }, repair.value), checked.value, [], options);
  }

  async openFile(file: File): Promise<void> {
    this.editor.forgetPaint();
    const params = this.form.read();
    if (!params.ok) {
      this.status.error(params.message);
      return;
    }
    const prepare = this.preparation.read(params.value);
    if (!prepare.ok) {
      this.status.error(prepare.message);
      return;
    }
    const repair = this.repair.read();
    if (!repair.ok) {
      this.status.error(repair.message);
      return;
    }
    const bytes = new Uint8Array(await file.arrayBuffer());
    await this.open(withRepair({ kind: 'file', name: file.name, bytes, prepare: prepare.value }, repair.value), params.value, [], { solve: true, note: '' });
  }

  // New subdivision levels: the design's mesh opened again, prepared with them.
  private async reopenPrepared(): Promise<void> {
    const design = this.machine.mesh?.design;
    const params = this.form.read();
    if (!design || !params.ok) return;
    const prepare = this.preparation.read(params.value);
    if (!prepare.ok) {
      this.status.error(prepare.message);
      return;
    }
    this.editor.forgetPaint(); // painted on the previous mesh
    await this.open({ ...design, prepare: prepare.value }, params.value, [], { solve: true, note: '' });
  }

  // New holes to fill: the design's mesh opened again with them (its largest-part choice kept).
  private async reopenRepaired(): Promise<void> {
    const design = this.machine.mesh?.design;
    const params = this.form.read();
    if (!design || !params.ok) return;
    const repair = this.repair.read(design.repair?.largestPart ?? false);
    if (!repair.ok) {
      this.status.error(repair.message);
      return;
    }
    this.editor.forgetPaint(); // painted on the previous mesh
    await this.open(withRepair(design, repair.value), params.value, [], { solve: true, note: '' });
  }

  // "Use largest manifold part": the refused open again, keeping that part.
  private async openLargestPart(): Promise<void> {
    const last = this.lastOpen;
    if (!last) return;
    const repair = { fillHoles: last.design.repair?.fillHoles ?? 0, largestPart: true };
    await this.open(withRepair(last.design, repair), last.params, last.history, { ...last.options, note: 'Keeping the largest manifold part' });
  }

  async openState(state: DesignState, note: string, fromLink: boolean): Promise<void> {
    this.editor.adopt(state);
    this.form.write(state.params);
    this.preparation.show(state.mesh);
    this.repair.show(state.mesh);
    if (state.fabrication) this.fabrication.write(state.fabrication);
    await this.open(state.mesh, state.params, state.history, { solve: true, note, fromLink });
  }

  private async open(design: DesignMesh, params: DesignParams, history: DesignParams[], options: OpenOptions): Promise<void> {
    const { example, label, fileName, up } = describeDesign(design);
    const token = this.machine.beginOpen({ design, label, fileName, up, params, history, solve: options.solve });
    this.lastOpen = { design, params, history, options };
    this.repair.hideOffer();
    if (!options.fromLink) this.outputs.forgetLink();
    this.updateButtons();
    this.status.show(`${options.note ? `${options.note}: ` : ''}loading ${label}…`);
    const payload = example ? await payloadFromExample(example) : design.kind === 'file' ? await payloadFromFile(design.name, design.bytes) : null;
    if (!this.machine.isCurrentOpen(token)) return; // a later open won
    if (payload?.ok && design.prepare) payload.value.prepare = { ...design.prepare };
    if (payload?.ok && design.repair) payload.value.repair = { ...design.repair };
    if (!payload || !payload.ok) {
      this.machine.abandonOpen(token);
      this.failOpen(payload ? payload.message : 'nothing to open');
      return;
    }
    // The session's mesh is about to change: a solve under way is of no use any more.
    this.dropSolve();
    this.machine.openSent(token, this.solver.load(payload.value));
    this.updateButtons();
  }

  private failOpen(reason: string): void {
    const notice = this.pendingNotice;
    this.pendingNotice = null;
    this.syncExampleSelect();
    this.status.resetProgress();
    this.status.error(notice ? `${notice} ${reason}` : reason);
    this.updateButtons();
  }

  private onLoaded(job: number, info: MeshInfo, positions: Float32Array, indices: Uint32Array): void {
    const loaded = this.machine.loaded(job, (opening) => ({ design: opening.design, label: opening.label, fileName: opening.fileName, info }));
    if (!loaded) return;
    const opening = loaded.info;
    this.viewer.setSurface(positions, indices, opening.up === 'guess' ? guessUpAxis(positions) : opening.up);
    this.editor.meshLoaded(opening.params);
    showMeshInfo(loaded.mesh.label, loaded.mesh.info);
    rhinoLoaded(loaded.mesh.fileName, loaded.mesh.info);
    renderStats(this.statsBox, null);
    this.fabrication.panelsChanged(false);
    this.updateButtons();
    // Overtaken by a later open: shown, since the worker holds it now, but that open goes on.
    if (!loaded.newest) return;
    this.syncExampleSelect();
    this.save({ mesh: opening.design, params: opening.params, history: [], fabrication: this.fabrication.current });
    // Panel edits name triangles: a link's must exist in the mesh it opened.
    const misfit = [...opening.history, opening.params].map((p) => checkEditsFit(p.edits, info.triangles)).find((c) => !c.ok);
    if (opening.solve && misfit && !misfit.ok) {
      this.status.error(`${misfit.message}; not solved.`);
    } else if (opening.solve) {
      const chain = [...opening.history, opening.params];
      this.startSolve(chain, false, chain);
    } else {
      this.status.show(`${opening.label} is loaded. Remesh to make panels.`);
    }
    if (this.pendingNotice) {
      this.status.error(this.pendingNotice);
      this.pendingNotice = null;
    }
    this.updateButtons();
  }

  private syncExampleSelect(): void {
    this.examples.sync(this.machine.mesh?.design);
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
      if (!this.machine.mesh && !this.machine.opening) this.status.error('open a mesh or pick an example first');
      return;
    }
    const checked = this.form.read();
    if (!checked.ok) {
      this.status.error(checked.message);
      return;
    }
    this.dropSolve();
    const plan = this.machine.planRemesh(checked.value);
    if (plan.kind === 'refused') return;
    this.outputs.forgetLink();
    this.startSolve(plan.run, plan.fresh, plan.chain, plan.lost);
  }

  // `run` is solved in order; `chain` is what reproduces the result from the loaded mesh.
  private startSolve(run: DesignParams[], fresh: boolean, chain: DesignParams[] | null, lost: ChainLoss | null = null): void {
    const params = run[run.length - 1]!;
    const job = this.solver.solve(fresh, run.map((p) => this.editor.solveStep(p)));
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
    if (!this.dropSolve()) return;
    const solved = this.machine.solved;
    if (solved) this.viewer.setClusters(solved.result.clusterIds);
    this.status.resetProgress('cancelled');
    this.status.show(solved ? 'Cancelled. The last finished design is shown.' : 'Cancelled.');
    this.updateButtons();
  }

  // A committed change during a solve goes to the worker at once and warm-starts there.
  private parametersChanged(): void {
    if (!this.machine.solving) return;
    const checked = this.form.read();
    if (!checked.ok) {
      this.status.error(checked.message);
      return;
    }
    const job = this.machine.update(checked.value);
    if (job === null) return;
    this.solver.update(job, this.editor.solveStep(checked.value));
    this.outputs.forgetLink();
  }

  private onSolved(job: number, result: SolveResult): void {
    const solved = this.machine.finishSolve(job, result);
    const mesh = this.machine.mesh;
    if (!solved || !mesh) return;
    countOutcome('solves');
    this.viewer.setSolving(false);
    this.viewer.setResult(result);
    renderStats(this.statsBox, result);
    this.status.finishProgress();
    const summary = solvedSummary(result);
    this.status.show(summary.text, summary.warning ? 'info' : 'done');
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
        this.machine.crashed(false);
        this.viewer.setSolving(false);
        this.status.error(message.message);
        this.updateButtons();
        return;
      case 'crashed': // handled by the client (onCrash)
        return;
      case 'loaded':
        this.onLoaded(message.job, message.info, message.positions, message.indices);
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
    const what = this.machine.failed(job);
    if (what === null) return; // an answer to a request the page moved past
    if (what === 'open' && largestPart && !this.machine.opening) {
      // Non-manifold edges: offer the largest manifold part (issue 7).
      this.repair.showOffer(largestPart.faces, largestPart.of, () => void this.openLargestPart());
      reason = `${reason}. Use the largest manifold part (${largestPart.faces.toLocaleString('en-US')} of ${largestPart.of.toLocaleString('en-US')} faces)?`;
    }
    if (what === 'open') {
      if (this.machine.opening) this.status.error(reason); // a later open goes on
      else this.failOpen(reason);
      return;
    }
    if (what === 'solve') {
      this.editor.solveFailed();
      this.viewer.setSolving(false);
      const solved = this.machine.solved;
      if (solved) this.viewer.setClusters(solved.result.clusterIds);
    }
    this.status.resetProgress();
    this.status.error(reason);
    this.updateButtons();
  }

  // The worker crashed and was replaced (with the last loaded mesh, when it could be
  // reloaded). What was under way is lost; the last result stays on show and exportable.
  private onCrash(crash: Crash): void {
    console.warn(`flatfacet: the solver worker crashed: ${crash.message}`);
    const lost = this.machine.crashed(crash.meshKept);
    this.viewer.setSolving(false);
    const solved = this.machine.solved;
    if (solved) this.viewer.setClusters(solved.result.clusterIds);
    this.pendingNotice = null;
    this.fabrication.workerLost();
    this.editor.workerReplaced();
    this.syncExampleSelect();
    this.status.resetProgress();
    const parts = [crash.meshKept ? CRASH_MESSAGE : `${CRASH_MESSAGE}, but without the mesh: open it again`];
    if (lost.lostOpening) parts.push(`${lost.lostOpening.label} was not opened`);
    this.status.error(`${parts.join('; ')}.`);
    this.updateButtons();
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
    document.body.dataset.solving = String(solving);
    const opening = this.machine.opening;
    document.body.dataset.opening = opening === null ? 'false' : opening.job === null ? 'reading' : 'loading';
    this.editor.updateButtons();
  }
}

// The design's mesh with this repair (none: the field left out, as links before it had).
function withRepair(design: DesignMesh, repair: MeshRepair | undefined): DesignMesh {
  const { repair: _old, ...rest } = design;
  return repair ? { ...rest, repair } : rest;
}
