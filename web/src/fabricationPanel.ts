// The Fabrication section: its settings, the worker's fabrication outputs for the panels on
// show, their downloads, numbers, and the thick-panel view. The controller (app.ts) says when
// the panels change and forwards the worker's answers; this asks the worker for outputs.
import { countOutcome, element } from './dom.ts';
import { DEFAULT_FABRICATION, toFabricationParams, validateFabrication, type FabricationSettings } from './fabricationParams.ts';
import { PanelThicknessControl } from './panelThickness.ts';
import { FabricationForm } from './fabricationForm.ts';
import { renderFabricationStats } from './fabricationStats.ts';
import { downloadText } from './exports.ts';
import type { PanelSelection } from './panelSelection.ts';
import type { FabricationResult, SolveResult } from './protocol.ts';
import { SOLVER_DEAD, type SolverClient } from './solverClient.ts';
import type { Viewer } from './view/viewer.ts';

export interface FabricationHost {
  solver: SolverClient;
  viewer: Viewer;
  selection: PanelSelection; // the page's one selected panel
  panels(): SolveResult | null; // the panels on show
  panelsJob(): number | null; // the solve that gave the last result (the worker fabricates its panels)
  // Whether the worker keeps the panels on show ('kept'), will have them or new ones once what
  // is under way ends ('pending': a restore, a solve, a mesh loading; App.restorePanels), or
  // will not ('lost': a request is refused, saying to Remesh), or no worker answers at all
  // ('dead': it could not start).
  workerPanels(): 'kept' | 'pending' | 'lost' | 'dead';
  stem(): string; // file name stem of the design ("saddle")
  error(message: string): void;
  settingsChanged(): void; // save the session, forget a link in the address bar
}

export class FabricationPanel {
  private readonly form = new FabricationForm();
  private readonly statsBox = element('fab-stats', HTMLDivElement);
  private readonly legend = element('spread-legend', HTMLDivElement);
  private readonly legendText = element('spread-legend-text', HTMLSpanElement);
  private readonly foldedLegend = element('folded-legend', HTMLDivElement);
  private readonly foldedLegendText = element('folded-legend-text', HTMLSpanElement);
  private readonly buttons = {
    csv: element('export-parts', HTMLButtonElement),
    json: element('export-parts-json', HTMLButtonElement),
    svg: element('export-sheets', HTMLButtonElement),
    dxf: element('export-sheets-dxf', HTMLButtonElement),
    obj: element('export-solid', HTMLButtonElement),
  };
  private settings: FabricationSettings = { ...DEFAULT_FABRICATION };
  private hasPanels = false;
  private job: number | null = null; // the request whose answer is awaited
  private deferred = false; // a request waits for the panels to be restored
  private result: FabricationResult | null = null;
  private readonly panelThickness: PanelThicknessControl;

  constructor(private readonly host: FabricationHost) {
    this.panelThickness = new PanelThicknessControl(host.selection, () => host.panels(), (label, value) => this.setPanelThickness(label, value));
    this.form.write(this.settings);
    this.panelThickness.setValues(this.settings.panelThickness, this.settings.units);
    this.form.onChange(() => this.formChanged());
    this.buttons.csv.addEventListener('click', () => this.download('csv'));
    this.buttons.json.addEventListener('click', () => this.download('json'));
    this.buttons.svg.addEventListener('click', () => this.download('svg'));
    this.buttons.dxf.addEventListener('click', () => this.download('dxf'));
    this.buttons.obj.addEventListener('click', () => this.download('obj'));
    this.update();
  }

  get current(): FabricationSettings {
    return { ...this.settings };
  }

  // From a link or the stored session.
  write(settings: FabricationSettings): void {
    this.settings = { ...settings };
    this.form.write(this.settings);
    this.panelThickness.setValues(this.settings.panelThickness, this.settings.units);
    if (this.hasPanels) this.request();
  }

  // New panels on show (or none): their outputs are asked for at once.
  panelsChanged(hasPanels: boolean): void {
    this.hasPanels = hasPanels;
    this.deferred = false;
    this.result = null;
    this.panelThickness.clear();
    this.job = null;
    if (hasPanels) this.request();
    else this.show();
  }

  onFabricated(job: number, result: FabricationResult): void {
    if (job !== this.job) return;
    this.job = null;
    this.result = result;
    countOutcome('fabrications');
    this.show();
  }

  // The outputs on show were made with other settings than the form's now: they go.
  onFailed(job: number, message: string): void {
    if (job !== this.job) return;
    this.job = null;
    this.result = null;
    this.host.error(`fabrication: ${message}`);
    this.show();
  }

  // The worker was replaced: an awaited answer will not come. It is asked for again once the
  // new worker has the panels (sendDeferred); until then the outputs on show, of the
  // settings before, are not offered.
  workerLost(): void {
    if (this.job === null) return;
    this.job = null;
    this.deferred = true;
    this.show();
  }

  private formChanged(): void {
    const checked = this.form.read();
    if (!checked.ok) {
      this.host.error(checked.message);
      return;
    }
    this.settings = checked.value;
    this.panelThickness.setValues(this.settings.panelThickness, this.settings.units);
    this.host.settingsChanged();
    if (this.hasPanels) this.request();
  }

  // A clicked panel's own thickness (null: the common one again).
  private setPanelThickness(label: string, value: number | null): void {
    const panelThickness = { ...this.settings.panelThickness };
    if (value === null) delete panelThickness[label];
    else panelThickness[label] = value;
    const checked = validateFabrication({ ...this.settings, panelThickness });
    if (!checked.ok) {
      this.host.error(checked.message);
      return;
    }
    this.write(checked.value);
    this.host.settingsChanged();
  }

  // What kept a request waiting has ended (App.restorePanels): it goes now, and is answered,
  // refused, or waits again.
  sendDeferred(): void {
    if (!this.deferred) return;
    this.deferred = false;
    if (this.hasPanels) this.request();
    else this.update();
  }

  private request(): void {
    const worker = this.host.workerPanels();
    if (worker === 'dead') {
      this.deferred = false;
      this.result = null;
      this.host.error(`fabrication: ${SOLVER_DEAD}`);
      this.show();
      return;
    }
    if (worker === 'pending') {
      // The outputs on show are of the settings before: not offered until the new ones come.
      this.deferred = true;
      this.job = null;
      this.update();
      return;
    }
    const panels = this.host.panelsJob();
    if (panels === null) return;
    this.deferred = false;
    this.job = this.host.solver.fabricate(toFabricationParams(this.settings), panels);
    this.update();
  }

  private show(): void {
    this.panelThickness.setResult(this.result);
    renderFabricationStats(this.statsBox, this.result, this.settings.meshUnits);
    const marked = this.host.viewer.setFabrication(this.result?.innerPositions ?? null, this.result?.spread ?? null);
    this.legend.hidden = marked.nodes === 0;
    this.legendText.textContent = `${marked.nodes} node${marked.nodes === 1 ? '' : 's'} needing extra chamfer (inner corners up to ${this.result ? Number(this.result.spread.maxSpread.toPrecision(3)) : 0} ${this.result?.spread.units ?? ''} apart)`;
    this.foldedLegend.hidden = marked.folded === 0;
    this.foldedLegendText.textContent = `${marked.folded} part${marked.folded === 1 ? '' : 's'} whose inner face folds over at this thickness (outlined)`;
    this.update();
  }

  private update(): void {
    const ready = this.hasPanels && this.job === null && !this.deferred && this.result !== null;
    this.buttons.csv.disabled = !ready;
    this.buttons.json.disabled = !ready;
    this.buttons.svg.disabled = !ready || !this.result?.sheets.ok;
    this.buttons.dxf.disabled = !ready || !this.result?.sheets.ok;
    this.buttons.obj.disabled = !ready || this.result?.solidObj === null;
    this.buttons.obj.title = this.settings.thickness > 0 ? '' : 'set a thickness first';
    document.body.dataset.fabricating = String(this.job !== null || this.deferred);
  }

  private download(kind: 'csv' | 'json' | 'svg' | 'dxf' | 'obj'): void {
    const r = this.result;
    if (!r) return;
    const stem = this.host.stem();
    if (kind === 'csv') downloadText(`${stem}-parts.csv`, r.partsCsv, 'text/csv');
    else if (kind === 'json') downloadText(`${stem}-parts.json`, r.partsJson, 'application/json');
    else if (kind === 'obj' && r.solidObj !== null) downloadText(`${stem}-solid.obj`, r.solidObj, 'model/obj');
    else if (r.sheets.ok && kind === 'svg') downloadText(`${stem}-sheets.svg`, r.sheets.svg, 'image/svg+xml');
    else if (r.sheets.ok && kind === 'dxf') downloadText(`${stem}-sheets.dxf`, r.sheets.dxf, 'application/dxf');
  }
}
