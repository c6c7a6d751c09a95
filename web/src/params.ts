// The designer's solver parameters: defaults, limits and a hand-written validator. Shared by
// the form, share links and the stored session, so a value from any of them is checked once,
// here, before it reaches the worker. No DOM: unit-tested in Node.
import type { RemeshParams } from '@flatfacet/wasm';

export type Seeding = 'farthest' | 'random';

export interface MetricWeights {
  euclidean: number;
  l2: number;
  l21: number;
  boundary: number;
}

// Every field explicit (unlike RemeshParams), so equal designs compare equal.
export interface DesignParams {
  panels: number;
  seed: number;
  weights: MetricWeights;
  lloydIterations: number;
  panelRounds: number;
  seeding: Seeding;
  teleport: boolean;
  singlePointNodes: boolean;
  optimizePlanes: boolean;
  glass: boolean; // glass mode: concave panels cut into coplanar convex pieces
  minCornerAngleDeg: number; // 0: no minimum corner angle
}

export const DEFAULT_PARAMS: DesignParams = {
  panels: 120,
  seed: 1,
  weights: { euclidean: 1, l2: 1, l21: 1, boundary: 1 },
  lloydIterations: 20,
  panelRounds: 30,
  seeding: 'farthest',
  teleport: true,
  singlePointNodes: false,
  optimizePlanes: true,
  glass: false,
  minCornerAngleDeg: 0,
};

// The one set of limits: the form's inputs take their min/max from here (paramsForm.ts), and
// links and the stored session are checked against them. Each range lies inside the core's
// (core/remesh_params_json.cpp: panels 1..1e7, iterations 0..1e5 with at least one panel
// round, seed 0..2^53-1, weights 0..1e6); the iteration caps are lower so that no link can
// start a solve of hours (a chain of MAX_HISTORY + 1 solves of at most 200 + 100 steps).
export const LIMITS = {
  panels: { min: 1, max: 100_000 },
  seed: { min: 0, max: Number.MAX_SAFE_INTEGER },
  weight: { min: 0, max: 1000 },
  lloydIterations: { min: 0, max: 200 },
  panelRounds: { min: 1, max: 100 },
  minCornerAngleDeg: { min: 0, max: 60 }, // as the core and the CLI's --min-angle
  // Fabrication (fabricationParams.ts), in the designer's units; inside the core's 0..1e9.
  thickness: { min: 0, max: 100_000 },
  sheetSize: { min: 0.001, max: 1_000_000 },
  boundaryBevelDeg: { min: -60, max: 60 },
} as const;

export const WEIGHT_NAMES: readonly (keyof MetricWeights)[] = ['euclidean', 'l2', 'l21', 'boundary'];

export type Checked<T> = { ok: true; value: T } | { ok: false; message: string };

export function failure<T>(message: string): Checked<T> {
  return { ok: false, message };
}

export function isRecord(value: unknown): value is Record<string, unknown> {
  return typeof value === 'object' && value !== null && !Array.isArray(value);
}

function checkInteger(value: unknown, what: string, range: { min: number; max: number }): Checked<number> {
  if (typeof value !== 'number' || !Number.isInteger(value)) return failure(`${what} must be a whole number`);
  if (value < range.min || value > range.max) return failure(`${what} must be between ${range.min} and ${range.max}`);
  return { ok: true, value };
}

export function checkNumber(value: unknown, what: string, range: { min: number; max: number }): Checked<number> {
  if (typeof value !== 'number' || !Number.isFinite(value)) return failure(`${what} must be a number`);
  if (value < range.min || value > range.max) return failure(`${what} must be between ${range.min} and ${range.max}`);
  return { ok: true, value };
}

function checkBoolean(value: unknown, what: string): Checked<boolean> {
  return typeof value === 'boolean' ? { ok: true, value } : failure(`${what} must be true or false`);
}

// Validates an untrusted object (from a link, the stored session or the form) field by field.
// Unknown fields are rejected too: a link from a newer version must not half-apply.
export function validateParams(value: unknown, where = 'parameters'): Checked<DesignParams> {
  if (!isRecord(value)) return failure(`${where} must be an object`);
  const known = new Set(['panels', 'seed', 'weights', 'lloydIterations', 'panelRounds', 'seeding', 'teleport', 'singlePointNodes', 'optimizePlanes', 'glass', 'minCornerAngleDeg']);
  for (const key of Object.keys(value)) {
    if (!known.has(key)) return failure(`${where}: unknown field "${key.slice(0, 40)}"`);
  }
  const panels = checkInteger(value.panels, 'Panels', LIMITS.panels);
  if (!panels.ok) return panels;
  const seed = checkInteger(value.seed, 'Seed', LIMITS.seed);
  if (!seed.ok) return seed;
  const lloyd = checkInteger(value.lloydIterations, 'Lloyd iterations', LIMITS.lloydIterations);
  if (!lloyd.ok) return lloyd;
  const rounds = checkInteger(value.panelRounds, 'Panel rounds', LIMITS.panelRounds);
  if (!rounds.ok) return rounds;
  if (value.seeding !== 'farthest' && value.seeding !== 'random') return failure('Seeding must be "farthest" or "random"');
  const flags: Record<'teleport' | 'singlePointNodes' | 'optimizePlanes', boolean> = { teleport: true, singlePointNodes: false, optimizePlanes: true };
  for (const flag of ['teleport', 'singlePointNodes', 'optimizePlanes'] as const) {
    const checked = checkBoolean(value[flag], flag);
    if (!checked.ok) return checked;
    flags[flag] = checked.value;
  }
  // Absent in links and sessions made before glass mode came to the page: off.
  const glass = value.glass === undefined ? { ok: true as const, value: false } : checkBoolean(value.glass, 'Glass mode');
  if (!glass.ok) return glass;
  const minAngle = value.minCornerAngleDeg === undefined ? { ok: true as const, value: 0 } : checkNumber(value.minCornerAngleDeg, 'Min corner angle', LIMITS.minCornerAngleDeg);
  if (!minAngle.ok) return minAngle;
  const weightsValue = value.weights;
  if (!isRecord(weightsValue)) return failure('weights must be an object');
  for (const key of Object.keys(weightsValue)) {
    if (!(WEIGHT_NAMES as readonly string[]).includes(key)) return failure(`weights: unknown term "${key.slice(0, 40)}"`);
  }
  const weights: MetricWeights = { euclidean: 0, l2: 0, l21: 0, boundary: 0 };
  for (const name of WEIGHT_NAMES) {
    const checked = checkNumber(weightsValue[name], `Weight ${name}`, LIMITS.weight);
    if (!checked.ok) return checked;
    weights[name] = checked.value;
  }
  if (weights.euclidean + weights.l2 + weights.l21 === 0) return failure('At least one of the euclidean, L2 and L2,1 weights must be above 0');
  return {
    ok: true,
    value: {
      panels: panels.value,
      seed: seed.value,
      weights,
      lloydIterations: lloyd.value,
      panelRounds: rounds.value,
      seeding: value.seeding,
      ...flags,
      glass: glass.value,
      minCornerAngleDeg: minAngle.value,
    },
  };
}

export function sameParams(a: DesignParams, b: DesignParams): boolean {
  return JSON.stringify(a) === JSON.stringify(b);
}

// A changed seed or seeding method starts over in the core; only the rest warm-starts.
export function canWarmStart(from: DesignParams, to: DesignParams): boolean {
  return from.seed === to.seed && from.seeding === to.seeding;
}

export function toRemeshParams(params: DesignParams): RemeshParams {
  return {
    panels: params.panels,
    seed: params.seed,
    weights: { ...params.weights },
    lloydIterations: params.lloydIterations,
    panelRounds: params.panelRounds,
    seeding: params.seeding,
    teleport: params.teleport,
    singlePointNodes: params.singlePointNodes,
    optimizePlanes: params.optimizePlanes,
    glass: params.glass,
    minCornerAngleDeg: params.minCornerAngleDeg,
  };
}
