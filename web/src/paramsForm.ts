// The parameter inputs of the side panel <-> DesignParams. Reading validates through
// params.ts, so the form, links and stored sessions share one set of rules.
import { element } from './dom.ts';
import { readNumber, setRange } from './formInputs.ts';
import { countAfterEdits, targetOfTyped, type PanelEdit } from './edits/panelEdits.ts';
import { checkExpression, DENSITY_PRESETS, DIRECTION_PRESETS, LIMITS, validateParams, type Checked, type DesignParams } from './params.ts';

export class ParamsForm {
  private readonly panels = element('panels', HTMLInputElement);
  private readonly seed = element('seed', HTMLInputElement);
  private readonly euclidean = element('w-euclidean', HTMLInputElement);
  private readonly l2 = element('w-l2', HTMLInputElement);
  private readonly l21 = element('w-l21', HTMLInputElement);
  private readonly boundary = element('w-boundary', HTMLInputElement);
  private readonly lloydIterations = element('lloyd-iterations', HTMLInputElement);
  private readonly panelRounds = element('panel-rounds', HTMLInputElement);
  private readonly retries = element('retries', HTMLInputElement);
  private readonly seeding = element('seeding', HTMLSelectElement);
  private readonly teleport = element('teleport', HTMLInputElement);
  private readonly singlePointNodes = element('single-point-nodes', HTMLInputElement);
  private readonly optimizePlanes = element('optimize-planes', HTMLInputElement);
  private readonly expression = element('density-expression', HTMLInputElement);
  private readonly preset = element('density-preset', HTMLSelectElement);
  private readonly direction = element('anisotropy-direction', HTMLSelectElement);
  private readonly stretch = element('anisotropy-stretch', HTMLInputElement);
  // "ex, ey, ez" for the Expression direction; its row shows with that direction only.
  private readonly directionExpression = element('anisotropy-expression', HTMLInputElement);
  private readonly directionExpressionRow = element('anisotropy-expression-row', HTMLDivElement);
  // The painted field's key (brush/densityField.ts): set by the brush, not typed.
  private paintKey = '';
  private readonly glass = element('glass', HTMLInputElement);
  private readonly minCornerAngle = element('min-corner-angle', HTMLInputElement);
  private readonly coplanarAngle = element('coplanar-angle', HTMLInputElement);
  // The per-panel edits (edits/editPanel.ts): made by clicking panels, not typed.
  private editList: PanelEdit[] = [];
  // "Panels" shows the count now, which after edits is not DesignParams.panels (the count the
  // solve targeted): the target, and the count shown for it; reading the count shown gives
  // the target back (edits/panelEdits.ts, targetOfTyped).
  private target = 0;
  private shown = 0;

  constructor() {
    // The inputs' ranges come from LIMITS (params.ts), the same rules links are checked by.
    const ranges: [HTMLInputElement, { min: number; max: number }][] = [
      [this.panels, LIMITS.panels],
      [this.seed, LIMITS.seed],
      [this.euclidean, LIMITS.weight],
      [this.l2, LIMITS.weight],
      [this.l21, LIMITS.weight],
      [this.boundary, LIMITS.weight],
      [this.lloydIterations, LIMITS.lloydIterations],
      [this.panelRounds, LIMITS.panelRounds],
      [this.retries, LIMITS.retries],
      [this.minCornerAngle, LIMITS.minCornerAngleDeg],
      [this.coplanarAngle, LIMITS.coplanarAngleDeg],
    ];
    for (const [input, range] of ranges) setRange(input, range);
    this.seed.title = `a whole number from ${LIMITS.seed.min} to 2^53 − 1 (${LIMITS.seed.max}); the same seed gives the same panels`;
    this.lloydIterations.title = `clustering iterations, ${LIMITS.lloydIterations.min} to ${LIMITS.lloydIterations.max}`;
    this.panelRounds.title = `panel rounds, ${LIMITS.panelRounds.min} to ${LIMITS.panelRounds.max}`;
    this.retries.title = `${LIMITS.retries.min} to ${LIMITS.retries.max}: solves from a new seeding when panels end invalid (the fewest invalid kept; a valid solve never retries)`;
    this.panels.title = `${LIMITS.panels.min} to ${LIMITS.panels.max.toLocaleString('en')} panels (at most one per triangle)`;
    this.stretch.min = String(LIMITS.stretch.min);
    this.stretch.max = String(LIMITS.stretch.max);
    this.expression.maxLength = LIMITS.expressionLength.max;
    for (const preset of DENSITY_PRESETS) this.preset.add(new Option(preset.label, preset.id));
    // Registered first, so the expression is in place when onChange's callbacks read the form.
    this.preset.addEventListener('change', () => {
      const chosen = DENSITY_PRESETS.find((p) => p.id === this.preset.value);
      if (this.preset.value === '') this.expression.value = '';
      else if (chosen) this.expression.value = chosen.expression;
    });
    this.expression.addEventListener('input', () => this.syncPreset());
    this.directionExpression.maxLength = LIMITS.expressionLength.max;
    const presets = element('direction-presets', HTMLDataListElement);
    for (const preset of DIRECTION_PRESETS) presets.append(new Option(preset.label, preset.expression));
    // Registered first too: choosing Expression with nothing typed starts from the vortex.
    this.direction.addEventListener('change', () => {
      if (this.direction.value === 'expression' && this.directionExpression.value.trim() === '') this.directionExpression.value = DIRECTION_PRESETS[0]!.expression;
      this.syncDirectionRow();
    });
  }

  private syncDirectionRow(): void {
    this.directionExpressionRow.hidden = this.direction.value !== 'expression';
  }

  // The preset whose expression is typed, else "custom" (or "none" when empty).
  private syncPreset(): void {
    const text = this.expression.value.trim();
    this.preset.value = text === '' ? '' : (DENSITY_PRESETS.find((p) => p.expression === text)?.id ?? 'custom');
  }

  private get numberInputs(): HTMLInputElement[] {
    return [this.panels, this.seed, this.euclidean, this.l2, this.l21, this.boundary, this.lloydIterations, this.panelRounds, this.retries, this.minCornerAngle, this.coplanarAngle];
  }

  // Calls back on committed changes (enter, blur, spinner, checkbox), not on every keystroke.
  onChange(callback: () => void): void {
    for (const input of [...this.numberInputs, this.teleport, this.singlePointNodes, this.optimizePlanes, this.glass, this.seeding, this.expression, this.preset, this.direction, this.stretch, this.directionExpression]) {
      input.addEventListener('change', callback);
    }
  }

  read(): Checked<DesignParams> {
    for (const input of [...this.numberInputs, this.expression, this.stretch, this.directionExpression]) input.removeAttribute('aria-invalid');
    const number = readNumber;
    const direction = this.direction.value;
    const checked = validateParams({
      panels: targetOfTyped(number(this.panels), this.shown, this.target, this.editList.length > 0),
      seed: number(this.seed),
      weights: { euclidean: number(this.euclidean), l2: number(this.l2), l21: number(this.l21), boundary: number(this.boundary) },
      lloydIterations: number(this.lloydIterations),
      panelRounds: number(this.panelRounds),
      retries: number(this.retries),
      seeding: this.seeding.value,
      teleport: this.teleport.checked,
      singlePointNodes: this.singlePointNodes.checked,
      optimizePlanes: this.optimizePlanes.checked,
      densityExpression: this.expression.value,
      anisotropy: direction === 'expression' ? { direction, stretch: number(this.stretch), expression: this.directionExpression.value } : { direction, stretch: number(this.stretch) },
      paint: this.paintKey,
      glass: this.glass.checked,
      minCornerAngleDeg: number(this.minCornerAngle),
      coplanarAngleDeg: number(this.coplanarAngle),
      edits: this.editList,
    });
    if (!checked.ok) this.markInvalid(checked.message);
    return checked;
  }

  private markInvalid(message: string): void {
    const byName: [string, HTMLInputElement][] = [
      ['Direction expression', this.directionExpression],
      ['Panels', this.panels],
      ['Seed', this.seed],
      ['euclidean', this.euclidean],
      ['l21', this.l21],
      ['l2', this.l2],
      ['boundary', this.boundary],
      ['Lloyd', this.lloydIterations],
      ['Panel rounds', this.panelRounds],
      ['Retries', this.retries],
      ['Density expression', this.expression],
      ['Stretch', this.stretch],
      ['Min corner angle', this.minCornerAngle],
      ['Coplanar angle', this.coplanarAngle],
    ];
    const match = byName.find(([name]) => message.includes(name));
    match?.[1].setAttribute('aria-invalid', 'true');
  }

  // `count`: the panels the design has (its solve's clusters), when known; else the target
  // plus splits minus merges, which is what a solve from scratch gives.
  write(params: DesignParams, count?: number): void {
    this.editList = params.edits.map((edit) => ({ ...edit }));
    this.showCount(params.panels, count ?? countAfterEdits(params.panels, params.edits));
    this.seed.value = String(params.seed);
    this.euclidean.value = String(params.weights.euclidean);
    this.l2.value = String(params.weights.l2);
    this.l21.value = String(params.weights.l21);
    this.boundary.value = String(params.weights.boundary);
    this.lloydIterations.value = String(params.lloydIterations);
    this.panelRounds.value = String(params.panelRounds);
    this.retries.value = String(params.retries);
    this.seeding.value = params.seeding;
    this.teleport.checked = params.teleport;
    this.singlePointNodes.checked = params.singlePointNodes;
    this.optimizePlanes.checked = params.optimizePlanes;
    this.glass.checked = params.glass;
    this.minCornerAngle.value = String(params.minCornerAngleDeg);
    this.coplanarAngle.value = String(params.coplanarAngleDeg);
    this.expression.value = params.densityExpression;
    this.syncPreset();
    this.direction.value = params.anisotropy.direction;
    this.stretch.value = String(params.anisotropy.stretch);
    // Another direction keeps what was typed, for a switch back.
    if (params.anisotropy.expression !== undefined) this.directionExpression.value = params.anisotropy.expression;
    this.syncDirectionRow();
    this.paintKey = params.paint;
    for (const input of [...this.numberInputs, this.expression, this.stretch, this.directionExpression]) input.removeAttribute('aria-invalid');
  }

  get paint(): string {
    return this.paintKey;
  }

  setPaint(key: string): void {
    this.paintKey = key;
  }

  get edits(): readonly PanelEdit[] {
    return this.editList;
  }

  setEdits(edits: readonly PanelEdit[]): void {
    this.editList = edits.map((edit) => ({ ...edit }));
  }

  setPanels(panels: number): void {
    this.showCount(panels, panels);
  }

  // The solved design's count in "Panels" for its target (the form shows that design, edits
  // included). Without edits "Panels" is the target, as it always was.
  showCount(target: number, count: number): void {
    this.target = target;
    this.shown = this.editList.length > 0 ? count : target;
    this.panels.value = String(this.shown);
  }

  // The density expression as the design uses it ('' for none or one the page refuses).
  get densityExpression(): string {
    const checked = checkExpression(this.expression.value);
    return checked.ok ? checked.value : '';
  }
}
