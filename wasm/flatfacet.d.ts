// Hand-written types of the Embind module (Emscripten 3.1.6 has no --emit-tsd).
// Calls that can fail return a string that parses to a Status (ok false + a one-line message
// naming the problem) and leave the session's previous mesh, parameters and result untouched.
// Nothing else throws, except when the wasm runs out of memory (a typed-array getter's copy)
// or traps: treat any exception from a call as a crashed solver (restart the worker).

export interface Status {
  ok: boolean;
  message: string; // empty when ok
}

export interface MeshInfo extends Status {
  name: string;
  vertices: number; // of the cleaned mesh
  triangles: number; // of the cleaned mesh
  inputTriangles: number; // as read, before clean-up
  components: number;
  boundaryLoops: number;
  euler: number; // Euler characteristic
  genus: number;
  bboxDiagonal: number;
  // Pairs of the cleaned mesh's triangles that pass through each other (the surface crossing
  // itself; panels made from it cross there too; -1: not checked, its triangles overlap too
  // much in space), and the first pair's deepest point (0s when none).
  selfCrossings: number;
  selfCrossingPoint: [number, number, number];
  // The separate places where it crosses (pairs joined through shared triangles and corners;
  // 0 when none or not checked; absent from an older worker that did not count them).
  selfCrossingPlaces?: number;
  // Every crossing pair's deepest point, flat x y z ... (the first 2,000 pairs), for the
  // view's markers; empty when none.
  selfCrossingPoints: number[];
  cleanup: string[]; // one sentence per repair applied ("welded 12 duplicate vertices")
  prepared: string[]; // what Session.prepare did and why ("refined 1,952 triangles to ...")
  repair: MeshRepair;
}

// What the load repaired (Session.setRepair's options and the counts).
export interface MeshRepair {
  fillHoles: number;
  largestPart: boolean;
  slivers: number; // sliver faces removed (collapsed or flipped)
  holesFilled: number;
  holeFaces: number; // faces the fillings added
  nonmanifoldEdgesCut: number; // largestPart: edges cut
  facesDropped: number; // largestPart: faces outside the kept part
  partsDropped: number;
}

// A load refused for non-manifold edges (the message names the first edge) or for a part far
// from the rest (named): setRepair(_, true) and loading again keeps the largest part, of `faces`
// of the mesh's `of` faces.
export interface NonManifoldStatus extends Status {
  largestPart?: { faces: number; of: number };
}

// Everything the designer sets; missing fields keep their defaults (DESIGN.md 4 / CLI).
export interface RemeshParams {
  panels: number; // >= 1
  seed?: number; // integer 0 .. 2^53-1; default 1
  weights?: { euclidean?: number; l2?: number; l21?: number; density?: number; boundary?: number };
  lloydIterations?: number; // k1, default 20
  panelRounds?: number; // k2, default 100 (stops at the first valid round, or after 50 rounds without fewer invalid panels)
  retries?: number; // 0..10, default 8: solves from a new seeding when panels end invalid (the fewest invalid kept)
  seeding?: 'farthest' | 'random';
  teleport?: boolean; // default true
  singlePointNodes?: boolean; // default false
  optimizePlanes?: boolean; // default true
  // Procedural density (core/density/expression.h): variables x y z, u v w, nx ny nz, k1 k2 H K
  // curv, border; higher = smaller panels. Multiplies a painted field (setDensity).
  densityExpression?: string;
  // Panels stretched along a direction (stretch 1..10). 'expression': a procedural direction
  // per face, `expression` = three expressions of the density language "ex, ey, ez"
  // (core/density/direction_expression.h), e.g. "-y, x, 0"; given with that direction only.
  anisotropy?: {
    direction: 'none' | 'x' | 'y' | 'z' | 'maxCurvature' | 'minCurvature' | 'expression';
    stretch: number;
    expression?: string;
  };
  // Per-panel edits, applied in order to the solved design (at most 10000); panels are named
  // by a cleaned triangle inside them. A setParams that changes only `edits` edits the design
  // in place: more edits apply to it, a shorter or different list (undo / redo) replays from
  // the design before the first edit. Locked panels keep their triangles, plane and outline
  // through later re-solves (panel count, weights). A failing edit leaves the previous result.
  edits?: PanelEdit[];
  glass?: boolean; // default false: concave panels cut into coplanar convex pieces
  minCornerAngleDeg?: number; // 0..60, default 0 (none): corners below it are panel problems
  // 0..10, default 1 (the paper's): neighbours whose planes differ by less share one plane
  // (master planes), unless their planes meet between them (core/panels/master_planes.h)
  coplanarAngleDeg?: number;
}

export type PanelEdit =
  | { op: 'split'; face: number }
  | { op: 'merge'; face: number; with: number } // `with`: a triangle of a neighbouring panel
  | { op: 'lock'; face: number }
  | { op: 'unlock'; face: number };

export type LengthUnitName = 'mm' | 'cm' | 'm' | 'in' | 'ft';

// Fabrication settings; missing fields keep the defaults (core/fabricate/fabrication_params_json.h):
// meshUnits 'm', units = meshUnits, thickness 0 (no inner faces), side 'inside', a
// 2440 x 1220 mm sheet. Lengths in `units`.
export interface FabricationParams {
  thickness?: number; // >= 0
  side?: 'inside' | 'outside'; // where the material lies relative to the designed surface
  units?: LengthUnitName; // of the outputs and of thickness / sheet size
  meshUnits?: LengthUnitName; // what one mesh coordinate is
  sheetWidth?: number; // > 0
  sheetHeight?: number; // > 0
  panelThickness?: Record<string, number>; // by label ("P3", "P12a"), > 0, in `units`; needs thickness > 0
  boundaryCut?: 'square' | 'plumb' | 'bevel'; // how boundary edges are cut, default 'square'
  boundaryBevelDeg?: number; // -60..60, for 'bevel': positive makes the inner face smaller
  upAxis?: 'x' | 'y' | 'z'; // for 'plumb' (the cut holds this axis), default 'z'
}

export interface SheetStats extends Status {
  sheets: number;
  materialUse: number; // outline area / (sheets * sheet area), 0..1
}

export interface SpreadNodes extends Status {
  units: LengthUnitName;
  thickness: number;
  maxSpread: number; // designer's units
  // Nodes whose panels' inner vertices miss one point (the extra chamfering they need).
  nodes: { vertex: number; position: [number, number, number]; spread: number; panels: string[] }[];
  // Labels of the parts whose inner face folds over at this thickness (too thick for them):
  // they cannot be cut as drawn (core/fabricate/parts_list.h, folded_inner_faces).
  folded: string[];
  foldedPanels: number[]; // the same parts, as panel indices (0-based, as panelOffsets)
}

// NURBS surfaces for Session.loadSurfaces (core/prepare/nurbs_json.h). Control point (i, j) is
// points[3 * (i * countV + j) ..] (i along u), Euclidean (not multiplied by its weight). Knots in
// either convention: Rhino's countU + degreeU - 1, or the textbook countU + degreeU + 1.
export interface SurfaceDescription {
  name?: string; // as used in messages and the note, e.g. "'Vault'", "face 2 of 'Tank'"; default "surface <k>"
  degreeU: number; // 1 .. 11
  degreeV: number;
  countU: number;
  countV: number;
  knotsU: number[];
  knotsV: number[];
  points: number[]; // xyz per control point
  weights?: number[]; // one per control point, > 0; absent: all 1
}

export interface SurfaceSet {
  surfaces: SurfaceDescription[];
  targetTriangles?: number; // 100 .. 2e6, default 30000: picks one edge length for all surfaces
  edgeLength?: number; // > 0: overrides targetTriangles
  weldTolerance?: number; // >= 0: vertices on open edges this close are joined (default 0: exact)
}

export interface SurfacesInfo extends MeshInfo {
  edgeLength: number; // the tessellation's target edge length
  // Per surface, in order: its name as given (or "surface 2"), its triangles
  // (before the joint clean-up), grid intervals along u / v, border points merged (seam, pole).
  surfaces: { name: string; triangles: number; samplesU: number; samplesV: number; seamWelded: number }[];
}

export type StageName = 'Seeding' | 'Lloyd' | 'Panels' | 'Optimize' | 'Done'; // capitalised for display

export interface Progress extends Status {
  stage: StageName;
  iteration: number; // within the stage
  of: number; // the stage's iteration limit
  energy: number;
  invalidPanels: number;
  done: boolean;
  panelRounds: number; // panel rounds done so far
  attempt: number; // the solve in progress: 1, or 2.. for a retry from a new seeding (RemeshParams.retries)
  attempts: number; // 1 + RemeshParams.retries: the most there can be
  // Panel rounds again after a valid result with a corner below 1 degree (the needle rounds):
  // the stage went back from Optimize to Panels on purpose. invalidPanels then counts needle
  // corners too. False in every other stage (from the Optimize after them on).
  needleRounds: boolean;
}

export interface Problems extends Status {
  spikes: number[]; // xyz triples: panel vertices farther than the spike distance from their corner
  flippedEdges: number[]; // pairs of xyz triples (6 numbers per edge): edges against their panel's orientation
  acuteCorners: number[]; // xyz triples: panel corners below the minimum corner angle (minCornerAngleDeg)
  invalidPanels: number[]; // panel ids of the report's "invalid" list (the quality check's and the panel phase's own)
  unbuiltClusters: number[]; // cluster ids that could not become a panel (their faces stay uncovered)
}

export interface Session {
  // Reads OBJ/OFF/STL/PLY bytes (format from the name's extension, else the content), cleans
  // the mesh (weld, drop degenerate/duplicate faces, orient). Returns MeshInfo JSON.
  loadMesh(name: string, bytes: Uint8Array): string;
  // A triangle soup from a three.js loader (glTF/GLB): xyz per vertex, 3 indices per triangle.
  loadArrays(name: string, positions: Float64Array, indices: Uint32Array): string;
  // NURBS surfaces (JSON of SurfaceSet), tessellated in the core, plus a triangle soup loaded
  // with them (meshes, render meshes; may be empty). Returns SurfacesInfo JSON or a Status.
  loadSurfaces(name: string, surfacesJson: string, positions: Float64Array, indices: Uint32Array): string;
  // A generated example: 'saddle' | 'barrel_vault' | 'groin_vault' | 'helicoid' | 'freeform_roof'
  // | 'torus' | 'bump' | 'roof_with_hole' | 'twisted_strip' | 'cone' | 'monkey_saddle', with
  // about `triangles` triangles.
  loadShape(name: string, triangles: number): string;
  // After a load, and again whenever the panel count outgrows the mesh: from the mesh as
  // loaded (kept in the session), subdivide `subdivide` levels (0..4; Loop on triangles, else
  // Catmull-Clark on the file's polygons), then refine to the resolution `panels` need (below
  // `refineBelow` triangles per panel, 20..50, 0: the core's 30; below 20 always; else the mesh
  // stays as loaded), or to `edgeLength` when > 0 (0: automatic). `refineRounds`: the
  // remeshing rounds of a refinement below 20 per panel (1..10, 0: the core's 5). MeshInfo
  // JSON, its `prepared` saying what was done and why; a Status on failure (the mesh kept).
  prepare(panels: number, subdivide: number, edgeLength: number, refineBelow: number, refineRounds: number): string;
  // The mesh as loaded again, neither subdivided nor prepared (what a design saved before
  // preparations were recorded was made on); answered as prepare().
  prepareAsLoaded(): string;
  // Carried from the mesh before the last prepare() to the mesh now: values per vertex
  // (closest point, barycentric), triangle ids (nearest centroid). Empty arrays when refused
  // (wrong length, an id out of range, no mesh before). Carry right after prepare(): the next
  // accepted setDensity or setParams, or step(), drops the mesh before (so does a load).
  transferField(values: Float64Array): Float64Array;
  remapFaces(faces: Int32Array): Int32Array;
  // How the next loads repair the mesh (issue 7): fill holes of at most `fillHoles` edges
  // (0 = off, at most 500); with `largestPart`, a mesh with non-manifold edges is cut there and
  // only its largest part kept (every other part dropped). Without it such a load, or one with a
  // part far from the rest, fails with a NonManifoldStatus.
  // Status JSON; the mesh already loaded stays as it is.
  setRepair(fillHoles: number, largestPart: boolean): string;
  // Sets parameters (JSON of RemeshParams). With a solve under way or finished, warm-starts from
  // the current clustering (panel count / weights); a changed seed starts over. Status JSON.
  setParams(paramsJson: string): string;
  // Density per vertex of the cleaned mesh (MeshInfo.vertices values, each finite and > 0;
  // higher = smaller panels, panel area roughly 1/density); empty = uniform. Warm-starts like
  // setParams; the same field again is a no-op; setParams keeps it; a new mesh drops it.
  // Status JSON (refused, nothing changed, on a wrong length or a bad value).
  setDensity(density: Float64Array): string;
  // Bounded work (seeding, one Lloyd iteration, one panel round). Progress JSON.
  step(): string;
  done(): boolean;
  // Drops the solve: the next step() starts cold from the loaded mesh with the current
  // parameters (the same result as a new Session), without reading the mesh again.
  resetSolve(): void;

  // The cleaned input mesh for display.
  inputPositions(): Float32Array; // xyz per vertex
  inputIndices(): Uint32Array; // 3 per triangle
  // Per cleaned triangle: its cluster (-1 unassigned), valid after any step.
  clusterIds(): Int32Array;
  // Per-panel edits (see RemeshParams.edits): the panel (cluster id, as in clusterIds) of a
  // cleaned triangle, -1 when out of range or before clustering; a triangle inside a panel
  // (to name it in an edit), -1 when out of range; the locked panels' ids, sorted; the number
  // of panels now (the requested count plus splits minus merges; 0 before clustering).
  panelOfFace(face: number): number;
  panelFace(panel: number): number;
  lockedPanels(): Int32Array;
  panelCount(): number;
  // The panels (empty before the panel phase): vertices, and panel i's vertex indices are
  // panelIndices[panelOffsets[i] .. panelOffsets[i+1]).
  panelPositions(): Float64Array;
  panelOffsets(): Uint32Array; // numPanels + 1 entries
  panelIndices(): Uint32Array;
  // The panels triangulated in their own planes (ear clipping, concave panels handled):
  // indices into panelPositions, and the panel of each triangle.
  panelTriangles(): Uint32Array;
  panelTriangleIds(): Uint32Array;
  // Per cleaned triangle: its panel (an index of panelOffsets' panels; glass pieces and
  // unbuilt clusters make it differ from clusterIds), -1 for none.
  facePanels(): Int32Array;
  // A density expression evaluated per vertex of the cleaned mesh (the factor the solver
  // multiplies the painted density with); empty for '' or an expression the core refuses.
  expressionDensity(expression: string): Float64Array;
  // "Before the fix": each panel vertex moved back to its mesh corner (same layout as
  // panelPositions), i.e. the polygons a plain corner remeshing would give, and per panel how
  // far those are from planar (max distance to the best-fit plane / panel diameter).
  cornerPositions(): Float64Array;
  cornerPlanarity(): Float64Array;
  // Per panel: the largest distance between it and the design near it, sampled both ways,
  // relative to the bounding-box diagonal (core/quality/panel_deviation.h).
  panelDeviation(): Float64Array;
  problems(): string; // Problems JSON (ok true) or a Status (ok false)
  // The quality report (DESIGN.md 4 keys plus "ok": true) of the current panels; only
  // Also "panel_area": the panels' total area in mesh units squared.
  // {"ok": true, "message": ""} without panels; a Status (ok false) on failure.
  reportJson(): string;
  // Panels OBJ as `flatfacet remesh --out` writes it (the comment's input line names the file
  // instead of a path); "" when there are no panels yet; a Status JSON on failure (it starts
  // with '{', which an OBJ never does).
  objText(): string;
  // Every fabrication output below is of the panels kept last: keepPanels() copies the current
  // ones (the page's worker calls it when it hands a solve's result over), so a later solve,
  // under way or cancelled half-way, does not change them. They stay until the next
  // keepPanels(), through loads and preparations too (the worker knows which design they are
  // of); before the first, the outputs are empty parts lists.
  keepPanels(): void;
  // Fabrication settings (JSON of FabricationParams). Status JSON; on failure the previous
  // settings stay. They apply to every fabrication output below.
  setFabrication(fabricationJson: string): string;
  // The parts list (core/fabricate/parts_list.h) CSV: header row (the nine basic columns, then
  // units, thickness, edge lengths, chamfers, neighbours, dihedrals, corner angles, outer_2d,
  // inner_2d), one row per panel, a total row; in the designer's units. A Status JSON on failure.
  partsCsv(): string;
  // The same as JSON ({"units", "mesh_units", "thickness", "side", "totals": {"panels", "area",
  // "perimeter"}, "max_node_spread", ..., "panels": [...], "spread_nodes": [...]}), or a Status
  // JSON (ok false) on failure.
  partsJson(): string;
  // Cut sheets (outlines packed onto sheets of sheetWidth x sheetHeight) as SVG / DXF (R12);
  // a Status JSON on failure (a part larger than the sheet names itself).
  sheetsSvg(): string;
  sheetsDxf(): string;
  sheetStats(): string; // SheetStats JSON or a Status
  // Solid panels OBJ (a closed prism per panel, mesh coordinates); a Status JSON without a
  // thickness or without panels.
  solidObj(): string;
  // Inner-face corners (mesh units), xyz per panel corner in panelIndices order: panel i's are
  // corners panelOffsets[i] .. panelOffsets[i+1]. Empty without panels or thickness.
  innerPositions(): Float64Array;
  spreadNodes(): string; // SpreadNodes JSON or a Status
  delete(): void;
}

export interface FlatfacetModule {
  Session: { new (): Session };
  version(): string;
  HEAPU8: Uint8Array;
}

export interface ModuleOptions {
  wasmBinary?: ArrayBuffer | Uint8Array;
  locateFile?: (path: string, prefix: string) => string;
}

declare function createFlatfacet(options?: ModuleOptions): Promise<FlatfacetModule>;
export default createFlatfacet;
