// The fabrication settings: thickness, material side, units and sheet size. Defaults and the
// one validator for the form, links and the stored session; the limits are LIMITS (params.ts).
// No DOM: unit-tested in Node.
import type { FabricationParams, LengthUnitName } from '@flatfacet/wasm';
import { absentOr, checkNumber, failure, isRecord, LIMITS, type Checked } from './params.ts';

export const UNIT_NAMES: readonly LengthUnitName[] = ['mm', 'cm', 'm', 'in', 'ft'];

// Every field explicit, so equal settings compare equal.
export interface FabricationSettings {
  thickness: number; // in `units`; 0: no inner faces
  side: 'inside' | 'outside';
  units: LengthUnitName;
  meshUnits: LengthUnitName;
  sheetWidth: number; // in `units`
  sheetHeight: number;
  panelThickness: Record<string, number>; // by panel label ("P3", "P12a"), in `units`; keys sorted
  boundaryCut: BoundaryCutName;
  boundaryBevelDeg: number; // for 'bevel': from square, positive makes the inner face smaller
  upAxis: 'x' | 'y' | 'z'; // for 'plumb'
}

export type BoundaryCutName = 'square' | 'plumb' | 'bevel';
export const BOUNDARY_CUTS: readonly BoundaryCutName[] = ['square', 'plumb', 'bevel'];
const PANEL_LABEL = /^P[1-9][0-9]*[a-z]*$/;
const MAX_PANEL_THICKNESSES = 100_000;

export const DEFAULT_FABRICATION: FabricationSettings = {
  thickness: 0,
  side: 'inside',
  units: 'mm',
  meshUnits: 'm',
  sheetWidth: 2440,
  sheetHeight: 1220,
  panelThickness: {},
  boundaryCut: 'square',
  boundaryBevelDeg: 0,
  upAxis: 'z',
};

const FIELDS = ['thickness', 'side', 'units', 'meshUnits', 'sheetWidth', 'sheetHeight', 'panelThickness', 'boundaryCut', 'boundaryBevelDeg', 'upAxis'];

// The per-panel thicknesses, keys sorted so equal settings stringify equally.
function checkPanelThickness(value: unknown): Checked<Record<string, number>> {
  if (value === undefined) return { ok: true, value: {} };
  if (!isRecord(value)) return failure('Panel thickness must be an object of panel labels');
  const keys = Object.keys(value).sort();
  if (keys.length > MAX_PANEL_THICKNESSES) return failure(`Panel thickness: at most ${MAX_PANEL_THICKNESSES} panels`);
  const out: Record<string, number> = {};
  for (const key of keys) {
    if (!PANEL_LABEL.test(key)) return failure(`Panel thickness: "${key.slice(0, 20)}" is not a panel label`);
    const t = checkNumber(value[key], `Panel thickness of ${key}`, LIMITS.thickness);
    if (!t.ok) return t;
    if (t.value <= 0) return failure(`Panel thickness of ${key} must be above 0`);
    out[key] = t.value;
  }
  return { ok: true, value: out };
}

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
  const panelThickness = checkPanelThickness(value.panelThickness);
  if (!panelThickness.ok) return panelThickness;
  // Absent in links and sessions made before these came to the page: the defaults.
  const boundaryCut = absentOr(value.boundaryCut, 'square');
  if (!(BOUNDARY_CUTS as readonly unknown[]).includes(boundaryCut)) return failure('Boundary edges must be "square", "plumb" or "bevel"');
  const bevel = value.boundaryBevelDeg === undefined ? { ok: true as const, value: 0 } : checkNumber(value.boundaryBevelDeg, 'Boundary bevel', LIMITS.boundaryBevelDeg);
  if (!bevel.ok) return bevel;
  const upAxis = absentOr(value.upAxis, 'z');
  if (upAxis !== 'x' && upAxis !== 'y' && upAxis !== 'z') return failure('Up axis must be x, y or z');
  return {
    ok: true,
    value: {
      thickness: thickness.value,
      side: value.side,
      units: units.value,
      meshUnits: meshUnits.value,
      sheetWidth: width.value,
      sheetHeight: height.value,
      panelThickness: panelThickness.value,
      boundaryCut: boundaryCut as BoundaryCutName,
      boundaryBevelDeg: bevel.value,
      upAxis,
    },
  };
}

// Absent (an older link or stored session): the defaults.
export function fabricationOrDefault(value: unknown, where: string): Checked<FabricationSettings> {
  if (value === undefined) return { ok: true, value: { ...DEFAULT_FABRICATION } };
  const checked = validateFabrication(value); // "fabrication: unknown field …", not "the link: …" twice
  return checked.ok ? checked : failure(`in ${where}, ${checked.message}`);
}

// Panel thicknesses wait for a thickness of the other panels (the core needs one).
export function toFabricationParams(settings: FabricationSettings): FabricationParams {
  const { panelThickness, ...rest } = settings;
  return settings.thickness > 0 && Object.keys(panelThickness).length > 0 ? { ...rest, panelThickness: { ...panelThickness } } : rest;
}
