// The Fabrication inputs <-> FabricationSettings, read through the one validator
// (fabricationParams.ts); the number inputs' ranges come from LIMITS.
import type { LengthUnitName } from '@flatfacet/wasm';
import { element } from './dom.ts';
import { validateFabrication, type FabricationSettings } from './fabricationParams.ts';
import { LIMITS, type Checked } from './params.ts';

export class FabricationForm {
  private readonly thickness = element('fab-thickness', HTMLInputElement);
  private readonly units = element('fab-units', HTMLSelectElement);
  private readonly meshUnits = element('fab-mesh-units', HTMLSelectElement);
  private readonly side = element('fab-side', HTMLSelectElement);
  private readonly sheetWidth = element('fab-sheet-width', HTMLInputElement);
  private readonly sheetHeight = element('fab-sheet-height', HTMLInputElement);

  constructor() {
    this.thickness.min = String(LIMITS.thickness.min);
    this.thickness.max = String(LIMITS.thickness.max);
    for (const input of [this.sheetWidth, this.sheetHeight]) {
      input.min = String(LIMITS.sheetSize.min);
      input.max = String(LIMITS.sheetSize.max);
    }
  }

  onChange(callback: () => void): void {
    for (const input of [this.thickness, this.units, this.meshUnits, this.side, this.sheetWidth, this.sheetHeight]) input.addEventListener('change', callback);
  }

  read(): Checked<FabricationSettings> {
    const number = (input: HTMLInputElement): number | string => (input.value.trim() === '' ? '' : Number(input.value));
    return validateFabrication({
      thickness: number(this.thickness),
      side: this.side.value,
      units: this.units.value,
      meshUnits: this.meshUnits.value,
      sheetWidth: number(this.sheetWidth),
      sheetHeight: number(this.sheetHeight),
    });
  }

  write(settings: FabricationSettings): void {
    this.thickness.value = String(settings.thickness);
    this.units.value = settings.units satisfies LengthUnitName;
    this.meshUnits.value = settings.meshUnits;
    this.side.value = settings.side;
    this.sheetWidth.value = String(settings.sheetWidth);
    this.sheetHeight.value = String(settings.sheetHeight);
  }
}
