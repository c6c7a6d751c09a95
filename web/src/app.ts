// The page's controller: opens meshes, runs solves in the worker, shows progress and results,
// and hands out exports and share links. Holds the one copy of the design's state:
//   mesh    the loaded surface (and what it came from, for links and the stored session)
//   solving the solve under way, if any
//   solved  the last finished result: what the view, the stats and the exports show
import type { MeshInfo } from '@flatfacet/wasm';
import { countOutcome, element } from './dom.ts';
import { DEFAULT_EXAMPLE_ID, EXAMPLES, findExample } from './examples.ts';
import { designStem, downloadText } from './exports.ts';
import { payloadFromExample, payloadFromFile } from './meshFiles.ts';
import { canWarmStart, sameParams, toRemeshParams, type DesignParams } from './params.ts';
import { ParamsForm } from './paramsForm.ts';
import type { SolveResult, WorkerResponse } from './protocol.ts';
import { saveSession } from './sessionStore.ts';
import { MAX_HISTORY, MAX_SHARED_MESH_BYTES, type DesignMesh, type DesignState } from './share.ts';
import { publishShareLink } from './shareLink.ts';
import { SolverClient } from './solverClient.ts';
import { renderStats } from './stats.ts';
import { StatusView } from './statusView.ts';
import { guessUpAxis } from './view/upAxis.ts';
import { Viewer } from './view/viewer.ts';

interface LoadedMesh {
  design: DesignMesh;
  label: string;
  fileName: string;
  info: MeshInfo;
}

interface Opening {
  job: number;
  design: DesignMesh;
  label: string;
  fileName: string;
  up: 'y' | 'z' | 'guess';
  params: DesignParams;
  history: DesignParams[];
  solve: boolean;
  note: string;
}

interface Solving {
  job: number;
  params: DesignParams;
  // The solves that reproduce this result from the loaded mesh; null once a parameter change
  // mid-solve made it depend on timing.
  chain: DesignParams[] | null;
}

interface Solved {
  params: DesignParams;
  chain: DesignParams[] | null;
  result: SolveResult;
}

export interface OpenOptions {
  solve: boolean;
  note: string; // said in the status while loading, e.g. "Opening the shared design"
}

export class App {
  private readonly solver = new SolverClient({ onMessage: (message) => this.onWorkerMessage(message) }, { cancelGraceMs: cancelGraceFromUrl() });
  private readonly viewer = new Viewer(element('viewport', HTMLElement));
  private readonly form = new ParamsForm();
  private readonly status = new StatusView();
  private readonly exampleSelect = element('example', HTMLSelectElement);
  private readonly remeshButton = element('remesh', HTMLButtonElement);
  private readonly cancelButton = element('cancel', HTMLButtonElement);
  private readonly exportObjButton = element('export-obj', HTMLButtonElement);
  private readonly exportPartsButton = element('export-parts', HTMLButtonElement);
  private readonly shareButton = element('share', HTMLButtonElement);
  private readonly shareRow = element('share-row', HTMLDivElement);
  private readonly shareField = element('share-link', HTMLInputElement);
  private readonly statsBox = element('stats', HTMLDivElement);

  private mesh: LoadedMesh | null = null;
  private opening: Opening | null = null;
  private openToken = 0;
  private solving: Solving | null = null;
  private solved: Solved | null = null;
  // What the worker's session holds: a just-loaded mesh, or exactly `solved` (warm-startable).
  private sessionPristine = false;
  private sessionHoldsSolved = false;
  private lastWrittenHash = '';
  private pendingNotice: string | null = null;

  constructor() {
    for (const example of EXAMPLES) this.exampleSelect.add(new Option(example.label, example.id));
    this.exampleSelect.add(new Option('Your mesh', 'file'));
    this.exampleSelect.options[this.exampleSelect.options.length - 1]!.hidden = true;
    this.exampleSelect.addEventListener('change', () => {
      if (this.exampleSelect.value !== 'file') void this.openExample(this.exampleSelect.value);
    });
    this.remeshButton.addEventListener('click', () => this.remesh());
    this.cancelButton.addEventListener('click', () => this.cancel());
    this.exportObjButton.addEventListener('click', () => this.exportFile('obj'));
    this.exportPartsButton.addEventListener('click', () => this.exportFile('csv'));
    this.shareButton.addEventListener('click', () => void this.share());
    this.form.onChange(() => this.parametersChanged());
    renderStats(this.statsBox, null);
    this.updateButtons();
  }

  get isSolving(): boolean {
    return this.solving !== null;
  }

  get currentHash(): string {
    return this.lastWrittenHash;
  }

  get viewerForToggles(): Viewer {
    return this.viewer;
  }

  // Shown after the load that follows, so the message is what the designer reads.
  showError(message: string): void {
    this.pendingNotice = message;
    if (!this.opening) this.status.error(message);
  }

  // ---- opening a design

  async openExample(id: string, options: OpenOptions = { solve: true, note: '' }): Promise<void> {
    const example = findExample(id) ?? findExample(DEFAULT_EXAMPLE_ID)!;
    this.form.setPanels(example.panels); // each example comes with a count that suits it
    const checked = this.form.read();
    if (!checked.ok) {
      this.status.error(checked.message);
      return;
    }
    await this.open({ kind: 'example', id: example.id }, checked.value, [], options);
  }

  async openFile(file: File): Promise<void> {
    const params = this.form.read();
    if (!params.ok) {
      this.status.error(params.message);
      return;
    }
    const bytes = new Uint8Array(await file.arrayBuffer());
    await this.open({ kind: 'file', name: file.name, bytes }, params.value, [], { solve: true, note: '' });
  }

  async openState(state: DesignState, note: string, solve = true): Promise<void> {
    this.form.write(state.params);
    await this.open(state.mesh, state.params, state.history, { solve, note });
  }

  private async open(design: DesignMesh, params: DesignParams, history: DesignParams[], options: OpenOptions): Promise<void> {
    const token = ++this.openToken;
    const example = design.kind === 'example' ? findExample(design.id) : undefined;
    const label = example ? example.label : design.kind === 'file' ? design.name : design.id;
    const fileName = example ? (example.kind === 'file' ? example.file : example.shape) : design.kind === 'file' ? design.name : 'design';
    this.status.show(`${options.note ? `${options.note}: ` : ''}loading ${label}…`);
    const payload = example ? await payloadFromExample(example) : design.kind === 'file' ? await payloadFromFile(design.name, design.bytes) : null;
    if (token !== this.openToken) return; // a later open won
    if (!payload || !payload.ok) {
      this.status.error(payload ? payload.message : 'nothing to open');
      this.syncExampleSelect();
      return;
    }
    if (this.solving) this.dropSolving();
    const job = this.solver.load(payload.value);
    this.opening = { job, design, label, fileName, up: example ? example.up : 'guess', params, history, solve: options.solve, note: options.note };
  }

  private onLoaded(info: MeshInfo, positions: Float32Array, indices: Uint32Array): void {
    const opening = this.opening;
    if (!opening) return;
    this.opening = null;
    this.mesh = { design: opening.design, label: opening.label, fileName: opening.fileName, info };
    this.solved = null;
    this.sessionPristine = true;
    this.sessionHoldsSolved = false;
    this.viewer.setSurface(positions, indices, opening.up === 'guess' ? guessUpAxis(positions) : opening.up);
    this.showMeshInfo(info);
    this.syncExampleSelect();
    renderStats(this.statsBox, null);
    void saveSession({ mesh: opening.design, params: opening.params, history: [] });
    if (opening.solve) this.startSolve([...opening.history, opening.params], false);
    else this.status.show(`${opening.label} is loaded. Remesh to make panels.`);
    if (this.pendingNotice) {
      this.status.error(this.pendingNotice);
      this.pendingNotice = null;
    }
    this.updateButtons();
  }

  private showMeshInfo(info: MeshInfo): void {
    element('mesh-title', HTMLSpanElement).textContent = this.mesh?.label ?? '';
    const loops = info.boundaryLoops === 1 ? '1 boundary loop' : `${info.boundaryLoops} boundary loops`;
    element('mesh-details', HTMLSpanElement).textContent = `${info.triangles.toLocaleString('en')} triangles · ${info.vertices.toLocaleString('en')} vertices · ${loops} · genus ${info.genus}`;
    const cleanup = element('mesh-cleanup', HTMLParagraphElement);
    cleanup.textContent = info.cleanup.length > 0 ? `Repaired on load: ${info.cleanup.join('; ')}.` : '';
    cleanup.hidden = info.cleanup.length === 0;
  }

  private syncExampleSelect(): void {
    const design = this.mesh?.design;
    this.exampleSelect.value = design?.kind === 'example' ? design.id : design ? 'file' : DEFAULT_EXAMPLE_ID;
    const fileOption = this.exampleSelect.options[this.exampleSelect.options.length - 1]!;
    fileOption.hidden = design?.kind !== 'file';
    fileOption.text = design?.kind === 'file' ? `Your mesh: ${design.name}` : 'Your mesh';
  }

  // ---- solving

  remesh(): void {
    if (!this.mesh) {
      this.status.error('open a mesh or pick an example first');
      return;
    }
    const checked = this.form.read();
    if (!checked.ok) {
      this.status.error(checked.message);
      return;
    }
    const params = checked.value;
    if (this.solving) this.dropSolving();
    const previous = this.solved;
    // Warm start (DESIGN.md 2): the session holds the finished previous result and only the
    // count, weights or iteration limits changed. Identical parameters solve afresh.
    if (previous && this.sessionHoldsSolved && canWarmStart(previous.params, params) && !sameParams(previous.params, params)) {
      const chain = previous.chain && previous.chain.length <= MAX_HISTORY ? [...previous.chain, params] : null;
      this.startSolve([params], false, chain);
    } else {
      this.startSolve([params], !this.sessionPristine);
    }
  }

  // `run` is solved in order; `chain` is what reproduces the result from the loaded mesh.
  private startSolve(run: DesignParams[], fresh: boolean, chain: DesignParams[] | null = run): void {
    const params = run[run.length - 1]!;
    const job = this.solver.solve(fresh, run.map(toRemeshParams));
    this.solving = { job, params, chain };
    this.sessionPristine = false;
    this.sessionHoldsSolved = false;
    this.viewer.setSolving(true);
    this.status.show(`Solving ${params.panels} panels…`);
    this.status.resetProgress('starting');
    this.updateButtons();
  }

  private dropSolving(): void {
    if (!this.solving) return;
    this.solver.cancel(this.solving.job);
    this.solving = null;
    this.sessionHoldsSolved = false;
    this.viewer.setSolving(false);
  }

  cancel(): void {
    if (!this.solving) return;
    this.dropSolving();
    if (this.solved) this.viewer.setClusters(this.solved.result.clusterIds);
    this.status.resetProgress('cancelled');
    this.status.show(this.solved ? 'Cancelled. The last finished design is shown.' : 'Cancelled.');
    this.updateButtons();
  }

  // A committed change during a solve goes to the worker at once and warm-starts there.
  private parametersChanged(): void {
    if (!this.solving) return;
    const checked = this.form.read();
    if (!checked.ok) {
      this.status.error(checked.message);
      return;
    }
    if (sameParams(checked.value, this.solving.params)) return;
    this.solver.update(this.solving.job, toRemeshParams(checked.value));
    this.solving = { ...this.solving, params: checked.value, chain: null };
  }

  private onSolved(result: SolveResult): void {
    const solving = this.solving;
    if (!solving || !this.mesh) return;
    this.solving = null;
    this.solved = { params: solving.params, chain: solving.chain, result };
    countOutcome('solves');
    this.sessionHoldsSolved = true;
    this.viewer.setSolving(false);
    this.viewer.setResult(result);
    renderStats(this.statsBox, result);
    this.status.finishProgress();
    const panels = typeof result.report.panels === 'number' ? result.report.panels : result.panelOffsets.length - 1;
    const invalid = result.problems.invalidPanels.length;
    const unbuilt = result.problems.unbuiltClusters.length;
    const warnings = [
      invalid > 0 ? `${invalid} invalid panel${invalid === 1 ? '' : 's'} (shown red)` : '',
      unbuilt > 0 ? `${unbuilt} cluster${unbuilt === 1 ? '' : 's'} could not become panels` : '',
    ].filter((text) => text !== '');
    const warning = warnings.length > 0 ? `${warnings.join('; ')}. ` : '';
    this.status.show(`${warning}Done: ${panels} panels`, warning ? 'info' : 'done');
    void saveSession({ mesh: this.mesh.design, params: solving.params, history: solving.chain ? solving.chain.slice(0, -1) : [] });
    this.updateButtons();
  }

  private onWorkerMessage(message: WorkerResponse): void {
    switch (message.type) {
      case 'ready':
        document.body.dataset.solverVersion = message.version;
        return;
      case 'fatal':
        this.solving = null;
        this.opening = null;
        this.viewer.setSolving(false);
        this.status.error(message.message);
        this.updateButtons();
        return;
      case 'loaded':
        this.onLoaded(message.info, message.positions, message.indices);
        return;
      case 'failed':
        this.onFailed(message.message);
        return;
      case 'progress':
        if (this.solving) this.status.showProgress(message.progress, message.elapsedSeconds);
        return;
      case 'clusters':
        if (this.solving) this.viewer.showLiveClusters(message.clusterIds);
        return;
      case 'solved':
        this.onSolved(message.result);
        return;
      case 'cancelled':
        return;
    }
  }

  // The core refused a mesh or parameters: the previous design stays loaded and usable.
  private onFailed(reason: string): void {
    if (this.opening) {
      this.opening = null;
      this.syncExampleSelect();
    }
    if (this.solving) {
      this.solving = null;
      this.viewer.setSolving(false);
      if (this.solved) this.viewer.setClusters(this.solved.result.clusterIds);
    }
    this.sessionHoldsSolved = false;
    this.sessionPristine = false;
    this.status.resetProgress();
    this.status.error(reason);
    this.updateButtons();
  }

  // ---- outputs

  private exportFile(kind: 'obj' | 'csv'): void {
    if (!this.solved || !this.mesh) return;
    const stem = designStem(this.mesh.fileName);
    if (kind === 'obj') downloadText(`${stem}-panels.obj`, this.solved.result.objText, 'model/obj');
    else downloadText(`${stem}-parts.csv`, this.solved.result.partsCsv, 'text/csv');
  }

  async share(): Promise<void> {
    if (!this.mesh) return;
    const design = this.mesh.design;
    if (design.kind === 'file' && design.bytes.length > MAX_SHARED_MESH_BYTES) {
      this.status.error(`${design.name} is ${(design.bytes.length / 1048576).toFixed(1)} MB; links carry meshes up to ${MAX_SHARED_MESH_BYTES / 1048576} MB. Share the file itself.`);
      return;
    }
    const formParams = this.form.read();
    const params = this.solved?.params ?? (formParams.ok ? formParams.value : null);
    if (!params) return;
    const chain = this.solved?.chain;
    // The history replays a warm-start chain so the link gives the identical panels.
    const state = { mesh: design, params, history: chain ? chain.slice(0, -1) : [] };
    const published = await publishShareLink(state, this.shareField, this.shareRow);
    this.lastWrittenHash = published.hash;
    const caveat = this.solved && !chain ? ' Parameters changed during that solve, so the link solves afresh and the panels may differ slightly.' : '';
    this.status.show(published.copied ? `Share link copied to the clipboard.${caveat}` : `The clipboard is not available: copy the share link from the field below.${caveat}`);
  }

  private updateButtons(): void {
    const solving = this.solving !== null;
    this.remeshButton.disabled = !this.mesh;
    this.cancelButton.disabled = !solving;
    this.exportObjButton.disabled = !this.solved;
    this.exportPartsButton.disabled = !this.solved;
    this.shareButton.disabled = !this.mesh;
    document.body.dataset.solving = String(solving);
  }
}

// ?cancelGrace=0 makes every cancel replace the worker (the path a long step takes); tests use it.
function cancelGraceFromUrl(): number | undefined {
  const value = new URLSearchParams(location.search).get('cancelGrace');
  const ms = value === null ? Number.NaN : Number(value);
  return Number.isInteger(ms) && ms >= 0 && ms <= 10_000 ? ms : undefined;
}
