// The designer's solver parameters: defaults, limits and a hand-written validator. Shared by
// the form, share links and the stored session, so a value from any of them is checked once,
// here, before it reaches the worker. No DOM: unit-tested in Node.
import type { RemeshParams } from '@flatfacet/wasm';
import { checkEdits, type PanelEdit } from './edits/panelEdits.ts';

export type Seeding = 'farthest' | 'random';

export interface MetricWeights {
  euclidean: number;
  l2: number;
  l21: number;
  boundary: number;
}

export type AnisotropyDirection = 'none' | 'x' | 'y' | 'z' | 'maxCurvature' | 'minCurvature' | 'expression';
export const ANISOTROPY_DIRECTIONS: readonly AnisotropyDirection[] = ['none', 'x', 'y', 'z', 'maxCurvature', 'minCurvature', 'expression'];

export interface Anisotropy {
  direction: AnisotropyDirection;
  stretch: number; // how much longer than wide panels are along `direction`, 1..10
  // Direction 'expression' only (and then always): "ex, ey, ez", three expressions of the
  // density language per face (core/density/direction_expression.h), e.g. "-y, x, 0".
  expression?: string;
}

// Every field explicit (unlike RemeshParams), so equal designs compare equal.
export interface DesignParams {
  // The count the solve targeted (what links store and the core reads as RemeshParams.panels).
  // With edits the design has this plus splits minus merges, which "Panels" shows and reads
  // back as this (edits/panelEdits.ts, countAfterEdits and targetOfTyped).
  panels: number;
  seed: number;
  weights: MetricWeights;
  lloydIterations: number;
  panelRounds: number;
  // Solves from a new seeding when panels end invalid (the fewest invalid kept).
  retries: number;
  seeding: Seeding;
  teleport: boolean;
  singlePointNodes: boolean;
  optimizePlanes: boolean;
  // Procedural density (core/density/expression.h), '' for none: higher = smaller panels.
  densityExpression: string;
  anisotropy: Anisotropy;
  // The painted density field (brush/densityField.ts): its content key, '' for none. The
  // field itself travels beside the parameters (DesignState.paint), once per key.
  paint: string;
  glass: boolean; // glass mode: concave panels cut into coplanar convex pieces
  minCornerAngleDeg: number; // 0: no minimum corner angle
  // Neighbours whose planes differ by less share one plane (the paper's master planes, 2.4).
  coplanarAngleDeg: number;
  // Per-panel edits in order (edits/panelEdits.ts): split, merge, lock, unlock by triangle.
  edits: PanelEdit[];
}

export const DEFAULT_PARAMS: DesignParams = {
  panels: 120,
  seed: 1,
  weights: { euclidean: 1, l2: 1, l21: 1, boundary: 1 },
  lloydIterations: 20,
  panelRounds: 100,
  retries: 8,
  seeding: 'farthest',
  teleport: true,
  singlePointNodes: false,
  optimizePlanes: true,
  densityExpression: '',
  anisotropy: { direction: 'none', stretch: 1 },
  paint: '',
  glass: false,
  minCornerAngleDeg: 0,
  coplanarAngleDeg: 1,
  edits: [],
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
  retries: { min: 0, max: 10 }, // as the core (RemeshParams::kMaxRetries) and the CLI's --retries
  minCornerAngleDeg: { min: 0, max: 60 }, // as the core and the CLI's --min-angle
  coplanarAngleDeg: { min: 0, max: 10 }, // as the core and the CLI's --coplanar-angle
  // Fabrication (fabricationParams.ts), in the designer's units; inside the core's 0..1e9.
  thickness: { min: 0, max: 100_000 },
  sheetSize: { min: 0.001, max: 1_000_000 },
  // Density expression length (the core takes up to 4096 characters) and the stretch factor.
  expressionLength: { min: 0, max: 1000 },
  stretch: { min: 1, max: 10 },
  boundaryBevelDeg: { min: -60, max: 60 },
} as const;

// The names an expression may use (core/density/expression.h); anything else is refused on
// the page already, so a link cannot smuggle in text the core would only reject later.
// `border` is a density input only (the core refuses it in a direction expression).
const CONSTANTS_AND_FUNCTIONS = [
  'pi', 'e',
  'sin', 'cos', 'tan', 'asin', 'acos', 'atan', 'atan2', 'sqrt', 'exp', 'log', 'log10', 'abs', 'sign', 'floor', 'ceil',
  'round', 'pow', 'min', 'max', 'clamp', 'smoothstep', 'step', 'mix', 'mod', 'if',
];
const DIRECTION_VARIABLES = ['x', 'y', 'z', 'u', 'v', 'w', 'nx', 'ny', 'nz', 'k1', 'k2', 'H', 'K', 'curv'];
const DENSITY_VARIABLES = [...DIRECTION_VARIABLES, 'border'];
const DENSITY_NAMES = new Set([...DENSITY_VARIABLES, ...CONSTANTS_AND_FUNCTIONS]);
const DIRECTION_NAMES = new Set([...DIRECTION_VARIABLES, ...CONSTANTS_AND_FUNCTIONS]);

// Starting points for the expression (the core's kDensityPresets): scale-free, written with
// u v w (0..1 across the bounding box), curv (curvature times the bounding box diagonal) and
// border (distance to the surface's border over the diagonal).
export const DENSITY_PRESETS: readonly { id: string; label: string; expression: string }[] = [
  { id: 'twoSizes', label: 'Two element sizes', expression: '1 + 3 * smoothstep(0.45, 0.55, u)' },
  { id: 'gradient', label: 'Gradient', expression: '1 + 3 * u' },
  { id: 'radial', label: 'Radial', expression: '1 + 3 * exp(-8 * ((u - 0.5)^2 + (v - 0.5)^2))' },
  { id: 'curvature', label: 'By curvature', expression: '1 + 2 * min(curv, 4)' },
  { id: 'border', label: 'Finer at borders', expression: '1 + 3 * exp(-border / 0.05)' },
];

// Starting points for the direction expression, scale-free like the density presets: around
// the middle of the plan, away from it, and down the slope (the normal's horizontal part,
// which the core projects into each face).
export const DIRECTION_PRESETS: readonly { id: string; label: string; expression: string }[] = [
  { id: 'vortex', label: 'Vortex', expression: '0.5 - v, u - 0.5, 0' },
  { id: 'radial', label: 'Radial', expression: 'u - 0.5, v - 0.5, 0' },
  { id: 'slope', label: 'Down the slope', expression: 'nx, ny, 0' },
];

const PAINT_KEY = /^[0-9a-f]{16}$/;

// A density expression from the form or a link: plain ASCII of numbers, operators and the
// known names only. The grammar itself is the core's to check (its message names the column).
// `what` names the input in messages (the direction expression shares the checks).
export function checkExpression(value: unknown, what = 'Density expression', names: ReadonlySet<string> = DENSITY_NAMES): Checked<string> {
  if (typeof value !== 'string') return failure(`${what} must be text`);
  const text = value.trim();
  if (text.length > LIMITS.expressionLength.max) return failure(`${what} is longer than ${LIMITS.expressionLength.max} characters`);
  // Numbers (1, 2.5, .5, 1e-3), names, operators and brackets, separated by spaces.
  const token = /[ \t]*(?:((?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)|([A-Za-z_][A-Za-z0-9_]*)|(<=|>=|==|!=|&&|\|\||[-+*/^%()<>!?:,]))/y;
  let at = 0;
  while (at < text.length) {
    token.lastIndex = at;
    const match = token.exec(text);
    if (!match) {
      const column = at + /^[ \t]*/.exec(text.slice(at))![0].length + 1;
      const code = text.codePointAt(column - 1) ?? 0;
      const shown = code > 0x20 && code < 0x7f && code !== 0x22 ? `"${String.fromCodePoint(code)}"` : `U+${code.toString(16).toUpperCase().padStart(4, '0')}`;
      return failure(`${what} has a character it cannot use (${shown} at column ${column})`);
    }
    const name = match[2];
    if (name !== undefined && !names.has(name)) {
      if (DENSITY_NAMES.has(name)) return failure(`${what} uses ${name}, which only the density expression has`);
      return failure(`${what} uses an unknown name "${name.slice(0, 20)}" (use x y z, u v w, nx ny nz, k1 k2 H K curv${names.has('border') ? ', border' : ''}, pi e and the listed functions)`);
    }
    at = token.lastIndex;
  }
  return { ok: true, value: text };
}

// "ex, ey, ez": the density expression's token checks (without border), then exactly three components split at
// the commas outside brackets (those inside separate a function's arguments), none empty.
export function checkDirectionExpression(value: unknown): Checked<string> {
  const checked = checkExpression(value, 'Direction expression', DIRECTION_NAMES);
  if (!checked.ok) return checked;
  const text = checked.value;
  if (text === '') return failure('Direction expression is empty: write three components, e.g. -y, x, 0');
  const parts: string[] = [];
  let depth = 0;
  let start = 0;
  for (let i = 0; i <= text.length; i++) {
    const c = text[i];
    if (c === '(') depth++;
    else if (c === ')') depth--;
    else if (i === text.length || (c === ',' && depth === 0)) {
      parts.push(text.slice(start, i));
      start = i + 1;
    }
  }
  if (parts.length !== 3) return failure(`Direction expression needs three components separated by commas (x, y, z), e.g. -y, x, 0; it has ${parts.length}`);
  const empty = parts.findIndex((part) => part.trim() === '');
  if (empty >= 0) return failure(`Direction expression component ${empty + 1} (${'xyz'[empty]}) is empty`);
  return checked;
}

export function checkAnisotropy(value: unknown): Checked<Anisotropy> {
  if (!isRecord(value)) return failure('Anisotropy must be an object');
  for (const key of Object.keys(value)) if (key !== 'direction' && key !== 'stretch' && key !== 'expression') return failure(`anisotropy: unknown field "${key.slice(0, 40)}"`);
  if (!(ANISOTROPY_DIRECTIONS as readonly unknown[]).includes(value.direction)) return failure(`Anisotropy direction must be one of ${ANISOTROPY_DIRECTIONS.join(', ')}`);
  const stretch = checkNumber(value.stretch, 'Stretch', LIMITS.stretch);
  if (!stretch.ok) return stretch;
  const direction = value.direction as AnisotropyDirection;
  if (direction !== 'expression') {
    if ('expression' in value) return failure('anisotropy: an expression goes with the Expression direction only');
    return { ok: true, value: { direction, stretch: stretch.value } };
  }
  const expression = checkDirectionExpression(absentOr(value.expression, ''));
  if (!expression.ok) return expression;
  return { ok: true, value: { direction, stretch: stretch.value, expression: expression.value } };
}

export const WEIGHT_NAMES: readonly (keyof MetricWeights)[] = ['euclidean', 'l2', 'l21', 'boundary'];

export type Checked<T> = { ok: true; value: T } | { ok: false; message: string };

export function failure<T>(message: string): Checked<T> {
  return { ok: false, message };
}

// An optional field of a link or stored session: `fallback` when absent (made before the field
// existed). Only when absent: a null is checked as the value it is (and refused), not read as
// the default.
export function absentOr(value: unknown, fallback: unknown): unknown {
  return value === undefined ? fallback : value;
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
  const known = new Set(['panels', 'seed', 'weights', 'lloydIterations', 'panelRounds', 'retries', 'seeding', 'teleport', 'singlePointNodes', 'optimizePlanes', 'densityExpression', 'anisotropy', 'paint', 'glass', 'minCornerAngleDeg', 'coplanarAngleDeg', 'edits']);
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
  // Absent in links and sessions made before the control came to the page: the core's current
  // default, which such a page let the core apply (sending nothing). Links from before the
  // core's default became 8 solve with 8 now, as they would have on the old page today.
  const retries = value.retries === undefined ? { ok: true as const, value: DEFAULT_PARAMS.retries } : checkInteger(value.retries, 'Retries', LIMITS.retries);
  if (!retries.ok) return retries;
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
  // Absent in links and sessions made before the control came to the page: the core's default.
  const coplanar = value.coplanarAngleDeg === undefined ? { ok: true as const, value: DEFAULT_PARAMS.coplanarAngleDeg } : checkNumber(value.coplanarAngleDeg, 'Coplanar angle', LIMITS.coplanarAngleDeg);
  if (!coplanar.ok) return coplanar;
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
  // Absent in links and sessions made before density and anisotropy came to the page.
  const expression = checkExpression(absentOr(value.densityExpression, ''));
  if (!expression.ok) return expression;
  const anisotropy = checkAnisotropy(absentOr(value.anisotropy, DEFAULT_PARAMS.anisotropy));
  if (!anisotropy.ok) return anisotropy;
  const paint = absentOr(value.paint, '');
  if (typeof paint !== 'string' || (paint !== '' && !PAINT_KEY.test(paint))) return failure(`${where}: the density paint key is not valid`);
  // Absent in links and sessions made before panel edits came to the page.
  const edits = checkEdits(absentOr(value.edits, []));
  if (!edits.ok) return edits;
  return {
    ok: true,
    value: {
      panels: panels.value,
      seed: seed.value,
      weights,
      lloydIterations: lloyd.value,
      panelRounds: rounds.value,
      retries: retries.value,
      seeding: value.seeding,
      ...flags,
      densityExpression: expression.value,
      anisotropy: anisotropy.value,
      paint,
      glass: glass.value,
      minCornerAngleDeg: minAngle.value,
      coplanarAngleDeg: coplanar.value,
      edits: edits.value,
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

// The paint goes to the worker as a field of its own (protocol.ts, SolveStep); the expression
// and anisotropy only when set, so the JSON stays what a core without them reads.
// The edits only when there are some, so the JSON stays what a core without them reads.
export function toRemeshParams(params: DesignParams): RemeshParams & { edits?: PanelEdit[] } {
  return {
    panels: params.panels,
    seed: params.seed,
    weights: { ...params.weights },
    lloydIterations: params.lloydIterations,
    panelRounds: params.panelRounds,
    retries: params.retries,
    seeding: params.seeding,
    teleport: params.teleport,
    singlePointNodes: params.singlePointNodes,
    optimizePlanes: params.optimizePlanes,
    glass: params.glass,
    minCornerAngleDeg: params.minCornerAngleDeg,
    coplanarAngleDeg: params.coplanarAngleDeg,
    ...(params.densityExpression !== '' ? { densityExpression: params.densityExpression } : {}),
    ...(params.anisotropy.direction !== 'none' ? { anisotropy: { ...params.anisotropy } } : {}),
    ...(params.edits.length > 0 ? { edits: params.edits.map((edit) => ({ ...edit })) } : {}),
  };
}
