// The last design (mesh and parameters) in IndexedDB, so a reload loses nothing. Stored in
// the share-link payload format, uncompressed (saving must not stall the page on a large
// upload), and decoded with the same checks as a link, just with room for larger meshes.
import { decodePayload, encodePayload, type DesignState } from './share.ts';

const DB_NAME = 'flatfacet';
const STORE = 'sessions';
const KEY = 'last';
const MAX_STORED_MESH_BYTES = 256 * 1024 * 1024;

function openDatabase(): Promise<IDBDatabase> {
  return new Promise((resolve, reject) => {
    const request = indexedDB.open(DB_NAME, 1);
    request.onupgradeneeded = () => request.result.createObjectStore(STORE);
    request.onsuccess = () => resolve(request.result);
    request.onerror = () => reject(request.error ?? new Error('IndexedDB open failed'));
  });
}

function run<T>(mode: IDBTransactionMode, action: (store: IDBObjectStore) => IDBRequest<T>): Promise<T> {
  return openDatabase().then(
    (db) =>
      new Promise<T>((resolve, reject) => {
        const transaction = db.transaction(STORE, mode);
        const request = action(transaction.objectStore(STORE));
        transaction.oncomplete = () => {
          db.close();
          resolve(request.result);
        };
        transaction.onerror = transaction.onabort = () => {
          db.close();
          reject(transaction.error ?? new Error('IndexedDB transaction failed'));
        };
      }),
  );
}

// Failures only cost the convenience, never the design in the page: they are logged, not shown.
export async function saveSession(state: DesignState): Promise<void> {
  try {
    await run('readwrite', (store) => store.put(encodePayload(state), KEY));
  } catch (error) {
    console.warn('flatfacet: could not keep the session in this browser', error);
  }
}

export async function loadSession(): Promise<DesignState | null> {
  try {
    const stored: unknown = await run('readonly', (store) => store.get(KEY));
    if (!(stored instanceof Uint8Array)) return null;
    const decoded = decodePayload(stored, { maxMeshBytes: MAX_STORED_MESH_BYTES });
    if (!decoded.ok) {
      console.warn(`flatfacet: the stored session is not usable: ${decoded.message}`);
      return null;
    }
    return decoded.value;
  } catch (error) {
    console.warn('flatfacet: could not read the stored session', error);
    return null;
  }
}
