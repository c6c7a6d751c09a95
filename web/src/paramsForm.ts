// The parameter inputs of the side panel <-> DesignParams. Reading validates through
// params.ts, so the form, links and stored sessions share one set of rules.
import { element } from './dom.ts';
import { readNumber, setRange } from './formInputs.ts';
import { LIMITS, validateParams, type Checked, type DesignParams } from './params.ts';

export class ParamsForm {
  private readonly panels = element('panels', HTMLInputElement);
  private readonly seed = element('seed', HTMLInputElement);
  private readonly euclidean = element('w-euclidean', HTMLInputElement);
  private readonly l2 = element('w-l2', HTMLInputElement);
  private readonly l21 = element('w-l21', HTMLInputElement);
  private readonly boundary = element('w-boundary', HTMLInputElement);
  private readonly lloydIterations = element('lloyd-iterations', HTMLInputElement);
  private readonly panelRounds = element('panel-rounds', HTMLInputElement);
  private readonly seeding = element('seeding', HTMLSelectElement);
  private readonly teleport = element('teleport', HTMLInputElement);
  private readonly singlePointNodes = element('single-point-nodes', HTMLInputElement);
  private readonly optimizePlanes = element('optimize-planes', HTMLInputElement);
  private readonly glass = element('glass', HTMLInputElement);
  private readonly minCornerAngle = element('min-corner-angle', HTMLInputElement);

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
      [this.minCornerAngle, LIMITS.minCornerAngleDeg],
    ];
    for (const [input, range] of ranges) setRange(input, range);
    this.seed.title = `a whole number from ${LIMITS.seed.min} to 2^53 − 1 (${LIMITS.seed.max}); the same seed gives the same panels`;
    this.lloydIterations.title = `clustering iterations, ${LIMITS.lloydIterations.min} to ${LIMITS.lloydIterations.max}`;
    this.panelRounds.title = `panel rounds, ${LIMITS.panelRounds.min} to ${LIMITS.panelRounds.max}`;
    this.panels.title = `${LIMITS.panels.min} to ${LIMITS.panels.max.toLocaleString('en')} panels (at most one per triangle)`;
  }

  private get numberInputs(): HTMLInputElement[] {
    return [this.panels, this.seed, this.euclidean, this.l2, this.l21, this.boundary, this.lloydIterations, this.panelRounds, this.minCornerAngle];
  }

  // Calls back on committed changes (enter, blur, spinner, checkbox), not on every keystroke.
  onChange(callback: () => void): void {
    for (const input of [...this.numberInputs, this.teleport, this.singlePointNodes, this.optimizePlanes, this.glass, this.seeding]) {
      input.addEventListener('change', callback);
    }
  }

  read(): Checked<DesignParams> {
    for (const input of this.numberInputs) input.removeAttribute('aria-invalid');
    const number = readNumber;
    const checked = validateParams({
      panels: number(this.panels),
      seed: number(this.seed),
      weights: { euclidean: number(this.euclidean), l2: number(this.l2), l21: number(this.l21), boundary: number(this.boundary) },
      lloydIterations: number(this.lloydIterations),
      panelRounds: number(this.panelRounds),
      seeding: this.seeding.value,
      teleport: this.teleport.checked,
      singlePointNodes: this.singlePointNodes.checked,
      optimizePlanes: this.optimizePlanes.checked,
      glass: this.glass.checked,
      minCornerAngleDeg: number(this.minCornerAngle),
    });
    if (!checked.ok) this.markInvalid(checked.message);
    return checked;
  }

  private markInvalid(message: string): void {
    const byName: [string, HTMLInputElement][] = [
      ['Panels', this.panels],
      ['Seed', this.seed],
      ['euclidean', this.euclidean],
      ['l21', this.l21],
      ['l2', this.l2],
      ['boundary', this.boundary],
      ['Lloyd', this.lloydIterations],
      ['Panel rounds', this.panelRounds],
      ['Min corner angle', this.minCornerAngle],
    ];
    const match = byName.find(([name]) => message.includes(name));
    match?.[1].setAttribute('aria-invalid', 'true');
  }

  write(params: DesignParams): void {
    this.panels.value = String(params.panels);
    this.seed.value = String(params.seed);
    this.euclidean.value = String(params.weights.euclidean);
    this.l2.value = String(params.weights.l2);
    this.l21.value = String(params.weights.l21);
    this.boundary.value = String(params.weights.boundary);
    this.lloydIterations.value = String(params.lloydIterations);
    this.panelRounds.value = String(params.panelRounds);
    this.seeding.value = params.seeding;
    this.teleport.checked = params.teleport;
    this.singlePointNodes.checked = params.singlePointNodes;
    this.optimizePlanes.checked = params.optimizePlanes;
    this.glass.checked = params.glass;
    this.minCornerAngle.value = String(params.minCornerAngleDeg);
    for (const input of this.numberInputs) input.removeAttribute('aria-invalid');
  }

  setPanels(panels: number): void {
    this.panels.value = String(panels);
  }
}
