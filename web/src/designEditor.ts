// Undo and redo of the design's edits (parameter and expression changes, paint strokes; panel
// edits later, as one more kind of step), the painted fields they name, and the wiring of the
// density brush to the solver. Each history step records the design's parameters (the paint by
// its field's key) and, once solved, the warm-start chain that reproduces its panels: undo and
// redo replay that chain from the loaded mesh, so they give back the very same panels.
import { countOutcome, element } from './dom.ts';
import { isUniform, fieldKey } from './brush/densityField.ts';
import { DensityPanel } from './brush/densityPanel.ts';
import { EditPanel } from './edits/editPanel.ts';
import { compactChain, type PanelEdit } from './edits/panelEdits.ts';
import { History } from './history.ts';
import { paintKeys, type PaintFields } from './paintFields.ts';
import { sameParams, toRemeshParams, type DesignParams } from './params.ts';
import type { PanelSelection } from './panelSelection.ts';
import type { ParamsForm } from './paramsForm.ts';
import type { SolveResult, SolveStep } from './protocol.ts';
import { samePrepare } from './preparation.ts';
import type { DesignState, MeshPrepare } from './share.ts';
import type { Viewer } from './view/viewer.ts';

export type StepKind = 'open' | 'params' | 'paint' | 'edit' | 'prepare';

export interface DesignStep {
  kind: StepKind;
  params: DesignParams;
  // The chain of solves that reproduces this step's panels from the loaded mesh, once solved
  // (null: not solved, or solved in a way no chain reproduces).
  chain: DesignParams[] | null;
  // The panels it has once solved ("Panels" shows it: after edits it is not params.panels,
  // the count the solve targeted); null until then.
  count: number | null;
  // The preparation of the mesh the parameters belong to (their paint and edits name its
  // vertices and triangles): undo across a re-preparation prepares the mesh back.
  prepare: MeshPrepare | undefined;
}

export interface EditorHost {
  form: ParamsForm;
  viewer: Viewer;
  selection: PanelSelection; // the page's one selected panel
  requestExpression(expression: string): void; // its values per vertex, for the density map
  error(message: string): void;
  note(message: string): void; // said in the status line
  canEdit(): boolean; // a mesh loaded, none opening
  solvedChain(): DesignParams[] | null; // the chain of the result on show, if reproducible
  solving(): boolean;
  result(): SolveResult | null; // the panels on show
  remesh(): void; // what Remesh does with the form's parameters
  replay(chain: DesignParams[]): void; // solve `chain` afresh from the loaded mesh
  prepared(): MeshPrepare | undefined; // the preparation of the mesh on show
  // Prepare the mesh as `prepare` says (from the mesh as loaded), then solve `chain` on it;
  // false when it could not even be asked (the solver lost the mesh: the status says so).
  reprepare(prepare: MeshPrepare | undefined, chain: DesignParams[]): boolean;
}

const HISTORY_LIMIT = 100;

// An Undo or Redo: the step it left and the one it reached.
interface HistoryMove {
  move: 'Undo' | 'Redo';
  left: DesignStep;
  reached: DesignStep;
}

export class DesignEditor {
  private readonly history = new History<DesignStep>(HISTORY_LIMIT);
  private readonly fields = new Map<string, Int8Array>();
  // The fields of a design being opened from a link or the stored session: kept until the next
  // such open, since its solve chain needs them before any history step names them.
  private pinned = new Set<string>();
  private readonly undoButton = element('undo', HTMLButtonElement);
  private readonly redoButton = element('redo', HTMLButtonElement);
  private readonly density: DensityPanel;
  private readonly panelEdits: EditPanel;
  // Undo or Redo moved from `left` to `reached`, a step on another preparation of the mesh,
  // which is being prepared back: until it is on show, the form and history are the step's but
  // the mesh is not.
  private repreparing: HistoryMove | null = null;

  constructor(private readonly host: EditorHost) {
    this.density = new DensityPanel({
      viewer: host.viewer,
      field: () => this.fields.get(host.form.paint) ?? null,
      expression: () => host.form.densityExpression,
      requestExpression: (expression) => host.requestExpression(expression),
      canPaint: () => host.canEdit() && host.viewer.surface !== null,
      strokeEnded: (field) => this.paint(isUniform(field) ? null : field),
      clear: () => this.paint(null),
    });
    this.panelEdits = new EditPanel({
      viewer: host.viewer,
      selection: host.selection,
      result: () => (host.solving() ? null : host.result()),
      edits: () => host.form.edits,
      canEdit: () => host.canEdit() && !host.solving(),
      painting: () => this.density.painting,
      apply: (edit) => this.edit(edit),
    });
    host.form.onChange(() => this.formChanged());
    this.undoButton.addEventListener('click', () => this.undo());
    this.redoButton.addEventListener('click', () => this.redo());
    window.addEventListener('keydown', (event) => this.key(event));
    this.updateButtons();
  }

  // ---- what the controller tells

  // The form and the density view show the current step (after Undo or Redo, or an open that
  // failed after writing its own parameters, which name a mesh that never came).
  showCurrent(): void {
    const current = this.history.current;
    if (!current) return;
    this.host.form.write(current.params, current.count ?? undefined);
    this.density.show();
    this.updateButtons();
  }

  // A new mesh is about to be opened from the form (an example, a file): its paint is gone.
  forgetPaint(): void {
    this.host.form.setPaint('');
    this.host.form.setEdits([]); // they name triangles of the previous mesh
    this.pinned = new Set();
  }

  // The core's values of a density expression (DensityPanel.show asked for them).
  expressionAnswered(expression: string, values: Float64Array): void {
    this.density.expressionAnswered(expression, values);
  }

  // A new worker: questions to the old one go unanswered.
  workerReplaced(): void {
    this.density.surfaceChanged();
  }

  // A design from a link or the stored session: its fields, before its parameters are used.
  adopt(state: DesignState): void {
    this.pinned = new Set(state.paint?.keys() ?? []);
    for (const [key, field] of state.paint ?? []) this.fields.set(key, field);
  }

  // The mesh of the design is shown: history starts over from its parameters.
  meshLoaded(params: DesignParams, prepare: MeshPrepare | undefined): void {
    this.history.reset({ kind: 'open', params, chain: null, count: null, prepare });
    this.surfaceChanged();
  }

  // The panel of a mesh triangle selected for the panel edits (EditPanel.selectFace).
  selectPanelFace(face: number): boolean {
    return this.panelEdits.selectFace(face);
  }

  // The mesh was prepared again (undo or redo across a re-preparation): the history stays.
  surfaceChanged(): void {
    const wasRepreparing = this.repreparing !== null;
    this.repreparing = null;
    this.density.surfaceChanged();
    this.panelEdits.surfaceChanged();
    this.updateButtons();
    // A change committed while the mesh was prepared back, unless another open has written the
    // form since (it starts its own history).
    if (wasRepreparing && this.host.canEdit()) this.formChanged();
  }

  // The mesh was prepared again for `after` (preparation.ts), with `before`'s paint and edits
  // carried to it: one history step (it takes the place of an unsolved parameter step that
  // asked for it, e.g. the typed panel count), whose undo prepares the mesh back.
  reprepared(before: DesignParams, after: DesignParams, prepare: MeshPrepare, paint: Int8Array | null): void {
    if (paint) this.fields.set(after.paint, paint);
    this.host.form.write(after);
    const step: DesignStep = { kind: 'prepare', params: after, chain: null, count: null, prepare };
    const current = this.history.current;
    if (current && current.kind === 'params' && current.chain === null && sameParams(current.params, before)) this.history.replaceCurrent(step);
    else this.history.push(step);
    this.prune();
    this.surfaceChanged();
  }

  // A painted field by its key (null: none, or not known).
  field(key: string): Int8Array | null {
    return key === '' ? null : (this.fields.get(key) ?? null);
  }

  // A solve finished with `count` panels: its chain reproduces the current step (or a step of
  // its own when the parameters were not recorded yet, e.g. Enter before the field's change
  // event). "Panels" shows the count when the form shows this design.
  solved(params: DesignParams, chain: DesignParams[] | null, count: number): void {
    const current = this.history.current;
    const prepare = this.host.prepared();
    if (current && sameParams(current.params, params)) this.history.replaceCurrent({ ...current, chain, count });
    else if (!this.history.all.some((step) => sameParams(step.params, params) && samePrepare(step.prepare, prepare))) this.history.push({ kind: 'params', params, chain, count, prepare });
    const read = this.host.form.read();
    if (read.ok && sameParams(read.value, params)) this.host.form.showCount(params.panels, count);
    this.prune();
    this.updateButtons();
  }

  // A solve failed (the core refused it; the previous panels stay): a panel edit that made it
  // (merge with a locked panel, say) is taken back, so the design's edit list stays one the
  // core accepts.
  solveFailed(): void {
    const current = this.history.current;
    if (!current || current.kind !== 'edit' || current.chain !== null) return;
    const previous = this.history.discardCurrent();
    if (previous) this.host.form.write(previous.params, previous.count ?? undefined);
    this.updateButtons();
  }

  // The worker's request for one solve of a chain.
  solveStep(params: DesignParams): SolveStep {
    return { params: toRemeshParams(params), paint: params.paint === '' ? null : (this.fields.get(params.paint) ?? null) };
  }

  // The state to save or share, with the fields its parameters name.
  withPaint(state: DesignState): DesignState {
    const keys = paintKeys(state.params, state.history);
    if (keys.length === 0) return state;
    const paint: PaintFields = new Map(keys.map((key) => [key, this.fields.get(key)!] as const));
    return { ...state, paint };
  }

  updateButtons(): void {
    const can = this.host.canEdit();
    this.undoButton.disabled = !can || !this.history.canUndo;
    this.redoButton.disabled = !can || !this.history.canRedo;
    this.density.updateButtons(this.host.form.paint !== '');
    this.panelEdits.show();
    document.body.dataset.historyIndex = String(this.history.index);
    document.body.dataset.historySize = String(this.history.size);
  }

  // ---- edits

  private paint(field: Int8Array | null): void {
    if (!this.host.canEdit()) return;
    const key = field ? fieldKey(field) : '';
    if (field) this.fields.set(key, field);
    this.host.form.setPaint(key);
    this.density.show();
    const read = this.host.form.read();
    if (!read.ok) {
      this.host.error(read.message);
      return;
    }
    const current = this.history.current;
    if (current && sameParams(current.params, read.value)) return; // the stroke changed nothing
    this.history.push({ kind: 'paint', params: read.value, chain: null, count: null, prepare: this.host.prepared() });
    countOutcome('strokes');
    this.prune();
    this.updateButtons();
    this.host.remesh(); // warm-starts from the result on show (designMachine.planRemesh)
  }

  // One panel edit (edits/editPanel.ts): one history step, solved at once. The core applies
  // a longer edit list to the design on show in place (a warm start with the same parameters).
  private edit(edit: PanelEdit): void {
    if (!this.host.canEdit() || this.host.solving()) return;
    const current = this.history.current;
    this.host.form.setEdits([...this.host.form.edits, edit]);
    const read = this.host.form.read();
    if (!read.ok) {
      if (current) this.host.form.setEdits(current.params.edits);
      this.host.error(read.message);
      return;
    }
    this.history.push({ kind: 'edit', params: read.value, chain: null, count: null, prepare: this.host.prepared() });
    countOutcome('edits');
    this.prune();
    this.updateButtons();
    this.host.remesh();
  }

  private formChanged(): void {
    const read = this.host.form.read();
    const current = this.history.current;
    this.density.show(); // the expression may have changed
    // Not while a mesh is opening (an Undo or Redo preparing it back, a link, a file): the step
    // would be tagged with the mesh on show while the form may hold the opening design's
    // parameters. After an Undo or Redo, surfaceChanged records it once the mesh is on show;
    // an open starts its own history, and Remesh reads the form either way.
    if (this.repreparing || !this.host.canEdit()) return;
    // A value refused is said when it is committed (its input is marked), not only at Remesh;
    // during a solve App.parametersChanged says it.
    if (!read.ok && !this.host.solving()) this.host.error(read.message);
    if (!read.ok || !current || sameParams(current.params, read.value)) return;
    this.history.push({ kind: 'params', params: read.value, chain: null, count: null, prepare: this.host.prepared() });
    this.prune();
    this.updateButtons();
  }

  undo(): void {
    if (!this.host.canEdit() || this.density.painting) return;
    const left = this.history.current;
    const step = this.history.undo();
    if (step && left) this.restore(step, { move: 'Undo', left, reached: step });
  }

  redo(): void {
    if (!this.host.canEdit() || this.density.painting) return;
    const left = this.history.current;
    const step = this.history.redo();
    if (step && left) this.restore(step, { move: 'Redo', left, reached: step });
  }

  // The preparation an Undo or Redo asked for failed, or its worker crashed: the mesh on show
  // is still the step's it left, so the history and the form go back to that step (else the
  // next Remesh would solve the other step's edits and paint on this mesh's triangles). Not
  // the form when `writeForm` is false: another design opening now has written it. Returns
  // which move was taken back, or null when none was under way.
  repreparationLost(writeForm: boolean): 'Undo' | 'Redo' | null {
    const lost = this.repreparing;
    if (!lost) return null;
    this.repreparing = null;
    // Nothing records a step while the mesh is opening (formChanged and the rest need
    // canEdit), so the history is where the move left it; checked all the same.
    if (this.history.current === lost.reached) {
      if (lost.move === 'Undo') this.history.redo();
      else this.history.undo();
    }
    if (writeForm && this.history.current === lost.left) this.showCurrent();
    else this.updateButtons();
    return lost.move;
  }

  // The step's parameters and paint back in the form and the view, and its panels replayed
  // when its chain is known. A step never solved (parameters typed, no Remesh) only goes back
  // in the form, as typing it would: the panels on show stay until Remesh.
  private restore(step: DesignStep, move: HistoryMove): void {
    this.showCurrent(); // `step`, which undo or redo made current
    // A step on another preparation of the mesh: the mesh is prepared back, then solved.
    if (!samePrepare(step.prepare, this.host.prepared())) {
      this.repreparing = move;
      if (!this.host.reprepare(step.prepare, step.chain ?? [step.params])) this.repreparationLost(true);
      return;
    }
    const shown = this.host.solvedChain();
    const same = step.chain !== null && shown !== null && shown.length === step.chain.length && shown.every((p, i) => sameParams(p, step.chain![i]!));
    if (same && !this.host.solving()) return;
    // Undo / redo of panel edits only: the core edits the design on show in place (it replays
    // the edit list from the design before the first edit), the chain the same as replayed.
    if (step.chain && shown && !this.host.solving() && sameChain(compactChain([...shown, step.params]), step.chain)) this.host.remesh();
    else if (step.chain) this.host.replay(step.chain);
    // Only the form moved: say so, or the move looks like it did nothing.
    else this.host.note(`${move.move}: the form is back to a step that was never solved; Remesh to solve it. The panels on show stay as they are.`);
  }

  // A cancelled solve left no panels on show (its mesh was prepared for it) and its step was
  // never solved: back to the step before it, as Undo, when that one was solved. False when
  // there is none such.
  backToSolved(): boolean {
    const current = this.history.current;
    const before = this.history.all[this.history.index - 1];
    if (!current || current.chain !== null || !before?.chain) return false;
    this.undo();
    return this.repreparing !== null || this.host.solving();
  }

  private key(event: KeyboardEvent): void {
    if (!(event.ctrlKey || event.metaKey) || event.altKey) return;
    const key = event.key.toLowerCase();
    const redo = (key === 'z' && event.shiftKey) || (key === 'y' && !event.shiftKey);
    const undo = key === 'z' && !event.shiftKey;
    if (!undo && !redo) return;
    if (isTyping(event.target)) return; // the field's own undo
    event.preventDefault();
    if (undo) this.undo();
    else this.redo();
  }

  // Fields no step names any more go (a long session of strokes stays bounded).
  private prune(): void {
    const keep = new Set<string>([this.host.form.paint, ...this.pinned]);
    for (const p of this.host.solvedChain() ?? []) keep.add(p.paint);
    for (const step of this.history.all) {
      for (const key of paintKeys(step.params, step.chain ?? [])) keep.add(key);
    }
    for (const key of [...this.fields.keys()]) if (!keep.has(key)) this.fields.delete(key);
  }
}

function sameChain(a: readonly DesignParams[], b: readonly DesignParams[]): boolean {
  return a.length === b.length && a.every((p, i) => sameParams(p, b[i]!));
}

function isTyping(target: EventTarget | null): boolean {
  if (target instanceof HTMLTextAreaElement || target instanceof HTMLSelectElement) return true;
  if (target instanceof HTMLElement && target.isContentEditable) return true;
  return target instanceof HTMLInputElement && !['checkbox', 'radio', 'range', 'button', 'submit', 'reset', 'file', 'color'].includes(target.type);
}
