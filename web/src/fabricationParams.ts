// The fabrication settings: thickness, material side, units and sheet size. Defaults and the
// one validator for the form, links and the stored session; the limits are LIMITS (params.ts).
// No DOM: unit-tested in Node.
import type { FabricationParams, LengthUnitName } from '@flatfacet/wasm';
import { checkNumber, failure, isRecord, LIMITS, type Checked } from './params.ts';

export const UNIT_NAMES: readonly LengthUnitName[] = ['mm', 'cm', 'm', 'in', 'ft'];

// Every field explicit, so equal settings compare equal.
export interface FabricationSettings {
  thickness: number; // in `units`; 0: no inner faces
  side: 'inside' | 'outside';
  units: LengthUnitName;
  meshUnits: LengthUnitName;
  sheetWidth: number; // in `units`
  sheetHeight: number;
}

export const DEFAULT_FABRICATION: FabricationSettings = {
  thickness: 0,
  side: 'inside',
  units: 'mm',
  meshUnits: 'm',
  sheetWidth: 2440,
  sheetHeight: 1220,
};

const FIELDS = ['thickness', 'side', 'units', 'meshUnits', 'sheetWidth', 'sheetHeight'];

function checkUnit(value: unknown, what: string): Checked<LengthUnitName> {
  return typeof value === 'string' && (UNIT_NAMES as readonly string[]).includes(value) ? { ok: true, value: value as LengthUnitName } : failure(`${what} must be one of ${UNIT_NAMES.join(', ')}`);
}

// Validates an untrusted object field by field; unknown fields are rejected.
export function validateFabrication(value: unknown, where = 'fabrication'): Checked<FabricationSettings> {
  if (!isRecord(value)) return failure(`${where} must be an object`);
  for (const key of Object.keys(value)) {
    if (!FIELDS.includes(key)) return failure(`${where}: unknown field "${key.slice(0, 40)}"`);
  }
  const thickness = checkNumber(value.thickness, 'Thickness', LIMITS.thickness);
  if (!thickness.ok) return thickness;
  if (value.side !== 'inside' && value.side !== 'outside') return failure('Material side must be "inside" or "outside"');
  const units = checkUnit(value.units, 'Units');
  if (!units.ok) return units;
  const meshUnits = checkUnit(value.meshUnits, 'Mesh units');
  if (!meshUnits.ok) return meshUnits;
  const width = checkNumber(value.sheetWidth, 'Sheet width', LIMITS.sheetSize);
  if (!width.ok) return width;
  const height = checkNumber(value.sheetHeight, 'Sheet height', LIMITS.sheetSize);
  if (!height.ok) return height;
  return { ok: true, value: { thickness: thickness.value, side: value.side, units: units.value, meshUnits: meshUnits.value, sheetWidth: width.value, sheetHeight: height.value } };
}

// Absent (an older link or stored session): the defaults.
export function fabricationOrDefault(value: unknown, where: string): Checked<FabricationSettings> {
  if (value === undefined) return { ok: true, value: { ...DEFAULT_FABRICATION } };
  const checked = validateFabrication(value, where);
  return checked.ok ? checked : failure(`in ${where}, ${checked.message}`);
}

export function toFabricationParams(settings: FabricationSettings): FabricationParams {
  return { ...settings };
}
