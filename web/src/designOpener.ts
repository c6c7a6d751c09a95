// Opening a design and preparing its mesh again (split from app.ts, the page's controller):
// an example, a file, a link or the stored session is read on the page, sent to the worker,
// shown when loaded and solved; a panel count the mesh cannot serve, or a new subdivision or
// target edge length, prepares the mesh again from the mesh as loaded (preparation.ts), with
// the paint and panel edits carried to it as one history step.
import type { MeshInfo } from '@flatfacet/wasm';
import { fieldKey, isUniform } from './brush/densityField.ts';
import type { DesignEditor } from './designEditor.ts';
import type { DesignMachine } from './designMachine.ts';
import { showMeshInfo, type ExamplePicker } from './examplePicker.ts';
import { renderSelfCrossing, selfCrossingPoints } from './crossings.ts';
import { describeDesign, findExample } from './examples.ts';
import { checkEditsFit, countAfterEdits } from './edits/panelEdits.ts';
import type { FabricationPanel } from './fabricationPanel.ts';
import type { FabricationSettings } from './fabricationParams.ts';
import type { MeshRepair } from './meshRepair.ts';
import { payloadFromExample, payloadFromFile } from './meshFiles.ts';
import type { Outputs } from './outputs.ts';
import type { DesignParams } from './params.ts';
import type { ParamsForm } from './paramsForm.ts';
import type { PrepareControl } from './prepareControl.ts';
import type { RepairControl } from './repairControl.ts';
import { carriedParams, editFaces, preparationNeeded, refusedPreparation, withPrepare } from './preparation.ts';
import type { Carry, SolveResult } from './protocol.ts';
import { renderQuality } from './qualityViews.ts';
import { rhinoLoaded } from './rhino/rhinoOpen.ts';
import type { DesignMesh, DesignState, MeshPrepare } from './share.ts';
import { SOLVER_DEAD, type SolverClient } from './solverClient.ts';
import type { StatusView } from './statusView.ts';
import { guessUpAxis } from './view/upAxis.ts';
import type { Viewer } from './view/viewer.ts';

export interface LoadedMesh {
  design: DesignMesh;
  label: string;
  fileName: string;
  info: MeshInfo;
  read: string[]; // what the page's reader left out or applied (MeshPayload.read)
}

export interface OpenInfo {
  design: DesignMesh;
  label: string;
  fileName: string;
  up: 'y' | 'z' | 'guess';
  params: DesignParams;
  history: DesignParams[];
  solve: boolean;
  // The design's mesh prepared again (not a new mesh: the history goes on): 'carry' brings
  // the paint and edits of `params` along; 'replay' solves `history` + `params`, made for it.
  reprepare?: 'carry' | 'replay';
  // A change of the holes filled: the mesh on show before it (keptThroughRepair decides, once
  // the repaired mesh is loaded, what of the paint and edits still fits).
  repairOf?: MeshBeforeRepair;
  // A link's fabrication settings, written once its mesh is on show (a refused link leaves
  // those of the design on show).
  fabrication?: FabricationSettings;
  // MeshPayload.read, once the page has read the file (a re-preparation keeps its mesh's).
  read?: string[];
}

export interface MeshBeforeRepair {
  prepared: boolean; // not the mesh as loaded
  unfilled: number; // its triangles before the filled ones
  facesDropped: number; // cut away as not the largest part
}

export interface OpenOptions {
  solve: boolean;
  note: string; // said in the status while loading, e.g. "Opening the shared design"
  fromLink?: boolean; // keeps the link in the address bar (it describes this design)
  repairOf?: MeshBeforeRepair; // OpenInfo.repairOf
  fabrication?: FabricationSettings; // OpenInfo.fabrication
}

// What the opener uses of the controller.
export interface OpenerHost {
  machine: DesignMachine<LoadedMesh, OpenInfo, SolveResult>;
  solver: SolverClient;
  viewer: Viewer;
  form: ParamsForm;
  preparation: PrepareControl;
  repair: RepairControl;
  editor: DesignEditor;
  status: StatusView;
  outputs: Outputs;
  examples: ExamplePicker;
  fabrication: FabricationPanel;
  statsBox: HTMLDivElement;
  dropSolve(): void; // a solve under way, and a quiet restore (the session's mesh changes)
  // `notice`: said with the solve's end; `sameDesign`: the mesh on show before, of which this
  // one is the same design prepared or repaired anew (a notice of its dropped solve carries).
  startSolve(run: DesignParams[], fresh: boolean, chain: DesignParams[] | null, notice?: string | null, sameDesign?: LoadedMesh | null): void;
  save(state: DesignState): void;
  updateButtons(): void;
  openFailed(): void; // after failOpen: the design on show stays
}

export class DesignOpener {
  // A message to show once the mesh being opened has loaded (set only while opening).
  pendingNotice: string | null = null;
  // The last open sent to the worker: what "Use largest manifold part" opens again.
  private lastOpen: { design: DesignMesh; params: DesignParams; history: DesignParams[]; options: OpenOptions } | null = null;

  constructor(private readonly host: OpenerHost) {}

  async openExample(id: string, options: OpenOptions = { solve: true, note: '' }): Promise<void> {
    if (this.refusedWithoutSolver()) return;
    const example = findExample(id) ?? findExample(this.host.examples.defaultId)!;
    this.host.form.setPanels(example.panels); // each example comes with a count that suits it
    this.host.editor.forgetPaint(); // painted on the previous mesh
    this.host.preparation.forgetEdgeLength();
    const read = this.readChoices();
    if (!read) return;
    await this.open(withRepair({ kind: 'example', id: example.id, prepare: read.prepare }, read.repair), read.params, [], options);
  }

  async openFile(file: File): Promise<void> {
    if (this.refusedWithoutSolver()) return;
    this.host.editor.forgetPaint();
    this.host.preparation.forgetEdgeLength();
    const read = this.readChoices();
    if (!read) return;
    const bytes = new Uint8Array(await file.arrayBuffer());
    await this.open(withRepair({ kind: 'file', name: file.name, bytes, prepare: read.prepare }, read.repair), read.params, [], { solve: true, note: '' });
  }

  // The form's parameters and the Surface section's preparation and repair for a new mesh;
  // null (the problem said in the status) when one of them is refused.
  private readChoices(): { params: DesignParams; prepare: MeshPrepare | undefined; repair: MeshRepair | undefined } | null {
    const params = this.host.form.read();
    if (!params.ok) {
      this.host.status.error(params.message);
      return null;
    }
    const prepare = this.host.preparation.read(params.value);
    if (!prepare.ok) {
      this.host.status.error(prepare.message);
      return null;
    }
    const repair = this.host.repair.read();
    if (!repair.ok) {
      this.host.status.error(repair.message);
      return null;
    }
    return { params: params.value, prepare: prepare.value, repair: repair.value };
  }

  // New holes to fill: the design's mesh opened again with them (its largest-part choice kept),
  // not while another open is under way (the Surface inputs are read-only then, and show the
  // opened mesh's own values when it ends). What the paint and edits name is kept where the
  // repaired mesh keeps it, decided once it is loaded (keptThroughRepair), so a refused open
  // leaves the design as it was.
  async repairChanged(): Promise<void> {
    if (this.refusedWithoutSolver()) return;
    const mesh = this.host.machine.mesh;
    if (!mesh || !this.host.machine.canRemesh) return;
    const repair = this.host.repair.read(mesh.design.repair?.largestPart ?? false);
    if (!repair.ok) {
      this.host.status.error(repair.message);
      return;
    }
    const params = this.host.form.read();
    if (!params.ok) {
      this.host.status.error(params.message);
      return;
    }
    const repairOf = { prepared: mesh.info.prepared.length > 0, unfilled: mesh.info.triangles - mesh.info.repair.holeFaces, facesDropped: mesh.info.repair.facesDropped };
    await this.open(withRepair(mesh.design, repair.value), params.value, [], { solve: true, note: '', repairOf });
  }

  // "Use largest manifold part": the refused open again, keeping that part.
  async openLargestPart(): Promise<void> {
    if (this.refusedWithoutSolver()) return;
    const last = this.lastOpen;
    if (!last) return;
    const repair = { fillHoles: last.design.repair?.fillHoles ?? 0, largestPart: true };
    await this.open(withRepair(last.design, repair), last.params, last.history, { ...last.options, note: 'Keeping the largest manifold part' });
  }

  // New subdivision levels or edge length: the design's mesh prepared again with them.
  preparationChanged(): void {
    if (this.refusedWithoutSolver()) return;
    const params = this.host.form.read();
    if (!params.ok) {
      this.host.status.error(params.message);
      return;
    }
    if (this.host.machine.canRemesh) this.prepareIfNeeded(params.value);
  }

  // A panel count the mesh on show cannot serve, or a new subdivision or edge length: the
  // mesh is prepared again (preparation.ts) and solved, and true is returned.
  prepareIfNeeded(params: DesignParams): boolean {
    const mesh = this.host.machine.mesh;
    if (!mesh) return false;
    const choice = this.host.preparation.choice();
    if (!choice.ok) {
      this.host.status.error(choice.message);
      return true;
    }
    const needed = preparationNeeded(mesh.design.prepare, mesh.info.triangles, params.panels, choice.value);
    if (!needed) return false;
    const refused = refusedPreparation(needed, mesh.info.triangles);
    if (refused) this.host.status.error(refused);
    else this.prepareAgain(needed, params, [], 'carry');
    return true;
  }

  // The worker prepares the design's mesh again from the mesh as loaded; answered like a load
  // (onLoaded), with the paint and edited triangles of `params` carried when `how` is 'carry'.
  // No preparation (undo to a design saved before preparations were recorded): the mesh as
  // loaded itself, which its edits and paint name. False when nothing was sent: no mesh or an
  // open under way (silent), paint or edits to carry that do not fit (said), or a solver that
  // lost the mesh (said).
  prepareAgain(prepare: MeshPrepare, params: DesignParams, history: DesignParams[], how: 'carry' | 'replay'): boolean;
  prepareAgain(prepare: MeshPrepare | undefined, params: DesignParams, history: DesignParams[], how: 'replay'): boolean; // nothing to carry to
  prepareAgain(prepare: MeshPrepare | undefined, params: DesignParams, history: DesignParams[], how: 'carry' | 'replay'): boolean {
    const mesh = this.host.machine.mesh;
    if (!mesh || !this.host.machine.canRemesh) return false;
    const carry: Carry = how === 'carry' ? { paint: this.host.editor.field(params.paint), faces: editFaces(params.edits) } : { paint: null, faces: new Int32Array(0) };
    // What is carried must fit the mesh on show: the worker carries it after it has taken the
    // prepared mesh, too late to refuse and keep this one. ('replay' carries nothing: its
    // parameters name the mesh it prepares.)
    const misfit = how === 'carry' ? carryMisfit(carry, params, mesh.info) : null;
    if (misfit) {
      this.host.status.error(`${misfit}; the mesh was not prepared again.`);
      return false;
    }
    const design = withPrepare(mesh.design, prepare);
    const token = this.host.machine.beginOpen({ design, label: mesh.label, fileName: mesh.fileName, up: 'guess', params, history, solve: true, reprepare: how, read: mesh.read });
    this.host.outputs.forgetLink();
    this.host.dropSolve();
    const job = this.host.solver.prepare(prepare ?? null, carry);
    if (job === null) {
      this.host.machine.abandonOpen(token);
      this.failOpen('the solver has lost the mesh: open it again', false);
      return false;
    }
    this.host.machine.openSent(token, job);
    this.host.status.show(prepare ? `Preparing the mesh for ${prepare.panels.toLocaleString('en')} panels…` : 'Opening the mesh as loaded…');
    this.host.updateButtons();
    return true;
  }

  async openState(state: DesignState, note: string, fromLink: boolean): Promise<void> {
    if (this.refusedWithoutSolver()) return;
    this.host.editor.adopt(state);
    this.host.form.write(state.params);
    this.host.preparation.show(state.mesh);
    this.host.repair.show(state.mesh);
    // A link's settings wait for its mesh (a refused link leaves the design's own); the stored
    // session's are the designer's own, kept even when its mesh cannot be opened again.
    if (state.fabrication && !fromLink) this.host.fabrication.write(state.fabrication);
    const fabrication = state.fabrication && fromLink ? { fabrication: state.fabrication } : {};
    await this.open(state.mesh, state.params, state.history, { solve: true, note, fromLink, ...fabrication });
  }

  private async open(design: DesignMesh, params: DesignParams, history: DesignParams[], options: OpenOptions): Promise<void> {
    const { example, label, fileName, up } = describeDesign(design);
    const info: OpenInfo = { design, label, fileName, up, params, history, solve: options.solve, ...(options.repairOf ? { repairOf: options.repairOf } : {}), ...(options.fabrication ? { fabrication: options.fabrication } : {}) };
    const token = this.host.machine.beginOpen(info);
    this.lastOpen = { design, params, history, options };
    this.host.repair.hideOffer();
    if (!options.fromLink) this.host.outputs.forgetLink();
    this.host.updateButtons();
    this.host.status.show(`${options.note ? `${options.note}: ` : ''}loading ${label}…`);
    const payload = example ? await payloadFromExample(example) : design.kind === 'file' ? await payloadFromFile(design.name, design.bytes) : null;
    if (!this.host.machine.isCurrentOpen(token)) return; // a later open won
    if (payload?.ok && design.prepare) payload.value.prepare = { ...design.prepare };
    if (payload?.ok && design.repair) payload.value.repair = { ...design.repair };
    if (payload?.ok && payload.value.read) info.read = payload.value.read;
    if (!payload || !payload.ok) {
      this.host.machine.abandonOpen(token);
      this.failOpen(payload ? payload.message : 'nothing to open');
      return;
    }
    // The session's mesh is about to change: a solve under way is of no use any more.
    this.host.dropSolve();
    this.host.machine.openSent(token, this.host.solver.load(payload.value));
    this.host.updateButtons();
  }

  // An open failed and none other goes on: the design on show stays, and the Surface section
  // shows its preparation and repair again (a refused value was never applied). `restoreForm`:
  // the open had written its own parameters into the form (a link, a file, an example; not a
  // re-preparation, whose form holds what the user typed), so the form shows the design's too,
  // or, when another open goes on, that open's (which solves them once its mesh is shown).
  failOpen(reason: string, restoreForm = true): void {
    const notice = this.pendingNotice;
    this.pendingNotice = null;
    const mesh = this.host.machine.mesh;
    const opening = this.host.machine.opening;
    if (mesh && !opening) {
      if (restoreForm) this.host.editor.showCurrent();
      this.host.preparation.show(mesh.design);
      this.host.repair.show(mesh.design);
    } else if (opening && restoreForm && !opening.info.reprepare) {
      this.host.form.write(opening.info.params);
    }
    this.syncExampleSelect();
    this.host.status.resetProgress();
    this.host.status.error(notice ? `${notice} ${reason}` : reason);
    this.host.openFailed();
    this.host.updateButtons();
  }

  onLoaded(job: number, info: MeshInfo, positions: Float32Array, indices: Uint32Array, carried?: Carry): void {
    // Prepared again: what the load said beyond the counts (a Rhino file's surfaces) stays.
    const previous = this.host.machine.mesh;
    const before = previous?.info;
    const loaded = this.host.machine.loaded(job, (opening) => ({ design: opening.design, label: opening.label, fileName: opening.fileName, info: opening.reprepare && before ? { ...before, ...info } : info, read: opening.read ?? [] }));
    if (!loaded) return;
    const opening = loaded.info;
    this.host.viewer.setSurface(positions, indices, opening.up === 'guess' ? guessUpAxis(positions) : opening.up, opening.reprepare !== undefined);
    if (opening.reprepare) {
      // An Undo or Redo ('replay') brings its own edits back: a notice of edits dropped before
      // is not carried to it.
      this.preparedAgain(opening, loaded.newest, carried, opening.reprepare === 'carry' ? previous : null);
      return;
    }
    const { params, notice } = opening.repairOf ? keptThroughRepair(opening.params, opening.repairOf, info) : { params: opening.params, notice: null };
    if (opening.repairOf && loaded.newest && params !== opening.params) {
      this.host.form.setPaint(params.paint);
      this.host.form.setEdits(params.edits);
      this.host.form.showCount(params.panels, countAfterEdits(params.panels, params.edits)); // "Panels" counted the dropped splits and merges
    }
    this.host.editor.meshLoaded(params, opening.design.prepare);
    this.host.preparation.show(opening.design); // what this mesh was prepared and repaired with
    this.host.repair.show(opening.design);
    showMeshInfo(loaded.mesh.label, loaded.mesh.info, loaded.mesh.read);
    rhinoLoaded(loaded.mesh.fileName, loaded.mesh.info);
    renderQuality(this.host.statsBox, null);
    this.host.viewer.setSelfCrossing(selfCrossingPoints(loaded.mesh.info));
    renderSelfCrossing(loaded.mesh.info);
    this.host.fabrication.panelsChanged(false);
    if (loaded.newest && opening.fabrication) this.host.fabrication.write(opening.fabrication);
    this.host.updateButtons();
    // Overtaken by a later open: shown, since the worker holds it now, but that open goes on.
    if (!loaded.newest) return;
    this.syncExampleSelect();
    const chain = [...opening.history, params];
    // A design that does not fit its mesh is neither saved over the stored one nor solved.
    const misfit = designMisfit(chain, info, (key) => this.host.editor.field(key));
    if (!misfit) this.host.save({ mesh: opening.design, params, history: [], fabrication: this.host.fabrication.current });
    if (opening.solve && misfit) {
      this.host.status.error(`${misfit}; not solved.`);
    } else if (opening.solve) {
      this.host.startSolve(chain, false, chain, notice, opening.repairOf ? previous : null);
    } else {
      this.host.status.show(`${opening.label} is loaded. Remesh to make panels.`);
    }
    if (this.pendingNotice) {
      this.host.status.error(this.pendingNotice);
      this.pendingNotice = null;
    }
    this.host.updateButtons();
  }

  // The design's mesh, prepared again, is on show: its note, the carried paint and edits as one
  // history step, and the solve (from the prepared mesh: no warm start across meshes).
  private preparedAgain(opening: OpenInfo, newest: boolean, carried: Carry | undefined, previous: LoadedMesh | null): void {
    const mesh = this.host.machine.mesh!;
    showMeshInfo(mesh.label, mesh.info, mesh.read);
    this.host.preparation.show(opening.design);
    this.host.repair.show(opening.design);
    renderQuality(this.host.statsBox, null);
    this.host.viewer.setSelfCrossing(selfCrossingPoints(mesh.info));
    renderSelfCrossing(mesh.info);
    this.host.fabrication.panelsChanged(false);
    let chain = [...opening.history, opening.params];
    let notice: string | null = null;
    if (opening.reprepare === 'carry' && carried) {
      const paint = carried.paint && !isUniform(carried.paint) ? carried.paint : null;
      const { params, dropped } = carriedParams(opening.params, paint ? fieldKey(paint) : '', carried.faces);
      this.host.editor.reprepared(opening.params, params, opening.design.prepare!, paint); // 'carry' comes with one (prepareAgain)
      if (dropped > 0) notice = `${dropped === 1 ? '1 merge edit was' : `${dropped} merge edits were`} dropped: on the prepared mesh both of its panels' triangles are one.`;
      chain = [params];
    } else {
      this.host.editor.surfaceChanged();
    }
    if (newest) this.host.startSolve(chain, false, chain, notice, previous);
    this.host.updateButtons();
  }

  // A worker that could not start answers nothing: no open is sent to it, the design on show
  // stays (exportable, shareable), and the page says what to do.
  private refusedWithoutSolver(): boolean {
    if (!this.host.machine.solverDead) return false;
    this.host.status.error(SOLVER_DEAD);
    this.syncExampleSelect();
    const mesh = this.host.machine.mesh;
    if (mesh) {
      this.host.preparation.show(mesh.design); // a value committed as the solver died
      this.host.repair.show(mesh.design);
    }
    return true;
  }

  syncExampleSelect(): void {
    this.host.examples.sync(this.host.machine.mesh?.design);
  }

}

// Why the paint or the edits to carry do not fit the mesh they are carried from (null: they do).
function carryMisfit(carry: Carry, params: DesignParams, info: MeshInfo): string | null {
  if (carry.paint && carry.paint.length !== info.vertices) return `The painted density has ${carry.paint.length} values, but the mesh has ${info.vertices} vertices (painted on another mesh? clear the paint)`;
  const edits = checkEditsFit(params.edits, info.triangles);
  return edits.ok ? null : edits.message;
}

// What of a design's paint and panel edits still fits after a change of the holes filled, from
// the mesh on show `before` to the one loaded now (`after`), and what it says of the rest (null:
// all kept). Filling appends triangles hole by hole and adds no vertex, so between two meshes
// as loaded, cut alike, the paint (per vertex) and the edits of unfilled triangles name what
// they named; filled triangles are numbered anew, so edits naming one go, all of them (an
// unlock dropped alone would leave its lock). A prepared mesh on either side (preparation
// follows the triangle count, which filling changes) or another cut renumbers everything.
function keptThroughRepair(params: DesignParams, before: MeshBeforeRepair, after: MeshInfo): { params: DesignParams; notice: string | null } {
  const renumbered = before.prepared || after.prepared.length > 0 || before.facesDropped !== after.repair.facesDropped;
  const unfilled = Math.min(before.unfilled, after.triangles - after.repair.holeFaces);
  const onFilled = params.edits.some((edit) => edit.face >= unfilled || (edit.op === 'merge' && edit.with >= unfilled));
  const paint = renumbered ? '' : params.paint;
  const edits = renumbered || onFilled ? [] : params.edits;
  const droppedEdits = params.edits.length - edits.length;
  const parts = [paint !== params.paint ? 'the painted density' : '', droppedEdits === 1 ? '1 panel edit' : droppedEdits > 1 ? `${droppedEdits} panel edits` : ''].filter((p) => p !== '');
  if (parts.length === 0) return { params, notice: null };
  const plural = parts.length > 1 || droppedEdits > 1;
  const text = parts.join(' and ');
  const why = renumbered ? `${plural ? 'they' : 'it'} named the mesh before the holes changed` : `${plural ? 'one' : 'it'} named a filled triangle, which filling numbers anew`;
  return { params: { ...params, paint, edits }, notice: `${text[0]!.toUpperCase()}${text.slice(1)} ${plural ? 'were' : 'was'} dropped: ${why}.` };
}

// Why the panel edits (which name triangles) or the density paint (a level per vertex) of a
// design opened from a link do not fit the mesh it opened (null: they do).
function designMisfit(chain: DesignParams[], info: MeshInfo, field: (key: string) => Int8Array | null): string | null {
  for (const params of chain) {
    const edits = checkEditsFit(params.edits, info.triangles);
    if (!edits.ok) return edits.message;
    const paint = params.paint === '' ? null : field(params.paint);
    if (paint && paint.length !== info.vertices) return `The density paint has ${paint.length.toLocaleString('en-US')} values, but the mesh has ${info.vertices.toLocaleString('en-US')} vertices`;
  }
  return null;
}

// The design's mesh with this repair (none: the field left out, as links before it had).
function withRepair(design: DesignMesh, repair: MeshRepair | undefined): DesignMesh {
  const { repair: _old, ...rest } = design;
  return repair ? { ...rest, repair } : rest;
}

