// Share links (DESIGN.md 4): the design in the URL hash, never sent to a server.
//
//   #v1=<base64url( zlib( u32 json length | JSON | mesh file bytes | density paint bytes ) )>
//
// JSON: { v: 1, mesh: { example } | { file, size }, params, history, fabrication?, paint? }.
// `paint` (optional) lists the painted density fields the parameters name ([{ key, vertices }],
// paintFields.ts), their bytes (one level per vertex) after the mesh's, in that order. `history` lists the
// earlier solves of a warm-start chain; replaying history then params from the loaded mesh
// gives the identical panels. An uploaded mesh travels as its file bytes, as long as the whole
// hash stays under MAX_LINK_HASH_CHARS (Chromium refuses URLs over 2 MiB characters).
// Decoding treats the link as hostile: its length capped, inflation capped as it goes, the
// zlib checksum and the stream's end checked, every field checked by hand, nothing evaluated.
// No DOM: unit-tested in Node.
import { Unzlib, zlibSync } from 'fflate';
import { decodeBase64url, encodeBase64url } from './base64url.ts';
import { findExample } from './examples.ts';
import { fabricationOrDefault, type FabricationSettings } from './fabricationParams.ts';
import { checkRepair, repairJson, type MeshRepair } from './meshRepair.ts';
import { checkPaintFields, checkPaintTable, paintEntries, type PaintFields } from './paintFields.ts';
import { absentOr, failure, LIMITS, validateParams, type Checked, type DesignParams } from './params.ts';

export const SHARE_VERSION = 1;
// The hash, "#v1=" included: Chromium's URL limit is 2,097,152 characters, and the page's own
// address comes in front of the hash.
export const MAX_LINK_HASH_CHARS = 1_900_000;
// What a link can unpack to: a hash of MAX_LINK_HASH_CHARS holds ~1.4 MB compressed, and mesh
// files compress 3-6x; beyond this a mesh cannot travel in a link, so it is not even tried.
export const MAX_SHARED_MESH_BYTES = 8 * 1024 * 1024;
export const LINK_TOO_LARGE = 'the mesh is too large to travel in a link; share an example or a smaller file';
export const MAX_HISTORY = 8;
// The settings' JSON: the largest design (MAX_EDITS panel edits in each of the parameters and
// the MAX_HISTORY steps before them, about 0.3 MB each) fits, which compresses to little.
const MAX_JSON_BYTES = 4 * 1024 * 1024;
// A link's fields, and its mesh's (an example or a file, each with its preparation and repair):
// a link from a newer version must not half-apply, as in the parameters (params.ts).
const LINK_FIELDS = ['v', 'mesh', 'params', 'history', 'fabrication', 'paint'];
const EXAMPLE_MESH_FIELDS = ['example', 'prepare', 'repair'];
const FILE_MESH_FIELDS = ['file', 'size', 'prepare', 'repair'];
const MAX_FILE_NAME = 200;
const HASH_PREFIX = `v${SHARE_VERSION}=`;

// How the loaded mesh was prepared for panelling (Session.prepare): subdivision levels, the
// panel count the resolution was chosen for, and the target edge length when the designer set
// one (absent: automatic). Recorded when the mesh is opened or prepared again for a panel
// count it could not serve (preparation.ts), so a link or a reload prepares the very same mesh;
// absent (links made before this): the mesh as loaded.
export interface MeshPrepare {
  panels: number;
  subdivide: number;
  edgeLength?: number;
  // The triangles per panel below which the mesh was refined for `panels` (Session.prepare):
  // recorded since the core's rule went from 20 to 30. A design without it (saved before)
  // keeps the rule it was made with, LEGACY_REFINE_BELOW, so its edits and paint still name
  // the triangles and vertices of its mesh.
  refineBelow?: number;
  // The remeshing rounds of a refinement below 20 per panel (Session.prepare): recorded since
  // they went from 10 to 5. A design without it keeps LEGACY_REFINE_ROUNDS, for the same reason.
  refineRounds?: number;
}
export const LEGACY_REFINE_BELOW = 20;
export const MAX_REFINE_BELOW = 50;
export const LEGACY_REFINE_ROUNDS = 10;
export const MAX_REFINE_ROUNDS = 10;
export const MAX_SUBDIVIDE = 4;
// A target edge length, in mesh units: positive, finite, and not absurd (the core refuses one
// that would make more than its triangle cap with its own message).
export const MAX_EDGE_LENGTH = 1e12;

// repair: how the mesh was repaired on opening (meshRepair.ts); absent: no repair asked.
export type DesignMesh = ({ kind: 'example'; id: string } | { kind: 'file'; name: string; bytes: Uint8Array }) & { prepare?: MeshPrepare; repair?: MeshRepair };

export function isEdgeLength(value: unknown): value is number {
  return typeof value === 'number' && Number.isFinite(value) && value > 0 && value <= MAX_EDGE_LENGTH;
}

const PREPARE_KEYS = ['panels', 'subdivide', 'edgeLength', 'refineBelow', 'refineRounds'];

// A mesh's preparation from a link or the stored session: absent, or exactly {panels,
// subdivide} with an optional edgeLength, refineBelow and refineRounds.
export function checkPrepare(value: unknown, where: string): Checked<MeshPrepare | undefined> {
  if (value === undefined) return { ok: true, value: undefined };
  if (!isRecord(value)) return failure(`${where}: the mesh's preparation is not an object`);
  for (const key of Object.keys(value)) if (!PREPARE_KEYS.includes(key)) return failure(`${where}: the mesh's preparation has an unknown field "${key.slice(0, 40)}"`);
  const { panels, subdivide, edgeLength, refineBelow, refineRounds } = value;
  if (typeof panels !== 'number' || !Number.isInteger(panels) || panels < LIMITS.panels.min || panels > LIMITS.panels.max) return failure(`${where}: the mesh's preparation names no valid panel count`);
  if (typeof subdivide !== 'number' || !Number.isInteger(subdivide) || subdivide < 0 || subdivide > MAX_SUBDIVIDE) return failure(`${where}: subdivision levels must be 0 to ${MAX_SUBDIVIDE}`);
  if (edgeLength !== undefined && !isEdgeLength(edgeLength)) return failure(`${where}: the target edge length must be a positive number up to ${MAX_EDGE_LENGTH}`);
  if (refineBelow !== undefined && (typeof refineBelow !== 'number' || !Number.isInteger(refineBelow) || refineBelow < LEGACY_REFINE_BELOW || refineBelow > MAX_REFINE_BELOW)) {
    return failure(`${where}: the mesh's preparation must refine below ${LEGACY_REFINE_BELOW} to ${MAX_REFINE_BELOW} triangles per panel`);
  }
  if (refineRounds !== undefined && (typeof refineRounds !== 'number' || !Number.isInteger(refineRounds) || refineRounds < 1 || refineRounds > MAX_REFINE_ROUNDS)) {
    return failure(`${where}: the mesh's preparation must refine in 1 to ${MAX_REFINE_ROUNDS} remeshing rounds`);
  }
  return { ok: true, value: prepareInOrder({ panels, subdivide, edgeLength, refineBelow, refineRounds }) };
}
// The preparation with its keys in one order and the absent ones left out (links and the
// stored session compare as text).
function prepareInOrder(p: MeshPrepare): MeshPrepare {
  return {
    panels: p.panels,
    subdivide: p.subdivide,
    ...(p.edgeLength !== undefined ? { edgeLength: p.edgeLength } : {}),
    ...(p.refineBelow !== undefined ? { refineBelow: p.refineBelow } : {}),
    ...(p.refineRounds !== undefined ? { refineRounds: p.refineRounds } : {}),
  };
}

// The mesh of a link or the stored session with the preparation and repair its record
// names (checked; each left out when the record has none).
export function withMeshOptions(mesh: DesignMesh, meshValue: Record<string, unknown>, where: string): Checked<DesignMesh> {
  const prepare = checkPrepare(meshValue.prepare, where);
  if (!prepare.ok) return prepare;
  const repair = checkRepair(meshValue.repair, where);
  if (!repair.ok) return repair;
  return { ok: true, value: { ...mesh, ...(prepare.value ? { prepare: prepare.value } : {}), ...(repair.value ? { repair: repair.value } : {}) } };
}

// The preparation as JSON, keys in one order (links and the stored session compare as text).
export function prepareJson(mesh: DesignMesh): { prepare?: MeshPrepare } {
  const p = mesh.prepare;
  if (!p) return {};
  return { prepare: prepareInOrder(p) };
}

export interface DesignState {
  mesh: DesignMesh;
  params: DesignParams;
  history: DesignParams[];
  // Absent in links and stored sessions made before fabrication came to the page: the defaults.
  fabrication?: FabricationSettings;
  // The painted density fields `params` and `history` name (absent: none painted).
  paint?: PaintFields;
}

export interface DecodeLimits {
  maxMeshBytes: number;
  maxPaintBytes: number; // all fields together
}

// The painted fields a link carries (one byte per vertex and field): the fields of a warm-start
// chain on a mesh of ~200k vertices; bounds what a hostile link makes the page inflate.
export const MAX_SHARED_PAINT_BYTES = 2 * 1024 * 1024;
export const PAINT_TOO_LARGE = 'the density paint is too large to travel in a link (too many painted steps on a large mesh); clear the paint or remesh afresh first';
export const LINK_LIMITS: DecodeLimits = { maxMeshBytes: MAX_SHARED_MESH_BYTES, maxPaintBytes: MAX_SHARED_PAINT_BYTES };

function isRecord(value: unknown): value is Record<string, unknown> {
  return typeof value === 'object' && value !== null && !Array.isArray(value);
}

// File names come back into the page as text only; still keep them plain and short.
export function checkFileName(value: unknown): Checked<string> {
  if (typeof value !== 'string' || value.length === 0 || value.length > MAX_FILE_NAME) return failure('the mesh file name is missing or too long');
  if (/[\u0000-\u001f\u007f/\\]/.test(value)) return failure('the mesh file name has characters a file name cannot have');
  return { ok: true, value };
}

// The binary payload (before compression).
export function encodePayload(state: DesignState): Uint8Array {
  const meshJson = { ...(state.mesh.kind === 'example' ? { example: state.mesh.id } : { file: state.mesh.name, size: state.mesh.bytes.length }), ...prepareJson(state.mesh), ...repairJson(state.mesh) };
  const paint = paintEntries(state.params, state.history, state.paint);
  const paintJson = paint.length > 0 ? { paint: paint.map(({ key, field }) => ({ key, vertices: field.length })) } : {};
  const json = new TextEncoder().encode(JSON.stringify({ v: SHARE_VERSION, mesh: meshJson, params: state.params, history: state.history, ...(state.fabrication ? { fabrication: state.fabrication } : {}), ...paintJson }));
  const fileBytes = state.mesh.kind === 'file' ? state.mesh.bytes : new Uint8Array(0);
  const paintBytes = paint.reduce((sum, { field }) => sum + field.length, 0);
  const out = new Uint8Array(4 + json.length + fileBytes.length + paintBytes);
  new DataView(out.buffer).setUint32(0, json.length, true);
  out.set(json, 4);
  out.set(fileBytes, 4 + json.length);
  let offset = 4 + json.length + fileBytes.length;
  for (const { field } of paint) {
    out.set(new Uint8Array(field.buffer, field.byteOffset, field.length), offset);
    offset += field.length;
  }
  return out;
}

export function encodeState(state: DesignState): Uint8Array {
  return compressPayload(encodePayload(state));
}

function compressPayload(payload: Uint8Array): Uint8Array {
  return zlibSync(payload, { level: 9 });
}

// Adler-32 (RFC 1950), updated piece by piece; fflate's streaming Unzlib does not check it.
export function adler32(data: Uint8Array, previous = 1): number {
  let a = previous & 0xffff;
  let b = previous >>> 16;
  for (let i = 0; i < data.length; ) {
    const end = Math.min(i + 5552, data.length); // the most bytes before the sums can overflow
    for (; i < end; i++) {
      a += data[i]!;
      b += a;
    }
    a %= 65521;
    b %= 65521;
  }
  return ((b << 16) | a) >>> 0;
}

function runInflater(compressed: Uint8Array, cap: number, onPiece: (piece: Uint8Array) => void): 'ok' | 'over' | 'damaged' {
  let total = 0;
  let overCap = false;
  const inflater = new Unzlib((piece) => {
    total += piece.length;
    if (total > cap) overCap = true;
    else onPiece(piece);
  });
  const step = 4096;
  try {
    for (let i = 0; i < compressed.length && !overCap; i += step) {
      const end = Math.min(i + step, compressed.length);
      inflater.push(compressed.subarray(i, end), end === compressed.length);
    }
  } catch {
    return 'damaged';
  }
  return overCap ? 'over' : 'ok';
}

// Inflates a zlib stream in small pieces and stops as soon as the output passes `cap`: a
// deflate bomb costs at most one piece beyond the cap (deflate expands at most ~1032x). Then
// checks what fflate does not: the Adler-32 of the output against the stream's last four
// bytes, and that the deflate data ends exactly before them (no bytes after the stream's end).
export function inflateCapped(compressed: Uint8Array, cap: number): Checked<Uint8Array> {
  if (compressed.length === 0) return failure('the link is empty');
  const damaged = failure<Uint8Array>('the link is damaged (its compressed data is not valid)');
  const pieces: Uint8Array[] = [];
  let total = 0;
  let checksum = 1;
  const outcome = runInflater(compressed, cap, (piece) => {
    pieces.push(piece);
    total += piece.length;
    checksum = adler32(piece, checksum);
  });
  if (outcome === 'over') return failure(`the link unpacks to more than ${Math.round(cap / 1024)} KiB, more than any design needs`);
  if (outcome === 'damaged' || compressed.length < 6) return damaged;
  const n = compressed.length;
  const stored = ((compressed[n - 4]! << 24) | (compressed[n - 3]! << 16) | (compressed[n - 2]! << 8) | compressed[n - 1]!) >>> 0;
  if (stored !== checksum) return failure('the link is damaged (its checksum does not match: it was cut or altered)');
  // The deflate stream's last byte always holds bits of its final block, so without that byte
  // a stream that ends where it should cannot be read. If it still can, data follows the
  // stream (the checksum test above passes only if that data ends with a copy of it).
  if (runInflater(compressed.subarray(0, n - 1), cap, () => {}) !== 'damaged') return failure('the link is damaged (data after the end of its compressed stream)');
  const out = new Uint8Array(total);
  let offset = 0;
  for (const piece of pieces) {
    out.set(piece, offset);
    offset += piece.length;
  }
  return { ok: true, value: out };
}

export function decodePayload(payload: Uint8Array, limits: DecodeLimits): Checked<DesignState> {
  if (payload.length < 4) return failure('the link is too short to hold a design');
  const jsonLength = new DataView(payload.buffer, payload.byteOffset, payload.byteLength).getUint32(0, true);
  if (jsonLength > payload.length - 4) return failure('the link is damaged (bad header)');
  if (jsonLength > MAX_JSON_BYTES) return failure(`the link's settings are larger than ${MAX_JSON_BYTES / 1024} KiB`);
  let parsed: unknown;
  try {
    parsed = JSON.parse(new TextDecoder('utf-8', { fatal: true }).decode(payload.subarray(4, 4 + jsonLength)));
  } catch {
    return failure('the link is damaged (its settings are not readable)');
  }
  if (!isRecord(parsed)) return failure('the link is damaged (its settings are not an object)');
  if (parsed.v !== SHARE_VERSION) {
    return failure(typeof parsed.v === 'number' ? `the link has format version ${parsed.v}; this page reads version ${SHARE_VERSION}` : 'the link has no format version');
  }
  const unknown = unknownField(parsed, LINK_FIELDS);
  if (unknown !== null) return failure(`the link has an unknown field "${unknown}"`);
  // The paint's bytes come last; what is before them is the mesh's.
  const table = checkPaintTable(parsed.paint, 'the link');
  if (!table.ok) return table;
  const paintBytes = table.value.reduce((sum, { vertices }) => sum + vertices, 0);
  if (paintBytes > limits.maxPaintBytes) return failure(`the link's density paint is larger than ${Math.round(limits.maxPaintBytes / 1024)} KiB`);
  const tail = payload.subarray(4 + jsonLength);
  if (paintBytes > tail.length) return failure('the link is damaged (the density paint is truncated)');
  const rest = tail.subarray(0, tail.length - paintBytes);
  const meshValue = parsed.mesh;
  if (!isRecord(meshValue)) return failure('the link names no mesh');
  let mesh: DesignMesh;
  if ('example' in meshValue && 'file' in meshValue) return failure('the link names both an example and a mesh file');
  const unknownMesh = unknownField(meshValue, 'example' in meshValue ? EXAMPLE_MESH_FIELDS : FILE_MESH_FIELDS);
  if (unknownMesh !== null) return failure(`the link's mesh has an unknown field "${unknownMesh}"`);
  if (typeof meshValue.example === 'string') {
    const example = findExample(meshValue.example);
    if (!example) return failure(`the link names an unknown example "${meshValue.example.slice(0, 40)}"`);
    if (rest.length !== 0) return failure('the link is damaged (extra data after an example)');
    mesh = { kind: 'example', id: example.id };
  } else if ('file' in meshValue) {
    const name = checkFileName(meshValue.file);
    if (!name.ok) return failure(`in the link, ${name.message}`);
    const size = meshValue.size;
    if (typeof size !== 'number' || !Number.isInteger(size) || size < 1) return failure('the link gives no valid mesh size');
    if (size > limits.maxMeshBytes) return failure(`the link's mesh is larger than ${Math.round(limits.maxMeshBytes / 1024)} KiB`);
    if (size !== rest.length) return failure('the link is damaged (the mesh is truncated)');
    mesh = { kind: 'file', name: name.value, bytes: rest.slice() };
  } else {
    return failure('the link names no mesh');
  }
  const options = withMeshOptions(mesh, meshValue, 'in the link');
  if (!options.ok) return options;
  mesh = options.value;
  const checked = checkParamsAndHistory(parsed.params, parsed.history, 'the link');
  if (!checked.ok) return checked;
  const fabrication = optionalFabrication(parsed.fabrication, 'the link');
  if (!fabrication.ok) return fabrication;
  let offset = rest.length;
  const entries = table.value.map(({ key, vertices }) => {
    const bytes = tail.subarray(offset, offset + vertices);
    offset += vertices;
    return { key, bytes };
  });
  const paint = checkPaintFields(entries, checked.value.params, checked.value.history, 'the link');
  if (!paint.ok) return paint;
  return { ok: true, value: { mesh, ...checked.value, ...fabrication.value, ...paint.value } };
}

// The first key of `record` not among `known` (shortened), or null.
function unknownField(record: Record<string, unknown>, known: readonly string[]): string | null {
  const key = Object.keys(record).find((k) => !known.includes(k));
  return key === undefined ? null : key.slice(0, 40);
}

// The parameters and the warm-start history of a link or a stored session.
export function checkParamsAndHistory(paramsValue: unknown, historyValue: unknown, where: string): Checked<{ params: DesignParams; history: DesignParams[] }> {
  const params = validateParams(paramsValue, 'parameters');
  if (!params.ok) return failure(`in ${where}, ${params.message}`);
  const list = absentOr(historyValue, []);
  if (!Array.isArray(list) || list.length > MAX_HISTORY) return failure(`${where} is damaged (bad solve history)`);
  const history: DesignParams[] = [];
  for (const entry of list) {
    const checked = validateParams(entry, 'history');
    if (!checked.ok) return failure(`in ${where}'s history, ${checked.message}`);
    history.push(checked.value);
  }
  return { ok: true, value: { params: params.value, history } };
}

// The fabrication settings of a link or stored session, when it has them (checked; none in
// older ones, which still open with the defaults).
export function optionalFabrication(value: unknown, where: string): Checked<{ fabrication?: FabricationSettings }> {
  if (value === undefined) return { ok: true, value: {} };
  const checked = fabricationOrDefault(value, where);
  return checked.ok ? { ok: true, value: { fabrication: checked.value } } : checked;
}

export function decodeState(compressed: Uint8Array, limits: DecodeLimits): Checked<DesignState> {
  const inflated = inflateCapped(compressed, limits.maxMeshBytes + limits.maxPaintBytes + MAX_JSON_BYTES + 4);
  if (!inflated.ok) return inflated;
  return decodePayload(inflated.value, limits);
}

export function stateToHash(state: DesignState): string {
  return payloadToHash(encodePayload(state));
}

function payloadToHash(payload: Uint8Array): string {
  return `#${HASH_PREFIX}${encodeBase64url(compressPayload(payload))}`;
}

// The hash of a design, or why it cannot travel in a link. The mesh size is checked before
// compressing (a large upload is not compressed for nothing), the hash length after.
export function shareHash(state: DesignState): Checked<string> {
  if (state.mesh.kind === 'file' && state.mesh.bytes.length > MAX_SHARED_MESH_BYTES) return failure(LINK_TOO_LARGE);
  let paintBytes = 0;
  for (const field of state.paint?.values() ?? []) paintBytes += field.length;
  if (paintBytes > MAX_SHARED_PAINT_BYTES) return failure(PAINT_TOO_LARGE);
  let hash: string;
  try {
    // What the decoder would refuse is not offered (it fits by the limits above; kept in step).
    const payload = encodePayload(state);
    if (new DataView(payload.buffer).getUint32(0, true) > MAX_JSON_BYTES) return failure(`the design's settings are larger than ${MAX_JSON_BYTES / 1024} KiB and cannot travel in a link`);
    hash = payloadToHash(payload);
  } catch (error) {
    return failure(`the link could not be made (${error instanceof Error ? error.message : String(error)})`);
  }
  return hash.length > MAX_LINK_HASH_CHARS ? failure(LINK_TOO_LARGE) : { ok: true, value: hash };
}

// Whether the hash is meant as a share link at all (an empty hash or "#" is not).
export function isShareHash(hash: string): boolean {
  return hash.replace(/^#/, '').length > 0;
}

export function hashToState(hash: string): Checked<DesignState> {
  const body = hash.replace(/^#/, '');
  const version = /^v(\d{1,6})=/.exec(body);
  if (!version) return failure('this is not a Flatfacet share link (it should start with #v1=)');
  if (version[1] !== String(SHARE_VERSION)) return failure(`the link has format version ${version[1]}; this page reads version ${SHARE_VERSION}`);
  // The same cap as for links this page writes.
  if (body.length + 1 > MAX_LINK_HASH_CHARS) return failure('the link is too long'); // "#" + body
  const encoded = body.slice(version[0].length);
  const compressed = decodeBase64url(encoded);
  if (!compressed) return failure('the link is damaged (it has characters a share link never has)');
  return decodeState(compressed, LINK_LIMITS);
}
