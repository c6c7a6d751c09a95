// The 3D viewport: scene, camera, orbit controls and the layers. Renders on demand (after a
// change or a camera move), so an idle page costs nothing and a solve in the worker gets the
// CPU.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import type { SpreadNodes } from '@flatfacet/wasm';
import { collapsedPanel, panelCentre } from '../collapsedPanel.ts';
import { crossingPoints } from '../crossings.ts';
import { farthestPoint } from '../farthest.ts';
import { sharpestCornerPoint } from '../sharpestCorner.ts';
import type { SolveResult } from '../protocol.ts';
import { isSoftwareRenderer } from './gpu.ts';
import { InputLayer } from './inputLayer.ts';
import { PanelLayer } from './panelLayer.ts';
import { ORANGE, ProblemLayer, shiftedPoints } from './problemLayer.ts';
import { ThickLayer } from './thickLayer.ts';

export interface ViewToggles {
  clusters: boolean;
  panels: boolean;
  edges: boolean;
  problems: boolean;
  beforeFix: boolean; // the polygons through their mesh corners, coloured by planarity
  deviation: boolean; // the panels coloured by how far each is from the design
  thick: boolean; // the panels' inner faces and side walls (needs a thickness)
}

// One press of + or - moves the camera this factor of its distance to the target (a wheel notch
// of OrbitControls is 0.95).
const KEY_ZOOM = 0.8;

export class Viewer {
  private readonly renderer: THREE.WebGLRenderer;
  private readonly scene = new THREE.Scene();
  private readonly camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
  private readonly controls: OrbitControls;
  // The framing of the model while the designer has not moved the view (frame()), else null.
  private framed: { box: THREE.Box3; upAxis: 'y' | 'z' } | null = null;
  private readonly input = new InputLayer();
  private readonly panels = new PanelLayer();
  private readonly problems = new ProblemLayer();
  private readonly thick = new ThickLayer();
  // Where the loaded surface passes through itself (an orange point per crossing pair, as where
  // panels cross), while the surface shows before its first panels.
  private readonly selfCrossing = new THREE.Points(new THREE.BufferGeometry(), new THREE.PointsMaterial({ color: ORANGE, size: 12, sizeAttenuation: false, depthTest: false }));
  private selfCrossingMarked = false;
  private readonly origin = new THREE.Vector3();
  private toggles: ViewToggles = { clusters: false, panels: true, edges: true, problems: true, beforeFix: false, deviation: false, thick: false };
  private result: SolveResult | null = null;
  private hasPanels = false;
  private solving = false;
  private renderQueued = false;
  // Live cluster colours during a solve: at most one redraw per interval, the latest wins.
  private readonly liveInterval: number;
  private liveClusters: Int32Array | null = null;
  private liveTimer: ReturnType<typeof setTimeout> | null = null;
  private lastLiveUpdate = 0;
  private readonly software: boolean;
  // The surface in the view's frame (shifted to the origin), for the density brush's picking.
  private surfaceValue: { positions: Float32Array; indices: Uint32Array; diagonal: number } | null = null;
  private densityView = false; // the density paint's colour map instead of the panels
  private readonly selection = new THREE.LineLoop(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color: 0xffe14d, depthTest: false }));

  constructor(private readonly container: HTMLElement) {
    const software = isSoftwareRenderer();
    this.software = software;
    this.liveInterval = software ? 750 : 100;
    this.renderer = new THREE.WebGLRenderer({ antialias: !software, preserveDrawingBuffer: false });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
    this.renderer.setClearColor(0x24272c);
    container.appendChild(this.renderer.domElement);
    // Keyboard too: Tab reaches the view, the arrow keys move it, Shift and the arrows turn it
    // (OrbitControls' keys); #view-keys says so to a screen reader.
    this.renderer.domElement.setAttribute('aria-label', '3D view of the design');
    this.renderer.domElement.setAttribute('aria-describedby', 'view-keys');
    this.renderer.domElement.tabIndex = 0;

    this.scene.add(new THREE.HemisphereLight(0xf2f4f8, 0x3a3d44, 1.6));
    const headlight = new THREE.DirectionalLight(0xffffff, 1.4);
    headlight.position.set(0.4, 0.8, 1);
    this.camera.add(headlight); // lights what the camera sees, from any side
    this.scene.add(this.camera);
    this.scene.add(this.input.mesh, this.panels.faces, this.panels.edges, this.problems.group, this.thick.solid, this.thick.markers, this.thick.folded);
    this.selection.renderOrder = 11;
    this.selection.name = 'selected-panel';
    this.scene.add(this.selection);
    this.selfCrossing.name = 'self-crossing';
    this.selfCrossing.renderOrder = 9;
    this.scene.add(this.selfCrossing);

    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener('change', () => this.requestRender());
    this.controls.addEventListener('start', () => (this.framed = null)); // the designer's view now
    this.controls.listenToKeyEvents(this.renderer.domElement);
    this.renderer.domElement.addEventListener('keydown', (event) => {
      if (event.key.startsWith('Arrow')) this.framed = null; // keys fire no 'start'
      // OrbitControls has no zoom key: + (or =) comes closer, - steps back, as the wheel does.
      const zoom = event.key === '+' || event.key === '=' ? KEY_ZOOM : event.key === '-' ? 1 / KEY_ZOOM : 0;
      if (zoom === 0 || event.ctrlKey || event.metaKey || event.altKey) return;
      event.preventDefault();
      this.framed = null;
      this.dollyBy(zoom);
    });
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
    this.applyVisibility();
  }

  get canvas(): HTMLCanvasElement {
    return this.renderer.domElement;
  }

  // Mesh coordinates = view frame + offset.
  get offset(): THREE.Vector3 {
    return this.origin.clone();
  }

  get viewCamera(): THREE.PerspectiveCamera {
    return this.camera;
  }

  // The input surface as shown (view frame), or null before one is loaded.
  get surface(): { positions: Float32Array; indices: Uint32Array; diagonal: number } | null {
    return this.surfaceValue;
  }

  // Something drawn over the model (the brush cursor), in the view frame.
  addOverlay(object: THREE.Object3D): void {
    this.scene.add(object);
  }

  // The density paint's colour map (RGB per surface vertex) on the surface, with the panel
  // edges over it so their sizes show against the paint; null: the usual view.
  setDensityView(rgb: Float32Array | null): void {
    this.densityView = rgb !== null;
    this.input.setVertexColors(rgb);
    this.applyVisibility();
  }

  requestRender(): void {
    if (this.renderQueued) return;
    this.renderQueued = true;
    requestAnimationFrame(() => {
      this.renderQueued = false;
      this.renderer.render(this.scene, this.camera);
    });
  }

  private resize(): void {
    const width = Math.max(1, this.container.clientWidth);
    const height = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(width, height, false);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    // Framed by the page and not moved since: framed again for the new shape (a window made
    // narrow after the model opened cut it off at both sides).
    if (this.framed) this.frame(this.framed.box, this.framed.upAxis);
    const buffer = this.renderer.getDrawingBufferSize(new THREE.Vector2());
    this.problems.setResolution(buffer.x, buffer.y);
    this.thick.setResolution(buffer.x, buffer.y);
    this.requestRender();
  }

  // A new input surface: shifts everything to its bounding-box centre and frames it (unless
  // `keepView`: the same surface prepared again, seen as it was).
  setSurface(positions: Float32Array, indices: Uint32Array, upAxis: 'y' | 'z', keepView = false): void {
    const box = new THREE.Box3();
    for (let i = 0; i + 2 < positions.length; i += 3) box.expandByPoint(new THREE.Vector3(positions[i], positions[i + 1], positions[i + 2]));
    box.getCenter(this.origin);
    const local = new Float32Array(positions.length);
    for (let i = 0; i < positions.length; i++) local[i] = positions[i]! - this.origin.getComponent(i % 3);
    this.input.setSurface(local, indices);
    this.input.setClusters(null);
    this.surfaceValue = { positions: local, indices, diagonal: box.getSize(new THREE.Vector3()).length() };
    this.setResult(null);
    if (keepView) this.requestRender();
    else this.frame(box, upAxis);
  }

  private frame(box: THREE.Box3, upAxis: 'y' | 'z'): void {
    this.framed = { box: box.clone(), upAxis };
    const radius = Math.max(1e-9, box.getSize(new THREE.Vector3()).length() / 2);
    this.camera.up.set(0, upAxis === 'y' ? 1 : 0, upAxis === 'z' ? 1 : 0);
    const direction = upAxis === 'y' ? new THREE.Vector3(0.9, 0.55, 1.1) : new THREE.Vector3(1.1, -0.9, 0.6);
    // The narrower of the two view angles: in a view taller than wide (a narrow window) the
    // horizontal one is, and framing by the vertical one cut the model off at both sides.
    const halfVertical = THREE.MathUtils.degToRad(this.camera.fov / 2);
    const halfHorizontal = Math.atan(Math.tan(halfVertical) * this.camera.aspect);
    const distance = (radius / Math.sin(Math.min(halfVertical, halfHorizontal))) * 1.02;
    this.camera.position.copy(direction.normalize().multiplyScalar(distance));
    this.camera.near = distance / 200;
    this.camera.far = distance * 20;
    this.camera.updateProjectionMatrix();
    this.controls.target.set(0, 0, 0);
    this.controls.update();
    this.requestRender();
  }

  // Moves the camera `factor` times its distance to the orbit target, kept between twice the
  // near plane and half the far one so the model is never clipped.
  private dollyBy(factor: number): void {
    const offset = this.camera.position.clone().sub(this.controls.target);
    const distance = THREE.MathUtils.clamp(offset.length() * factor, this.camera.near * 2, this.camera.far / 2);
    this.camera.position.copy(this.controls.target).add(offset.setLength(distance));
    this.controls.update();
    this.requestRender();
  }

  setClusters(clusterIds: Int32Array | null): void {
    this.cancelLiveUpdate();
    this.input.setClusters(clusterIds);
    this.requestRender();
  }

  // The clusters converging (paper fig. 5 b-c), throttled so the page stays responsive.
  showLiveClusters(clusterIds: Int32Array): void {
    this.liveClusters = clusterIds;
    if (this.liveTimer !== null) return;
    const wait = Math.max(0, this.lastLiveUpdate + this.liveInterval - performance.now());
    this.liveTimer = setTimeout(() => {
      this.liveTimer = null;
      this.lastLiveUpdate = performance.now();
      if (this.liveClusters && this.solving) this.input.setClusters(this.liveClusters);
      this.liveClusters = null;
      this.requestRender();
    }, wait);
  }

  private cancelLiveUpdate(): void {
    if (this.liveTimer !== null) clearTimeout(this.liveTimer);
    this.liveTimer = null;
    this.liveClusters = null;
  }

  // The points of the loaded surface where it passes through itself (mesh coordinates, flat
  // x y z ...; empty for none); after setSurface, whose centre they are shifted by.
  setSelfCrossing(points: number[]): void {
    this.selfCrossing.geometry.dispose();
    this.selfCrossing.geometry = shiftedPoints(points, this.origin);
    this.selfCrossingMarked = points.length >= 3;
    this.container.dataset.selfCrossingMarkers = String(this.selfCrossing.geometry.getAttribute('position').count);
    this.applyVisibility();
  }

  setResult(result: SolveResult | null): void {
    this.result = result;
    this.panels.set(result, this.origin, this.toggles.beforeFix, this.toggles.deviation);
    const collapsed = result ? collapsedPanel(result.report) : null;
    this.problems.set(
      result?.problems ?? null,
      {
        farthest: result ? farthestPoint(result.report) : null,
        sharpest: result ? sharpestCornerPoint(result.report) : null,
        collapsed: result && collapsed !== null ? panelCentre(result, collapsed) : null,
        crossings: result ? crossingPoints(result.report) : [],
      },
      this.origin,
    );
    this.container.dataset.acuteCorners = String(this.problems.acuteCorners);
    this.setSelectedPanel(null);
    this.thick.set(null, null, null, this.origin); // until the fabrication of these panels arrives
    this.hasPanels = result !== null && result.panelTriangles.length > 0;
    if (result) this.setClusters(result.clusterIds);
    this.applyVisibility();
  }

  // The thick panels, the nodes needing extra chamfer and the folded parts, for the result on
  // show (ignored when they do not match it). Returns how many nodes and parts are marked.
  setFabrication(inner: Float64Array | null, spread: SpreadNodes | null): { nodes: number; folded: number } {
    const marked = this.thick.set(this.result, inner, spread, this.origin);
    this.applyVisibility();
    return marked;
  }

  // The panel under a point of the canvas (client coordinates), or null.
  panelAt(clientX: number, clientY: number): number | null {
    if (!this.result || !this.panels.faces.visible) return null;
    const rect = this.renderer.domElement.getBoundingClientRect();
    const ndc = new THREE.Vector2(((clientX - rect.left) / rect.width) * 2 - 1, -((clientY - rect.top) / rect.height) * 2 + 1);
    const raycaster = new THREE.Raycaster();
    raycaster.setFromCamera(ndc, this.camera);
    const hit = raycaster.intersectObject(this.panels.faces, false)[0];
    // The faces are unindexed triangles in panelTriangles order: face t is triangle t.
    return hit?.faceIndex != null ? (this.result.panelTriangleIds[hit.faceIndex] ?? null) : null;
  }

  // Outlines one panel (null: none) on the panels on show.
  setSelectedPanel(panel: number | null): void {
    this.selection.geometry.dispose();
    const geometry = new THREE.BufferGeometry();
    const r = this.result;
    if (r && panel !== null && panel + 1 < r.panelOffsets.length) {
      const begin = r.panelOffsets[panel]!;
      const end = r.panelOffsets[panel + 1]!;
      const positions = new Float32Array((end - begin) * 3);
      for (let i = begin; i < end; i++)
        for (let k = 0; k < 3; k++) positions[(i - begin) * 3 + k] = r.panelPositions[r.panelIndices[i]! * 3 + k]! - this.origin.getComponent(k);
      geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    }
    this.selection.geometry = geometry;
    this.requestRender();
  }

  // While solving, the clusters converging on the input are the view (paper fig. 5 b-c).
  setSolving(solving: boolean): void {
    if (this.solving !== solving && this.software) {
      // A software rasteriser shares the CPU with the solver: draw the live view at half
      // resolution so the page keeps its frame rate; full resolution again for the result.
      this.renderer.setPixelRatio(solving ? 0.5 : Math.min(window.devicePixelRatio, 2));
      this.resize();
    }
    this.solving = solving;
    if (!solving) this.cancelLiveUpdate();
    this.applyVisibility();
  }

  setToggles(toggles: ViewToggles): void {
    const rebuild = toggles.beforeFix !== this.toggles.beforeFix || toggles.deviation !== this.toggles.deviation;
    this.toggles = { ...toggles };
    if (rebuild) this.panels.set(this.result, this.origin, toggles.beforeFix, toggles.deviation);
    this.applyVisibility();
  }

  private applyVisibility(): void {
    const showPanels = this.hasPanels && !this.solving;
    this.panels.faces.visible = showPanels && this.toggles.panels;
    this.panels.edges.visible = showPanels && this.toggles.edges;
    this.problems.group.visible = showPanels && this.toggles.problems && !this.toggles.beforeFix;
    this.thick.solid.visible = showPanels && this.toggles.thick && !this.toggles.beforeFix;
    this.thick.markers.visible = showPanels && this.toggles.problems && !this.toggles.beforeFix;
    this.thick.folded.visible = this.thick.markers.visible && this.thick.foldedShown;
    this.selection.visible = showPanels && !this.toggles.beforeFix;
    // The surface shows when panels do not cover it: during a solve, before any, or on request.
    this.input.mesh.visible = this.solving || !showPanels || this.toggles.clusters || !this.toggles.panels;
    // Until the first panels, as its legend line (a solve's result replaces that line).
    this.selfCrossing.visible = this.selfCrossingMarked && !this.hasPanels && this.toggles.problems;
    if (this.densityView) {
      this.input.mesh.visible = true;
      this.panels.faces.visible = false;
      this.problems.group.visible = false;
      this.thick.solid.visible = false;
      this.thick.markers.visible = false;
      this.thick.folded.visible = false;
      this.selection.visible = false;
      this.selfCrossing.visible = false;
    }
    this.requestRender();
  }
}
