// Rhino .3dm files on the page: rhino3dm (a 2.6 MB wasm) is loaded only when the first one is
// opened; the file is parsed here, its objects listed in the "Rhino object" select, and the
// chosen object (or all of them, joined) turned into surfaces for the worker
// (rhinoConvert.ts). Picking another object opens the same file again with that pick in its
// name ("campus [Roof].3dm"), so share links and the stored session reproduce it. The note
// under the select says what was prepared, and, once the worker has tessellated and cleaned
// it, into how many triangles and whether the pieces joined.
/// <reference path="./rhinoModules.d.ts" />
import type { MeshInfo, SurfacesInfo } from '@flatfacet/wasm';
import type * as Rhino from 'rhino3dm';
import { element } from '../dom.ts';
import { failure, type Checked } from '../params.ts';
import type { MeshPayload } from '../protocol.ts';
import { free, listRhinoObjects, prepareRhino, type RhinoModule } from './rhinoConvert.ts';

// Triangles the surfaces are tessellated into (spread over their area by one edge length):
// plenty for hundreds of panels, quick to cluster.
export const RHINO_TARGET_TRIANGLES = 30_000;

let modulePromise: Promise<RhinoModule> | null = null;
let reopen: ((file: File) => void) | null = null;
let lastFile: { name: string; bytes: Uint8Array; names: Map<number, string> } | null = null;
let pendingNotes: { name: string; notes: string[] } | null = null;

export function isRhinoFile(name: string): boolean {
  return /\.3dm$/i.test(name);
}

async function loadRhino(): Promise<RhinoModule> {
  if (!modulePromise) {
    modulePromise = (async () => {
      const started = performance.now();
      const [{ default: rhino3dm }, { default: wasmUrl }] = await Promise.all([import('rhino3dm/rhino3dm.module.js'), import('rhino3dm/rhino3dm.wasm?url')]);
      const rh = await rhino3dm({ locateFile: (path: string) => (path.endsWith('.wasm') ? wasmUrl : path) });
      document.body.dataset.rhinoLoadMs = String(Math.round(performance.now() - started));
      return rh;
    })();
    modulePromise.catch(() => {
      modulePromise = null; // try again with the next file
    });
  }
  return modulePromise;
}

// Called once from main.ts: how the "Use object" button opens the file again.
export function bindRhinoPicker(open: (file: File) => void): void {
  reopen = open;
  element('rhino-use', HTMLButtonElement).addEventListener('click', () => {
    if (!lastFile || !reopen) return;
    const value = element('rhino-object', HTMLSelectElement).value;
    const base = splitPick(lastFile.name).base;
    const picked = value === 'all' ? undefined : lastFile.names.get(Number(value));
    const name = picked === undefined ? base : `${base.replace(/\.3dm$/i, '')} [${picked}].3dm`;
    reopen(new File([lastFile.bytes as Uint8Array<ArrayBuffer>], name));
  });
}

// "campus [Roof].3dm" -> the file "campus.3dm" and the object named "Roof"; no brackets: all.
export function splitPick(name: string): { base: string; object: string | null } {
  const match = /^(.*) \[([^\]]+)\]\.3dm$/i.exec(name);
  return match ? { base: `${match[1]}.3dm`, object: match[2]! } : { base: name, object: null };
}

function showPicker(objects: ReturnType<typeof listRhinoObjects>, pick: number | 'all'): void {
  const select = element('rhino-object', HTMLSelectElement);
  select.replaceChildren();
  const usable = objects.filter((o) => o.supported);
  if (usable.length > 1) select.add(new Option(`All (joined): ${usable.length} objects`, 'all'));
  for (const o of objects) {
    const option = new Option(`${o.name} — ${o.type}`, String(o.index));
    option.disabled = !o.supported;
    select.add(option);
  }
  select.value = String(pick);
  element('rhino-row', HTMLDivElement).hidden = false;
}

function showNote(text: string): void {
  const note = element('rhino-note', HTMLParagraphElement);
  note.textContent = text;
  note.hidden = text === '';
}

export async function rhinoPayload(name: string, bytes: Uint8Array): Promise<Checked<MeshPayload>> {
  let rh: RhinoModule;
  try {
    rh = await loadRhino();
  } catch (error) {
    return failure(`Rhino files cannot be read here: rhino3dm did not load (${String(error).slice(0, 120)})`);
  }
  const doc: Rhino.File3dm | null = rh.File3dm.fromByteArray(bytes);
  if (!doc) return failure(`${name}: not a readable Rhino file (rhino3dm could not parse it)`);
  try {
    const objects = listRhinoObjects(rh, doc);
    const usable = objects.filter((o) => o.supported);
    const wanted = splitPick(name).object;
    // By name (brackets cannot be in it: they delimit it); the first of equal names.
    const named = wanted === null ? undefined : usable.find((o) => o.name.replace(/[[\]]/g, '') === wanted);
    if (wanted !== null && !named) return failure(`${name}: the file has no surface object named "${wanted}"`);
    const pick: number | 'all' = named ? named.index : usable.length === 1 ? usable[0]!.index : 'all';
    lastFile = { name, bytes, names: new Map(usable.map((o) => [o.index, o.name.replace(/[[\]]/g, '')])) };
    showPicker(objects, pick);
    const prepared = prepareRhino(rh, doc, name, pick, RHINO_TARGET_TRIANGLES);
    if (!prepared.ok) {
      showNote(prepared.message);
      return prepared;
    }
    const p = prepared.value;
    pendingNotes = { name, notes: p.notes };
    showNote(`Preparing ${name}: ${p.notes.join('; ')}.`);
    return { ok: true, value: { kind: 'surfaces', name, surfacesJson: JSON.stringify(p.set), positions: p.positions, indices: p.indices } };
  } finally {
    free(doc);
  }
}

// What the worker made of it (app.ts, when a mesh has loaded): triangle counts per surface
// and whether the pieces joined. Any other mesh hides the picker.
export function rhinoLoaded(name: string, info: MeshInfo): void {
  if (!isRhinoFile(name) || !pendingNotes || pendingNotes.name !== name) {
    if (!isRhinoFile(name)) {
      element('rhino-row', HTMLDivElement).hidden = true;
      showNote('');
      lastFile = null;
    }
    return;
  }
  const surfaces = (info as Partial<SurfacesInfo>).surfaces ?? [];
  const parts: string[] = [];
  for (const s of surfaces) parts.push(`tessellated NURBS surface ${s.name} into ${s.triangles.toLocaleString('en')} triangles (${s.samplesU} × ${s.samplesV} grid)`);
  const edge = (info as Partial<SurfacesInfo>).edgeLength;
  if (surfaces.length > 0 && edge !== undefined) parts.push(`target edge ${edge.toPrecision(3)} (about ${RHINO_TARGET_TRIANGLES.toLocaleString('en')} triangles in all)`);
  const notes = pendingNotes.notes.filter((n) => !/NURBS surface tessellated$/.test(n));
  parts.push(...notes);
  parts.push(info.components === 1 ? `one connected surface of ${info.triangles.toLocaleString('en')} triangles` : `the pieces did not all join: ${info.components} separate parts (no shared edges within the file's tolerance); they are panelled apart`);
  pendingNotes = null;
  showNote(`Prepared from ${name}: ${parts.join('; ')}.`);
}
