// The last design in IndexedDB, so a reload loses nothing. Two stores: `meshes` holds the
// uploaded mesh's bytes once, under a key made of its name, size and a cheap hash, and is
// rewritten only when the mesh changes; `sessions` holds the small part (which mesh,
// parameters, warm-start history) and is rewritten after every load and solve. What is read
// back is checked like a share link (same validators), just with room for larger meshes.
import { findExample } from './examples.ts';
import { failure, type Checked } from './params.ts';
import { checkPaintFields, paintEntries } from './paintFields.ts';
import { repairJson, type MeshRepair } from './meshRepair.ts';
import { checkFileName, checkParamsAndHistory, decodePayload, prepareJson, MAX_SHARED_PAINT_BYTES, optionalFabrication, withMeshOptions, type DesignMesh, type DesignState, type MeshPrepare } from './share.ts';

const DB_NAME = 'flatfacet';
const DB_VERSION = 2;
const SESSIONS = 'sessions';
const MESHES = 'meshes';
const KEY = 'last';
export const MAX_STORED_MESH_BYTES = 128 * 1024 * 1024;
const RECORD_VERSION = 2;

// What `sessions` holds under KEY (version 1 of the page stored a share-link payload there).
interface SessionRecord {
  v: typeof RECORD_VERSION;
  mesh: ({ example: string } | { file: string; size: number; key: string }) & { prepare?: MeshPrepare; repair?: MeshRepair };
  params: unknown;
  history: unknown;
  fabrication?: unknown; // absent in sessions stored before fabrication came to the page
  paint?: unknown; // [{ key, bytes: Uint8Array }]: the painted density fields the params name
}

export type SaveOutcome = { ok: true } | { ok: false; message: string };
export type Restored = { kind: 'none' } | { kind: 'ok'; state: DesignState } | { kind: 'error'; message: string };

// FNV-1a over the whole file up to 8 MiB, else over 256 spread samples of 4 KiB: a key that
// tells re-saves of the same upload apart from a new one, without reading 100 MB each time.
export function meshKey(name: string, bytes: Uint8Array): string {
  let hash = 0x811c9dc5;
  const mix = (from: number, to: number): void => {
    for (let i = from; i < to; i++) hash = Math.imul(hash ^ bytes[i]!, 0x01000193);
  };
  const whole = 8 * 1024 * 1024;
  if (bytes.length <= whole) mix(0, bytes.length);
  else {
    const sample = 4096;
    const samples = 256;
    const stride = Math.floor((bytes.length - sample) / (samples - 1));
    for (let s = 0; s < samples; s++) mix(s * stride, s * stride + sample);
  }
  return `${name}:${bytes.length}:${(hash >>> 0).toString(16).padStart(8, '0')}`;
}

const keys = new WeakMap<Uint8Array, string>();
function keyOf(name: string, bytes: Uint8Array): string {
  let key = keys.get(bytes);
  if (key === undefined) {
    key = meshKey(name, bytes);
    keys.set(bytes, key);
  }
  return key;
}

function openDatabase(): Promise<IDBDatabase> {
  return new Promise((resolve, reject) => {
    const request = indexedDB.open(DB_NAME, DB_VERSION);
    request.onupgradeneeded = () => {
      const db = request.result;
      if (!db.objectStoreNames.contains(SESSIONS)) db.createObjectStore(SESSIONS);
      if (!db.objectStoreNames.contains(MESHES)) db.createObjectStore(MESHES);
    };
    // A tab still running the page's older version holds the database at version 1.
    request.onblocked = () => reject(new Error('another tab with an older version of this page is open'));
    request.onsuccess = () => {
      const db = request.result;
      db.onversionchange = () => db.close(); // never block a newer version in another tab
      resolve(db);
    };
    request.onerror = () => reject(request.error ?? new Error('IndexedDB open failed'));
  });
}

// Runs `body` in one transaction over both stores; resolves with its value once committed.
async function transaction<T>(mode: IDBTransactionMode, body: (sessions: IDBObjectStore, meshes: IDBObjectStore, done: (value: T) => void) => void): Promise<T> {
  const db = await openDatabase();
  return new Promise<T>((resolve, reject) => {
    const tx = db.transaction([SESSIONS, MESHES], mode);
    let value: T | undefined;
    let set = false;
    tx.oncomplete = () => {
      db.close();
      if (set) resolve(value as T);
      else reject(new Error('IndexedDB transaction ended without a result'));
    };
    tx.onerror = tx.onabort = () => {
      db.close();
      reject(tx.error ?? new Error('IndexedDB transaction failed'));
    };
    body(tx.objectStore(SESSIONS), tx.objectStore(MESHES), (result) => {
      value = result;
      set = true;
    });
  });
}

// The key of the mesh this page last wrote (or found already stored): the bytes are not
// written again while it stays the same.
let storedMeshKey: string | null = null;

// Failures cost only the convenience, never the design in the page; the caller shows them.
export async function saveSession(state: DesignState): Promise<SaveOutcome> {
  const mesh = state.mesh;
  if (mesh.kind === 'file' && mesh.bytes.length > MAX_STORED_MESH_BYTES) {
    return failure(`${mesh.name} is too large to keep in this browser (over ${MAX_STORED_MESH_BYTES / 1048576} MB): a reload will not bring it back`);
  }
  const key = mesh.kind === 'file' ? keyOf(mesh.name, mesh.bytes) : null;
  const record: SessionRecord = {
    v: RECORD_VERSION,
    mesh: { ...(mesh.kind === 'example' ? { example: mesh.id } : { file: mesh.name, size: mesh.bytes.length, key: key! }), ...prepareJson(mesh), ...repairJson(mesh) },
    params: state.params,
    history: state.history,
    ...(state.fabrication ? { fabrication: state.fabrication } : {}),
  };
  try {
    const paint = paintEntries(state.params, state.history, state.paint);
    if (paint.length > 0) record.paint = paint.map(({ key, field }) => ({ key, bytes: new Uint8Array(field.buffer, field.byteOffset, field.length) }));
  } catch (error) {
    return failure(`this browser did not keep the session (${error instanceof Error ? error.message : String(error)}): a reload will not bring it back`);
  }
  try {
    await transaction<boolean>('readwrite', (sessions, meshes, done) => {
      sessions.put(record, KEY);
      if (mesh.kind !== 'file' || key === storedMeshKey) {
        done(true);
        return;
      }
      const existing = meshes.getKey(key!);
      existing.onsuccess = () => {
        if (existing.result === undefined) {
          meshes.clear(); // one mesh kept: the current design's
          meshes.put(mesh.bytes, key!);
        }
        done(true);
      };
    });
    storedMeshKey = key ?? storedMeshKey;
    return { ok: true };
  } catch (error) {
    return failure(`this browser did not keep the session (${error instanceof Error ? error.message : String(error)}): a reload will not bring it back`);
  }
}

function isRecord(value: unknown): value is Record<string, unknown> {
  return typeof value === 'object' && value !== null && !Array.isArray(value);
}

function checkRecord(record: unknown, meshBytes: unknown): Checked<DesignState> {
  if (!isRecord(record) || record.v !== RECORD_VERSION || !isRecord(record.mesh)) return failure('it is not in a format this page reads');
  const meshValue = record.mesh;
  let mesh: DesignMesh;
  if (typeof meshValue.example === 'string') {
    const example = findExample(meshValue.example);
    if (!example) return failure(`it names an unknown example "${meshValue.example.slice(0, 40)}"`);
    mesh = { kind: 'example', id: example.id };
  } else {
    const name = checkFileName(meshValue.file);
    if (!name.ok) return name;
    if (!(meshBytes instanceof Uint8Array)) return failure(`the mesh ${name.value} is missing from the browser's storage`);
    if (meshBytes.length !== meshValue.size) return failure(`the mesh ${name.value} in the browser's storage is damaged`);
    mesh = { kind: 'file', name: name.value, bytes: meshBytes };
  }
  const options = withMeshOptions(mesh, meshValue, 'in the stored session');
  if (!options.ok) return options;
  mesh = options.value;
  const checked = checkParamsAndHistory(record.params, record.history, 'the stored session');
  if (!checked.ok) return checked;
  const fabrication = optionalFabrication(record.fabrication, 'the stored session');
  if (!fabrication.ok) return fabrication;
  const paintList = record.paint ?? [];
  if (!Array.isArray(paintList) || !paintList.every((e) => isRecord(e) && typeof e.key === 'string' && e.bytes instanceof Uint8Array)) return failure('its density paint is damaged');
  const paint = checkPaintFields(paintList as { key: string; bytes: Uint8Array }[], checked.value.params, checked.value.history, 'the stored session');
  if (!paint.ok) return paint;
  return { ok: true, value: { mesh, ...checked.value, ...fabrication.value, ...paint.value } };
}

export async function loadSession(): Promise<Restored> {
  let found: { record: unknown; meshBytes: unknown };
  try {
    found = await transaction('readonly', (sessions, meshes, done: (value: { record: unknown; meshBytes: unknown }) => void) => {
      const request = sessions.get(KEY);
      request.onsuccess = () => {
        const record: unknown = request.result;
        const meshValue = isRecord(record) && isRecord(record.mesh) ? record.mesh : null;
        if (meshValue && typeof meshValue.key === 'string') {
          const bytes = meshes.get(meshValue.key);
          bytes.onsuccess = () => done({ record, meshBytes: bytes.result });
        } else done({ record, meshBytes: undefined });
      };
    });
  } catch (error) {
    return { kind: 'error', message: `the last session could not be read from this browser (${error instanceof Error ? error.message : String(error)})` };
  }
  if (found.record === undefined) return { kind: 'none' };
  // Version 1 of the page stored the share-link payload itself.
  const checked = found.record instanceof Uint8Array ? decodePayload(found.record, { maxMeshBytes: MAX_STORED_MESH_BYTES, maxPaintBytes: MAX_SHARED_PAINT_BYTES }) : checkRecord(found.record, found.meshBytes);
  if (!checked.ok) return { kind: 'error', message: `the last session kept in this browser cannot be restored: ${checked.message}` };
  const record = found.record;
  if (checked.value.mesh.kind === 'file' && isRecord(record) && isRecord(record.mesh) && typeof record.mesh.key === 'string') {
    keys.set(checked.value.mesh.bytes, record.mesh.key); // already stored under this key
    storedMeshKey = record.mesh.key;
  }
  return { kind: 'ok', state: checked.value };
}
