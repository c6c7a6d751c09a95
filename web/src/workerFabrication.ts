// The worker's side of fabrication: sets the settings on the session and collects every
// output. A Status with ok false from any call becomes a message, never a crash; an exception
// (out of memory, a trap) still propagates to the worker's crash handling.
import type { Session, SheetStats, SpreadNodes, Status } from '@flatfacet/wasm';
import type { FabricationResult } from './protocol.ts';

type Outcome<T> = { ok: true; value: T } | { ok: false; message: string };

// A CSV, SVG, DXF or OBJ never starts with '{'; a Status does.
function text(answer: string): Outcome<string> {
  if (!answer.startsWith('{')) return { ok: true, value: answer };
  const status = JSON.parse(answer) as Status;
  return { ok: false, message: status.message || 'failed' };
}

// A Status-shaped answer, or a document (the parts list JSON) that has no `ok` unless it failed.
function json<T>(answer: string): Outcome<T> {
  const parsed = JSON.parse(answer) as T & Partial<Status>;
  return parsed.ok === false ? { ok: false, message: parsed.message || 'failed' } : { ok: true, value: parsed };
}

export function fabricationOf(session: Session, settingsJson: string): Outcome<FabricationResult> {
  const set = json<Status>(session.setFabrication(settingsJson));
  if (!set.ok) return set;
  const partsCsv = text(session.partsCsv());
  if (!partsCsv.ok) return partsCsv;
  const partsJsonText = session.partsJson();
  const partsJson = json<object>(partsJsonText);
  if (!partsJson.ok) return partsJson;
  const spread = json<SpreadNodes>(session.spreadNodes());
  if (!spread.ok) return spread;
  const svg = text(session.sheetsSvg());
  const dxf = text(session.sheetsDxf());
  const stats = json<SheetStats>(session.sheetStats());
  const sheets: FabricationResult['sheets'] =
    svg.ok && dxf.ok && stats.ok ? { ok: true, svg: svg.value, dxf: dxf.value, stats: stats.value } : { ok: false, message: !svg.ok ? svg.message : !dxf.ok ? dxf.message : !stats.ok ? stats.message : '' };
  const solid = spread.value.thickness > 0 ? text(session.solidObj()) : null;
  return {
    ok: true,
    value: {
      partsCsv: partsCsv.value,
      partsJson: partsJsonText,
      sheets,
      solidObj: solid && solid.ok ? solid.value : null,
      innerPositions: session.innerPositions(),
      spread: spread.value,
    },
  };
}
