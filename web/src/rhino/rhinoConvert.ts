// A Rhino file (parsed by rhino3dm) into what the solver worker loads: NURBS surfaces as
// descriptions for the core's tessellation (wasm Session.loadSurfaces), meshes as triangles.
// Pure functions over a rhino3dm module and document, no DOM: the Node tests run them too.
//
// What becomes what:
//   NURBS surface, other surfaces (plane, revolution, sum)    -> their NURBS form, tessellated by the core
//   Brep, polysurface, extrusion                              -> untrimmed faces: their surface, as above;
//                                                                trimmed faces: the face's render mesh from
//                                                                the file, else left out with a message
//   Mesh                                                      -> its triangles (quads split)
//   SubD                                                      -> its control net subdivided (Catmull-Clark)
//   anything else (curves, points, text, blocks)              -> listed as not a surface
import type { SurfaceDescription, SurfaceSet } from '@flatfacet/wasm';
import type * as Rhino from 'rhino3dm';

export type RhinoModule = Rhino.RhinoModule;

export interface RhinoObjectInfo {
  index: number; // in the file's object table
  name: string; // the object's name, or e.g. "Brep 2" when it has none
  type: string; // "NURBS surface", "Brep (3 faces)", "Mesh (1,200 faces)", ...
  supported: boolean;
}

export interface PreparedRhino {
  set: SurfaceSet;
  positions: Float64Array; // triangles beside the surfaces (meshes, render meshes)
  indices: Uint32Array;
  notes: string[]; // what was prepared and why, one sentence each
  objects: number; // objects used
}

export type Prepared = { ok: true; value: PreparedRhino } | { ok: false; message: string };

const SUBD_LEVELS = 2;
const MAX_SUBD_FACES = 200_000;

// Loosely typed views of what rhino3dm returns at run time (its .d.ts does not say that
// NurbsSurfacePointList.get gives homogeneous [x w, y w, z w, w], for instance).
interface AnyGeometry {
  objectType: { value: number } | number;
  delete?: () => void;
}

function objectTypeValue(rh: RhinoModule, geometry: AnyGeometry): string {
  const types = rh.ObjectType as unknown as Record<string, { value: number } | number>;
  const value = typeof geometry.objectType === 'number' ? geometry.objectType : geometry.objectType.value;
  for (const key of ['Surface', 'Brep', 'Mesh', 'SubD', 'Extrusion', 'Curve', 'Point', 'PointSet', 'Annotation', 'InstanceReference', 'TextDot', 'Hatch', 'Light', 'ClipPlane']) {
    const t = types[key];
    if (t !== undefined && (typeof t === 'number' ? t : t.value) === value) return key;
  }
  return 'Other';
}

// Embind objects free their wasm memory only when deleted (rhino3dm's .d.ts leaves delete() out).
export function free(object: unknown): void {
  const deletable = object as { delete?: () => void } | null;
  if (deletable && typeof deletable.delete === 'function') deletable.delete();
}

const plural = (n: number, word: string): string => `${n.toLocaleString('en')} ${word}${n === 1 ? '' : 's'}`;

const TYPE_NAMES: Record<string, string> = {
  Curve: 'curve',
  Point: 'point',
  PointSet: 'point cloud',
  Annotation: 'annotation',
  InstanceReference: 'block instance',
  TextDot: 'text dot',
  Hatch: 'hatch',
  Light: 'light',
  ClipPlane: 'clipping plane',
  Other: 'object',
};

export function listRhinoObjects(rh: RhinoModule, doc: Rhino.File3dm): RhinoObjectInfo[] {
  const table = doc.objects();
  const out: RhinoObjectInfo[] = [];
  const counts = new Map<string, number>();
  for (let index = 0; index < table.count; index++) {
    const object = table.get(index);
    const geometry = object.geometry() as unknown as AnyGeometry & Record<string, unknown>;
    const kind = objectTypeValue(rh, geometry);
    let type: string;
    let supported = true;
    if (kind === 'Surface') {
      type = geometry instanceof rh.NurbsSurface ? 'NURBS surface' : 'Surface';
    } else if (kind === 'Brep') {
      type = `Brep (${plural((geometry as unknown as Rhino.Brep).faces().count, 'face')})`;
    } else if (kind === 'Mesh') {
      type = `Mesh (${plural((geometry as unknown as Rhino.Mesh).faces().count, 'face')})`;
    } else if (kind === 'SubD') {
      type = 'SubD';
    } else if (kind === 'Extrusion') {
      type = 'Extrusion';
    } else {
      type = TYPE_NAMES[kind] ?? 'object';
      supported = false;
    }
    const shortType = type.replace(/ \(.*/, '');
    counts.set(shortType, (counts.get(shortType) ?? 0) + 1);
    const given = object.attributes().name;
    out.push({ index, name: given && given.trim() ? given.trim().slice(0, 80) : `${shortType} ${counts.get(shortType)}`, type, supported });
  }
  return out;
}

// The NURBS form of a surface as the core wants it; `flip` swaps u and v (a reversed face).
export function describeNurbs(surface: Rhino.NurbsSurface, name: string, flip: boolean): SurfaceDescription {
  const points = surface.points();
  const countU = points.countU;
  const countV = points.countV;
  const rational = surface.isRational;
  const xyz: number[] = [];
  const weights: number[] = [];
  const [outerCount, innerCount] = flip ? [countV, countU] : [countU, countV];
  for (let a = 0; a < outerCount; a++) {
    for (let b = 0; b < innerCount; b++) {
      const p = (flip ? points.get(b, a) : points.get(a, b)) as unknown as number[];
      const w = rational && p.length > 3 ? p[3]! : 1;
      // Homogeneous: rhino3dm hands out (x w, y w, z w, w).
      xyz.push(p[0]! / w, p[1]! / w, p[2]! / w);
      weights.push(w);
    }
  }
  const knotsU = surface.knotsU().toList() as unknown as number[];
  const knotsV = surface.knotsV().toList() as unknown as number[];
  const description: SurfaceDescription = {
    name,
    degreeU: (flip ? surface.orderV : surface.orderU) - 1,
    degreeV: (flip ? surface.orderU : surface.orderV) - 1,
    countU: outerCount,
    countV: innerCount,
    knotsU: Array.from(flip ? knotsV : knotsU),
    knotsV: Array.from(flip ? knotsU : knotsV),
    points: xyz,
  };
  if (rational) description.weights = weights;
  return description;
}

class Soup {
  positions: number[] = [];
  indices: number[] = [];
  // Faces left out for naming a vertex their mesh does not have (rhino3dm keeps such a face):
  // joined, it would land on the next object's vertices.
  faultyFaces = 0;

  addMesh(mesh: Rhino.Mesh): number {
    const vertices = mesh.vertices();
    const faces = mesh.faces();
    const base = this.positions.length / 3;
    for (let i = 0; i < vertices.count; i++) {
      const p = vertices.get(i) as unknown as number[];
      this.positions.push(p[0]!, p[1]!, p[2]!);
    }
    let triangles = 0;
    const inside = (v: number): boolean => Number.isInteger(v) && v >= 0 && v < vertices.count;
    for (let i = 0; i < faces.count; i++) {
      const f = faces.get(i) as unknown as number[];
      const [a, b, c, d] = [f[0]!, f[1]!, f[2]!, f[3] ?? f[2]!];
      if (![a, b, c, d].every(inside)) {
        this.faultyFaces += 1;
        continue;
      }
      this.indices.push(base + a, base + b, base + c);
      triangles += 1;
      if (d !== c) {
        this.indices.push(base + a, base + c, base + d);
        triangles += 1;
      }
    }
    return triangles;
  }
}

interface Collector {
  rh: RhinoModule;
  surfaces: SurfaceDescription[];
  soup: Soup;
  notes: string[];
  problems: string[]; // why something was left out
}

function nurbsOf(surface: Rhino.Surface): Rhino.NurbsSurface | null {
  const nurbs = surface.toNurbsSurface() as Rhino.NurbsSurface | null;
  return nurbs ?? null;
}

function renderMesh(c: Collector, face: Rhino.BrepFace): Rhino.Mesh | null {
  const mesh = face.getMesh(c.rh.MeshType.Render) ?? face.getMesh(c.rh.MeshType.Any);
  return mesh && mesh.faces().count > 0 ? mesh : null;
}

function addBrep(c: Collector, brep: Rhino.Brep, label: string): boolean {
  const faces = brep.faces();
  if (faces.count === 0) {
    c.problems.push(`${label} is a Brep with no faces: left out`);
    return false;
  }
  // A polysurface the file has meshed in full: Rhino's render meshes of neighbouring faces share
  // their edge vertices, so they join, which separately tessellated faces would not.
  if (faces.count > 1) {
    const meshes: Rhino.Mesh[] = [];
    for (let k = 0; k < faces.count; k++) {
      const mesh = renderMesh(c, faces.get(k));
      if (mesh) meshes.push(mesh);
    }
    if (meshes.length === faces.count) {
      let triangles = 0;
      for (const mesh of meshes) triangles += c.soup.addMesh(mesh);
      if (triangles === 0) {
        c.problems.push(`${label}: the render meshes of its ${faces.count} faces have no usable triangles: left out`);
        return false;
      }
      c.notes.push(`${label}: the render meshes of its ${faces.count} faces from the file (${plural(triangles, 'triangle')}; Rhino meshes a polysurface so that its faces meet)`);
      return true;
    }
  }
  const used: number[] = [];
  const meshed: number[] = [];
  const missing: number[] = [];
  for (let k = 0; k < faces.count; k++) {
    const face = faces.get(k);
    // Null for a damaged face: then it is taken as trimmed (its render mesh, else left out, said).
    const single = face.duplicateFace(false) as Rhino.Brep | null;
    // Trivially trimmed: the face is its whole surface (rhino3dm's own test).
    const untrimmed = single?.isSurface ?? false;
    if (single) free(single);
    if (untrimmed) {
      const nurbs = nurbsOf(face.underlyingSurface());
      if (nurbs) {
        c.surfaces.push(describeNurbs(nurbs, faces.count === 1 ? label : `face ${k} of ${label}`, face.orientationIsReversed));
        used.push(k);
        continue;
      }
    }
    const mesh = renderMesh(c, face);
    if (mesh) {
      c.soup.addMesh(mesh);
      meshed.push(k);
    } else {
      missing.push(k);
    }
  }
  if (used.length > 0) {
    const which = used.length === faces.count ? (faces.count === 1 ? 'its face' : `all ${faces.count} faces`) : `${used.length} of ${faces.count} faces`;
    c.notes.push(`${label}: ${which} untrimmed, tessellated from ${used.length === 1 ? 'its NURBS surface' : 'their NURBS surfaces'}`);
  }
  if (meshed.length > 0) c.notes.push(`${label}: trimmed ${meshed.length === 1 ? 'face' : 'faces'} ${meshed.join(', ')} taken from the file's render mesh`);
  if (missing.length > 0) {
    const which = missing.length === 1 ? `face ${missing[0]}` : `faces ${missing.join(', ')}`;
    c.problems.push(`${which} of ${label} ${missing.length === 1 ? 'is' : 'are'} trimmed and the file has no render mesh for ${missing.length === 1 ? 'it' : 'them'}: left out (save the file from Rhino with render meshes, or untrim the ${missing.length === 1 ? 'face' : 'faces'})`);
  }
  return used.length + meshed.length > 0;
}

function addSubD(c: Collector, subd: Rhino.SubD, label: string): boolean {
  const rh = c.rh as unknown as { Mesh: { createFromSubDControlNet(subd: Rhino.SubD): Rhino.Mesh | null } };
  const copy = (subd as unknown as { duplicate(): Rhino.SubD }).duplicate();
  const faceCount = (): number => (copy as unknown as { faces(): { count: number } }).faces().count;
  let levels = 0;
  while (levels < SUBD_LEVELS && faceCount() * 4 <= MAX_SUBD_FACES && copy.subdivide()) levels += 1;
  const mesh = rh.Mesh.createFromSubDControlNet(copy);
  free(copy);
  if (!mesh || mesh.faces().count === 0) {
    c.problems.push(`${label} is a SubD and rhino3dm could not make a mesh of it: left out (convert it to a mesh or NURBS in Rhino)`);
    return false;
  }
  c.soup.addMesh(mesh);
  c.notes.push(`${label}: SubD control net subdivided ${plural(levels, 'time')} (Catmull-Clark), close to its limit surface`);
  free(mesh);
  return true;
}

function addObject(c: Collector, doc: Rhino.File3dm, info: RhinoObjectInfo): boolean {
  const label = `'${info.name}'`;
  const geometry = doc.objects().get(info.index).geometry() as unknown as AnyGeometry;
  const kind = objectTypeValue(c.rh, geometry);
  if (kind === 'Surface') {
    const nurbs = nurbsOf(geometry as unknown as Rhino.Surface);
    if (!nurbs) {
      c.problems.push(`${label} is a surface without a NURBS form: left out`);
      return false;
    }
    c.surfaces.push(describeNurbs(nurbs, label, false));
    c.notes.push(`${label}: NURBS surface tessellated`);
    return true;
  }
  if (kind === 'Brep') return addBrep(c, geometry as unknown as Rhino.Brep, label);
  if (kind === 'Extrusion') {
    const brep = (geometry as unknown as Rhino.Extrusion).toBrep(true) as Rhino.Brep | null;
    if (!brep) {
      c.problems.push(`${label} is an extrusion rhino3dm cannot turn into a Brep: left out (convert it to a polysurface in Rhino)`);
      return false;
    }
    try {
      return addBrep(c, brep, label);
    } finally {
      free(brep);
    }
  }
  if (kind === 'Mesh') {
    const faulty = c.soup.faultyFaces;
    const triangles = c.soup.addMesh(geometry as unknown as Rhino.Mesh);
    const left = c.soup.faultyFaces - faulty;
    if (left > 0) c.problems.push(`${label}: ${plural(left, 'face')} naming vertices the mesh does not have: left out`);
    if (triangles === 0) {
      c.problems.push(`${label} is a mesh with no usable faces: left out`);
      return false;
    }
    c.notes.push(`${label}: mesh of ${plural(triangles, 'triangle')} used as it is`);
    return true;
  }
  if (kind === 'SubD') return addSubD(c, geometry as unknown as Rhino.SubD, label);
  c.problems.push(`${label} is a ${info.type}, not a surface: left out`);
  return false;
}

// `pick`: an object index, or 'all' (every supported object, welded where edges meet within
// the file's absolute tolerance). Fails when nothing usable remains, naming why.
export function prepareRhino(rh: RhinoModule, doc: Rhino.File3dm, fileName: string, pick: number | 'all', targetTriangles: number): Prepared {
  const objects = listRhinoObjects(rh, doc);
  const chosen = pick === 'all' ? objects.filter((o) => o.supported) : objects.filter((o) => o.index === pick);
  if (chosen.length === 0) {
    const kinds = [...new Set(objects.map((o) => o.type))].join(', ');
    return { ok: false, message: `${fileName} has no surfaces, Breps, meshes or SubDs${objects.length > 0 ? ` (only ${kinds})` : ' (it is empty)'}` };
  }
  const c: Collector = { rh, surfaces: [], soup: new Soup(), notes: [], problems: [] };
  let used = 0;
  for (const info of chosen) if (addObject(c, doc, info)) used += 1;
  if (used === 0) return { ok: false, message: `${fileName}: nothing to panel: ${c.problems.join('; ')}` };
  const left = pick === 'all' ? objects.filter((o) => !o.supported) : [];
  if (left.length > 0) c.notes.push(`left out ${plural(left.length, 'object')} that ${left.length === 1 ? 'is' : 'are'} not a surface (${[...new Set(left.map((o) => o.type))].join(', ')})`);
  const tolerance = doc.settings().modelAbsoluteTolerance;
  const set: SurfaceSet = { surfaces: c.surfaces, targetTriangles };
  const pieces = c.surfaces.length + (c.soup.indices.length > 0 ? 1 : 0);
  if (pieces > 1 || chosen.length > 1) set.weldTolerance = Number.isFinite(tolerance) && tolerance > 0 ? tolerance : 0;
  return {
    ok: true,
    value: { set, positions: Float64Array.from(c.soup.positions), indices: Uint32Array.from(c.soup.indices), notes: [...c.notes, ...c.problems], objects: used },
  };
}
