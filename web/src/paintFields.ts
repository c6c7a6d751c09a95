// The painted density fields of a design as they travel in share links and the stored
// session: each field once, under its content key (brush/densityField.ts), for the keys the
// parameters and their warm-start history name. Checked like everything else from outside:
// sizes bounded, levels in range, each field hashing to its key, no field missing or extra.
// No DOM: unit-tested in Node.
import { fieldProblem } from './brush/densityField.ts';
import { failure, isRecord, type Checked, type DesignParams } from './params.ts';

export type PaintFields = ReadonlyMap<string, Int8Array>;

// A design names at most this many fields (parameters + a warm-start history of 8).
export const MAX_PAINT_FIELDS = 16;
// Vertices of one field: far more than a link can carry; the stored session's meshes (128 MB)
// stay well under it.
export const MAX_PAINT_VERTICES = 8_000_000;

export interface PaintEntry {
  key: string;
  field: Int8Array;
}

// The keys `params` and `history` name, each once, in order of first use.
export function paintKeys(params: DesignParams, history: readonly DesignParams[]): string[] {
  const keys: string[] = [];
  for (const p of [...history, params]) if (p.paint !== '' && !keys.includes(p.paint)) keys.push(p.paint);
  return keys;
}

// The fields a design needs, from `fields`; throws if one is missing (the page keeps every
// field its parameters name, so that is a bug, not bad input).
export function paintEntries(params: DesignParams, history: readonly DesignParams[], fields: PaintFields | undefined): PaintEntry[] {
  return paintKeys(params, history).map((key) => {
    const field = fields?.get(key);
    if (!field) throw new Error(`the density paint ${key} is missing`);
    return { key, field };
  });
}

// A link's JSON table: [{ key, vertices }], the fields' bytes following in that order.
export function checkPaintTable(value: unknown, where: string): Checked<{ key: string; vertices: number }[]> {
  if (value === undefined) return { ok: true, value: [] };
  if (!Array.isArray(value) || value.length > MAX_PAINT_FIELDS) return failure(`${where} is damaged (bad density paint list)`);
  const table: { key: string; vertices: number }[] = [];
  for (const entry of value) {
    if (!isRecord(entry) || Object.keys(entry).some((k) => k !== 'key' && k !== 'vertices')) return failure(`${where} is damaged (bad density paint entry)`);
    const { key, vertices } = entry;
    if (typeof key !== 'string' || !/^[0-9a-f]{16}$/.test(key)) return failure(`${where} is damaged (bad density paint key)`);
    if (typeof vertices !== 'number' || !Number.isInteger(vertices) || vertices < 1 || vertices > MAX_PAINT_VERTICES) {
      return failure(`${where}'s density paint has a size outside 1 .. ${MAX_PAINT_VERTICES.toLocaleString('en')} vertices`);
    }
    table.push({ key, vertices });
  }
  return { ok: true, value: table };
}

// The fields of a link or stored session against the parameters that name them.
export function checkPaintFields(entries: readonly { key: string; bytes: Uint8Array }[], params: DesignParams, history: readonly DesignParams[], where: string): Checked<{ paint?: PaintFields }> {
  const keys = paintKeys(params, history);
  if (entries.length !== keys.length) return failure(`${where} is damaged (its density paint does not match its parameters)`);
  const paint = new Map<string, Int8Array>();
  for (const { key, bytes } of entries) {
    if (!keys.includes(key) || paint.has(key)) return failure(`${where} is damaged (its density paint does not match its parameters)`);
    if (bytes.length !== entries[0]!.bytes.length) return failure(`${where} is damaged (its density paint fields differ in size)`);
    const problem = fieldProblem(bytes, key);
    if (problem) return failure(`${where}'s density paint is damaged: ${problem}`);
    paint.set(key, new Int8Array(bytes.slice().buffer));
  }
  return { ok: true, value: paint.size > 0 ? { paint } : {} };
}
