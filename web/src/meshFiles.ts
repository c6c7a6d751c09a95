// Turns what the designer opens into something the worker loads. OBJ, OFF, STL and PLY go to
// the core's own readers as bytes (so the page and the command line read a file identically);
// glTF/GLB goes through three.js and arrives as one triangle soup in world coordinates
// (gltfFile.ts); Rhino .3dm files become NURBS surfaces for the core's tessellation
// (web/src/rhino/).
import type { Example } from './examples.ts';
import { gltfPayload } from './gltfFile.ts';
import { failure, type Checked } from './params.ts';
import type { MeshPayload } from './protocol.ts';
import { rhinoPayload } from './rhino/rhinoOpen.ts';

const GLTF_EXTENSIONS = ['gltf', 'glb'];
export const ACCEPTED_EXTENSIONS = ['obj', 'off', 'stl', 'ply', ...GLTF_EXTENSIONS, '3dm'];

export function extensionOf(name: string): string {
  const dot = name.lastIndexOf('.');
  return dot < 0 ? '' : name.slice(dot + 1).toLowerCase();
}

export async function payloadFromFile(name: string, bytes: Uint8Array): Promise<Checked<MeshPayload>> {
  // The page's own readers (glTF through three.js, Rhino through rhino3dm) meet hostile files:
  // whatever one throws is a refusal of the file, never an open left "loading" for good.
  const onPage = async (read: () => Promise<Checked<MeshPayload>>, kind: string): Promise<Checked<MeshPayload>> => {
    try {
      return await read();
    } catch (error) {
      const reason = error instanceof Error ? error.message : String(error);
      return failure(`${name}: not a readable ${kind} file (${reason.slice(0, 160)})`);
    }
  };
  if (GLTF_EXTENSIONS.includes(extensionOf(name))) return onPage(() => gltfPayload(name, bytes), 'glTF');
  // Rhino: parsed on the page by rhino3dm, itself loaded on the first .3dm (web/src/rhino/).
  if (extensionOf(name) === '3dm') return onPage(() => rhinoPayload(name, bytes), 'Rhino');
  // An extension that names another kind of file (a photo, a PDF) is refused here: the core's
  // own message lists only the formats it reads itself. Without an extension the core reads
  // by content and names the problem when it cannot.
  const extension = extensionOf(name);
  if (extension !== '' && !ACCEPTED_EXTENSIONS.includes(extension)) {
    return failure(`${name}: not a mesh file this page reads (OBJ, OFF, STL, PLY, glTF/GLB or Rhino .3dm)`);
  }
  return { ok: true, value: { kind: 'bytes', name, bytes } };
}

export async function fetchExampleBytes(file: string): Promise<Checked<Uint8Array>> {
  try {
    const response = await fetch(new URL(`examples/${file}`, document.baseURI));
    if (!response.ok) return failure(`the example ${file} is not on this server (HTTP ${response.status})`);
    return { ok: true, value: new Uint8Array(await response.arrayBuffer()) };
  } catch (error) {
    return failure(`the example ${file} could not be fetched (${String(error)})`);
  }
}

// The example files this site ships (examples/index.json, written by
// web/scripts/copy_examples.mjs at build time). Without it, or without the shared meshes at
// build time, none: the page then offers only the generated examples.
export async function availableExampleFiles(): Promise<Set<string>> {
  try {
    const response = await fetch(new URL('examples/index.json', document.baseURI));
    if (!response.ok) return new Set();
    const list: unknown = await response.json();
    const files = typeof list === 'object' && list !== null && 'files' in list ? (list as { files: unknown }).files : null;
    return new Set(Array.isArray(files) ? files.filter((file): file is string => typeof file === 'string') : []);
  } catch {
    return new Set();
  }
}

export async function payloadFromExample(example: Example): Promise<Checked<MeshPayload>> {
  if (example.kind === 'shape') return { ok: true, value: { kind: 'shape', name: example.shape, triangles: example.triangles } };
  const bytes = await fetchExampleBytes(example.file);
  if (!bytes.ok) return bytes;
  return { ok: true, value: { kind: 'bytes', name: example.file, bytes: bytes.value } };
}
