// The messages between the page and the solver worker. The worker owns the wasm Session; the
// page only ever sees copies. Every request carries a job number and every answer repeats
// it, so the page drops answers to jobs it has moved past (a cancelled solve, a replaced mesh).
import type { MeshRepair } from './meshRepair.ts';
import type { FabricationParams, MeshInfo, Problems, Progress, RemeshParams, SheetStats, SpreadNodes } from '@flatfacet/wasm';
import type { MeshPrepare } from './share.ts';

export type { MeshPrepare };

// What the worker loads: file bytes for the core's readers (OBJ, OFF, STL, PLY), a triangle
// soup from three.js (glTF/GLB), or a generated surface.
export type MeshPayload = (
  | { kind: 'bytes'; name: string; bytes: Uint8Array }
  | { kind: 'arrays'; name: string; positions: Float64Array; indices: Uint32Array }
  | { kind: 'shape'; name: string; triangles: number }
  // NURBS surfaces (JSON of SurfaceSet) tessellated by the core, with a triangle soup beside
  // them (a Rhino file: web/src/rhino/).
  | { kind: 'surfaces'; name: string; surfacesJson: string; positions: Float64Array; indices: Uint32Array }
) & {
  // Applied right after the load (Session.prepare): subdivision, then the resolution the panel
  // count needs. Part of the payload, so a worker restart prepares the same mesh again.
  prepare?: MeshPrepare;
  // How the load repairs the mesh (Session.setRepair; absent: no holes filled, non-manifold
  // edges refused). Part of the payload for the same reason.
  repair?: MeshRepair;
  // What the page's own reader left out or applied (a glTF's lines, its other scenes, its
  // instances), one phrase each, said under the mesh. The worker does not read it.
  read?: string[];
};

// What a re-preparation carries from the mesh before to the new one: the painted density
// (levels per vertex; null: none) and the triangles the panel edits name (preparation.ts).
export interface Carry {
  paint: Int8Array | null;
  faces: Int32Array;
}

// One solve of a chain: the parameters and the painted density field (brush/densityField.ts
// levels, one per vertex of the loaded mesh; null: none), set in the session before it.
export interface SolveStep {
  params: RemeshParams;
  paint: Int8Array | null;
}

export type WorkerRequest =
  // quiet: reload after a worker restart; answer without the display arrays.
  | { type: 'load'; job: number; mesh: MeshPayload; quiet: boolean }
  // Prepares the loaded mesh again, from the mesh as loaded (Session.prepare; null: the mesh
  // as loaded itself, Session.prepareAsLoaded, for a design saved before preparations were
  // recorded), and carries `carry` over to it; answered like a load (`loaded`, with `carried`).
  | { type: 'prepare'; job: number; prepare: MeshPrepare | null; carry: Carry }
  // fresh: start cold from the loaded mesh (Session.resetSolve), else warm-start from what the
  // session holds.
  // chain: parameter sets solved one after the other (a share link replays a warm-start chain).
  | { type: 'solve'; job: number; fresh: boolean; chain: SolveStep[] }
  // A parameter change during a solve: applied before the next step (warm start).
  | { type: 'update'; job: number; step: SolveStep }
  | { type: 'cancel'; job: number }
  // The page shows the result of solve `job`: its panels are what fabrication reads from now
  // on (Session.keepPanels), until the next 'keep' or a new mesh. `as`: a new worker solved
  // the result on show again (the same panels), which fabricate requests name by its first job.
  | { type: 'keep'; job: number; as?: number }
  // The fabrication outputs of the panels the solve numbered `panels` gave (the result on
  // show), with these settings; refused when the worker no longer holds them (restarted, or a
  // mesh loaded since). Its own job numbers (SolverClient.fabricate), so it never disturbs a
  // solve's.
  | { type: 'fabricate'; job: number; settings: FabricationParams; panels: number }
  // A density expression's values per vertex of the loaded mesh (the Density colour map shows
  // expression x paint). Its own job numbers too (SolverClient.expressionDensity).
  | { type: 'expressionDensity'; job: number; expression: string }
  // Test hooks: the worker makes a wasm call that throws a non-Status error, as running out of
  // memory would, N steps into its second solve (?crashAfterSteps=N); its Nth preparation of the
  // mesh crashes so (?crashOnPrepare=N) or is refused as the core refuses (?refuseOnPrepare=N);
  // `failStart`: it answers as a worker whose solver could not start ('fatal') and nothing
  // after (?failRestart=1, sent to every replacement worker); `stepDelayMs`: each solve step
  // waits so long first (?stepDelay=MS), so that a test can act during a solve.
  | { type: 'test'; job: 0; crashAfterSteps?: number; prepareFault?: PrepareFault; failStart?: boolean; stepDelayMs?: number };

export interface PrepareFault {
  at: number; // 1: the first preparation
  kind: 'crash' | 'refuse';
}

// The report's keys as DESIGN.md 4 names them; read defensively (the core may add keys).
export type QualityReport = Record<string, unknown>;

export interface SolveResult {
  clusterIds: Int32Array;
  panelPositions: Float64Array;
  panelOffsets: Uint32Array;
  panelIndices: Uint32Array;
  panelTriangles: Uint32Array;
  panelTriangleIds: Uint32Array;
  facePanels: Int32Array; // per mesh triangle: its panel (an index of panelOffsets), -1 none
  // "Before the fix": the same polygons through their mesh corners (layout of panelPositions),
  // and per panel how far each is from planar (distance / diameter).
  cornerPositions: Float64Array;
  cornerPlanarity: Float64Array;
  panelDeviation: Float64Array; // per panel: distance from the design, / bounding-box diagonal
  problems: Problems;
  report: QualityReport;
  objText: string;
  solveSeconds: number; // wall time in the worker, first step to last
  steps: number;
}

// What the Fabrication section shows and exports. The cut sheets fail on their own (a part
// larger than the sheet) without taking the rest with them.
export interface FabricationResult {
  partsCsv: string;
  partsJson: string;
  sheets: { ok: true; svg: string; dxf: string; stats: SheetStats } | { ok: false; message: string };
  solidObj: string | null; // null without a thickness
  innerPositions: Float64Array; // per panel corner, panelIndices order; empty without thickness
  spread: SpreadNodes;
}

export type WorkerResponse =
  | { type: 'ready'; version: string }
  // The solver could not start at all.
  | { type: 'fatal'; message: string }
  // A wasm call threw something that is not a Status (out of memory, a trap, a bug): the
  // module's state is unknown, so the page replaces this worker.
  | { type: 'crashed'; message: string }
  | { type: 'loaded'; job: number; info: MeshInfo; positions: Float32Array; indices: Uint32Array; carried?: Carry }
  // A load or solve the core refused; the worker's previous mesh and result are intact.
  // largestPart: refused for non-manifold edges or a part far off; the largest part has `faces` of `of`.
  | { type: 'failed'; job: number; message: string; largestPart?: { faces: number; of: number } }
  | { type: 'progress'; job: number; progress: Progress; elapsedSeconds: number }
  | { type: 'clusters'; job: number; clusterIds: Int32Array }
  | { type: 'solved'; job: number; result: SolveResult }
  | { type: 'cancelled'; job: number }
  | { type: 'fabricated'; job: number; result: FabricationResult }
  | { type: 'fabricationFailed'; job: number; message: string }
  // Empty `values`: no expression, or one the core refuses (the solve says why).
  | { type: 'expressionDensity'; job: number; expression: string; values: Float64Array };

// The buffers a message can hand over instead of copying. Each is the fresh array an Embind
// getter returns (wasm/bindings.cpp copies out of the heap), never a view of the wasm heap
// (shared/notes/toolchain.md, note 7), so the worker transfers it without another copy.
export function transferablesOf(message: WorkerResponse): Transferable[] {
  switch (message.type) {
    case 'loaded': {
      const carried = message.carried ? [message.carried.faces.buffer, ...(message.carried.paint ? [message.carried.paint.buffer] : [])] : [];
      return [message.positions.buffer, message.indices.buffer, ...carried];
    }
    case 'clusters':
      return [message.clusterIds.buffer];
    case 'solved': {
      const r = message.result;
      return [r.clusterIds, r.panelPositions, r.panelOffsets, r.panelIndices, r.panelTriangles, r.panelTriangleIds, r.facePanels, r.cornerPositions, r.cornerPlanarity, r.panelDeviation].map((a) => a.buffer);
    }
    case 'fabricated':
      return [message.result.innerPositions.buffer];
    case 'expressionDensity':
      return [message.values.buffer];
    default:
      return [];
  }
}
