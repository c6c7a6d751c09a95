// The Fabrication inputs <-> FabricationSettings, read through the one validator
// (fabricationParams.ts); the number inputs' ranges come from LIMITS.
import type { LengthUnitName } from '@flatfacet/wasm';
import { element } from './dom.ts';
import { readNumber, setRange } from './formInputs.ts';
import { validateFabrication, type FabricationSettings } from './fabricationParams.ts';
import { LIMITS, type Checked } from './params.ts';

export class FabricationForm {
  private readonly thickness = element('fab-thickness', HTMLInputElement);
  private readonly units = element('fab-units', HTMLSelectElement);
  private readonly meshUnits = element('fab-mesh-units', HTMLSelectElement);
  private readonly side = element('fab-side', HTMLSelectElement);
  private readonly sheetWidth = element('fab-sheet-width', HTMLInputElement);
  private readonly sheetHeight = element('fab-sheet-height', HTMLInputElement);
  private readonly boundaryCut = element('fab-boundary-cut', HTMLSelectElement);
  private readonly boundaryBevel = element('fab-boundary-bevel', HTMLInputElement);
  private readonly upAxis = element('fab-up-axis', HTMLSelectElement);
  private readonly error = element('fab-form-error', HTMLParagraphElement);
  private panelThickness: Record<string, number> = {}; // set by clicking panels (panelThickness.ts)

  constructor() {
    setRange(this.thickness, LIMITS.thickness);
    setRange(this.sheetWidth, LIMITS.sheetSize);
    setRange(this.sheetHeight, LIMITS.sheetSize);
    setRange(this.boundaryBevel, LIMITS.boundaryBevelDeg);
    this.boundaryCut.addEventListener('change', () => this.showBoundaryInputs());
  }

  // The bevel angle only for a bevel, the up axis only for a plumb cut.
  private showBoundaryInputs(): void {
    this.boundaryBevel.hidden = this.boundaryCut.value !== 'bevel';
    this.upAxis.hidden = this.boundaryCut.value !== 'plumb';
  }

  onChange(callback: () => void): void {
    for (const input of [this.thickness, this.units, this.meshUnits, this.side, this.sheetWidth, this.sheetHeight, this.boundaryCut, this.boundaryBevel, this.upAxis]) input.addEventListener('change', callback);
  }

  // A value refused is marked on its input and said under the inputs (the status line is in
  // the Solve section, out of sight here); a valid read clears both.
  read(): Checked<FabricationSettings> {
    const checked = this.readValues();
    const inputs: [string, HTMLInputElement][] = [
      ['Thickness', this.thickness],
      ['Sheet width', this.sheetWidth],
      ['Sheet height', this.sheetHeight],
      ['Boundary bevel', this.boundaryBevel],
    ];
    for (const [, input] of inputs) input.removeAttribute('aria-invalid');
    if (!checked.ok) inputs.find(([name]) => checked.message.startsWith(name))?.[1].setAttribute('aria-invalid', 'true');
    this.error.textContent = checked.ok ? '' : `${checked.message}: the outputs keep the settings before.`;
    this.error.hidden = checked.ok;
    return checked;
  }

  private readValues(): Checked<FabricationSettings> {
    const number = readNumber;
    return validateFabrication({
      thickness: number(this.thickness),
      side: this.side.value,
      units: this.units.value,
      meshUnits: this.meshUnits.value,
      sheetWidth: number(this.sheetWidth),
      sheetHeight: number(this.sheetHeight),
      panelThickness: this.panelThickness,
      boundaryCut: this.boundaryCut.value,
      boundaryBevelDeg: number(this.boundaryBevel),
      upAxis: this.upAxis.value,
    });
  }

  write(settings: FabricationSettings): void {
    this.thickness.value = String(settings.thickness);
    this.units.value = settings.units satisfies LengthUnitName;
    this.meshUnits.value = settings.meshUnits;
    this.side.value = settings.side;
    this.sheetWidth.value = String(settings.sheetWidth);
    this.sheetHeight.value = String(settings.sheetHeight);
    this.panelThickness = { ...settings.panelThickness };
    this.boundaryCut.value = settings.boundaryCut;
    this.boundaryBevel.value = String(settings.boundaryBevelDeg);
    this.upAxis.value = settings.upAxis;
    this.showBoundaryInputs();
  }
}
