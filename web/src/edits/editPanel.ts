// The "Panel edits" section: click a panel in the view to select it (while the density brush
// is off), then split it, merge it with a neighbour (the next panel clicked), or lock / unlock
// it. It owns no design state: the edit list is the design's (DesignParams.edits, kept by the
// form), each edit goes to the editor (designEditor.ts) as one undoable step. The selection is
// the page's one (panelSelection.ts), which the per-panel thickness acts on too; this draws
// its highlight.
import * as THREE from 'three';
import { MeshBVH } from 'three-mesh-bvh';
import { element } from '../dom.ts';
import type { SolveResult } from '../protocol.ts';
import { panelsOfClusters, selectedIn, type PanelSelection } from '../panelSelection.ts';
import type { Viewer } from '../view/viewer.ts';
import { clusterProblems } from '../invalidPanels.ts';
import { EditOverlay } from './editOverlay.ts';
import { lockedPanels, neighbourPanels, type PanelEdit } from './panelEdits.ts';

export interface EditPanelHost {
  viewer: Viewer;
  selection: PanelSelection;
  result(): SolveResult | null; // the panels on show, null while solving or before any
  edits(): readonly PanelEdit[]; // of the design on show
  canEdit(): boolean; // a mesh loaded, none opening
  painting(): boolean; // the density brush has the pointer
  apply(edit: PanelEdit): void;
}

const CLICK_SLOP_PX = 5; // a press that moves further turns the view instead

export class EditPanel {
  private readonly hint = element('edit-hint', HTMLParagraphElement);
  private readonly summary = element('edit-summary', HTMLParagraphElement);
  private readonly splitButton = element('split-panel', HTMLButtonElement);
  private readonly mergeButton = element('merge-panel', HTMLButtonElement);
  private readonly lockButton = element('lock-panel', HTMLButtonElement);
  private readonly legend = element('edit-legend', HTMLDivElement);
  private readonly overlay = new EditOverlay();
  private readonly raycaster = new THREE.Raycaster();
  private bvh: MeshBVH | null = null;
  private merging = false;
  private press: { x: number; y: number; id: number } | null = null;

  constructor(private readonly host: EditPanelHost) {
    host.viewer.addOverlay(this.overlay.group);
    host.selection.onChange(() => this.show());
    const canvas = host.viewer.canvas;
    canvas.addEventListener('pointerdown', (event) => {
      this.press = event.button === 0 && !event.altKey ? { x: event.clientX, y: event.clientY, id: event.pointerId } : null;
    });
    canvas.addEventListener('pointerup', (event) => this.click(event));
    this.splitButton.addEventListener('click', () => this.edit('split'));
    this.lockButton.addEventListener('click', () => this.edit(this.selectedLocked() ? 'unlock' : 'lock'));
    this.mergeButton.addEventListener('click', () => {
      this.merging = !this.merging && this.selectedPanel() !== null;
      this.show();
    });
    window.addEventListener('keydown', (event) => {
      if (event.key === 'Escape' && (this.merging || host.selection.face !== null)) {
        if (this.merging) this.merging = false;
        else host.selection.select(null);
        this.show();
      }
    });
  }

  // Selects the panel of this triangle as a click on it in the view would (the collapsed
  // panel's legend button: a sliver is too small to click). False when no edit can be made now.
  selectFace(face: number): boolean {
    if (!this.host.result() || !this.host.canEdit() || this.host.painting()) return false;
    this.merging = false;
    this.host.selection.select(face);
    this.show();
    return true;
  }

  // A new surface: nothing selected, picking rebuilt on first use.
  surfaceChanged(): void {
    this.bvh = null;
    this.merging = false;
    this.host.selection.select(null);
    this.show();
  }

  // The panel under the selected triangle in the result on show.
  private selectedPanel(): number | null {
    const result = this.host.result();
    const face = this.host.selection.face;
    if (!result || face === null) return null;
    const panel = result.clusterIds[face];
    return panel === undefined || panel < 0 ? null : panel;
  }

  private selectedLocked(): boolean {
    const result = this.host.result();
    const panel = this.selectedPanel();
    return result !== null && panel !== null && lockedPanels(this.host.edits(), result.clusterIds).has(panel);
  }

  private pick(event: PointerEvent): number | null {
    const surface = this.host.viewer.surface;
    if (!surface) return null;
    if (!this.bvh) {
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(surface.positions, 3));
      geometry.setIndex(new THREE.BufferAttribute(surface.indices, 1));
      // Indirect: the tree keeps its own order, so a hit's faceIndex is the mesh's triangle.
      this.bvh = new MeshBVH(geometry, { indirect: true });
    }
    const rect = this.host.viewer.canvas.getBoundingClientRect();
    const ndc = new THREE.Vector2(((event.clientX - rect.left) / rect.width) * 2 - 1, -((event.clientY - rect.top) / rect.height) * 2 + 1);
    this.raycaster.setFromCamera(ndc, this.host.viewer.viewCamera);
    const hit = this.bvh.raycastFirst(this.raycaster.ray, THREE.DoubleSide);
    return hit?.faceIndex ?? null;
  }

  private click(event: PointerEvent): void {
    const press = this.press;
    this.press = null;
    if (!press || press.id !== event.pointerId || Math.hypot(event.clientX - press.x, event.clientY - press.y) > CLICK_SLOP_PX) return;
    const result = this.host.result();
    if (!result || !this.host.canEdit() || this.host.painting()) return;
    const face = this.pick(event);
    const panel = face === null ? -1 : (result.clusterIds[face] ?? -1);
    const selected = this.selectedPanel();
    if (this.merging && selected !== null) {
      // The selected panel itself, or beside the model: still waiting for the neighbour.
      if (face === null || panel < 0 || panel === selected) return;
      const surface = this.host.viewer.surface!;
      if (lockedPanels(this.host.edits(), result.clusterIds).has(panel)) {
        this.show('That panel is locked: unlock it first, or click another neighbour (Esc to stop merging).');
        return;
      }
      if (!neighbourPanels(selected, result.clusterIds, surface.indices).has(panel)) {
        this.show('That panel does not touch the selected one: click a neighbour (Esc to stop merging).');
        return;
      }
      this.merging = false;
      this.host.apply({ op: 'merge', face: this.host.selection.face!, with: face });
      return;
    }
    this.merging = false;
    this.host.selection.select(panel >= 0 ? face : null);
    this.show();
  }

  // What is wrong with the selected panel ([] when valid or nothing is selected): an invalid
  // panel is not locked, since the lock would hold it invalid through every re-solve. Refused
  // here, not in the core, whose replay of a design's edits on a re-prepared mesh can land an
  // older lock on a panel invalid there (that lock stays, and the panel is reported red).
  private selectedProblems(): string[] {
    const result = this.host.result();
    const panel = this.selectedPanel();
    return result === null || panel === null ? [] : clusterProblems(result.report, panel);
  }

  private edit(op: 'split' | 'lock' | 'unlock'): void {
    const face = this.host.selection.face;
    if (face === null || this.selectedPanel() === null || !this.host.canEdit()) return;
    if (op === 'lock' && this.selectedProblems().length > 0) return;
    this.merging = false;
    this.host.apply({ op, face });
  }

  // The result on show changed (a solve, undo, a new mesh): redraw and relabel.
  show(note = ''): void {
    const result = this.host.result();
    const edits = this.host.edits();
    const locked = result ? lockedPanels(edits, result.clusterIds) : new Set<number>();
    const panel = this.selectedPanel();
    if (panel === null) this.merging = false;
    const isLocked = panel !== null && locked.has(panel);
    const problems = isLocked ? [] : this.selectedProblems();
    const surface = this.host.viewer.surface;
    // Drawn by panel mesh ids (glass pieces and unbuilt clusters make them differ from clusters).
    const shown = selectedIn(this.host.selection.face, result)?.panel ?? null;
    const lockedShown = result ? panelsOfClusters(locked, result) : new Set<number>();
    this.overlay.set(result, this.host.viewer.offset, shown, lockedShown, (surface?.diagonal ?? 1) / 60);
    this.host.viewer.requestRender();
    const can = this.host.canEdit() && result !== null && panel !== null;
    this.splitButton.disabled = !can || isLocked;
    this.mergeButton.disabled = !can || isLocked;
    this.lockButton.disabled = !can || problems.length > 0;
    this.lockButton.textContent = isLocked ? 'Unlock panel' : 'Lock panel';
    this.mergeButton.setAttribute('aria-pressed', String(this.merging));
    this.legend.hidden = result === null || (locked.size === 0 && panel === null);
    if (note) this.hint.textContent = note;
    else if (!result) this.hint.textContent = 'Solve first, then click a panel in the view to edit it.';
    else if (this.merging) this.hint.textContent = 'Click a neighbouring panel to merge the selected one with (Esc: stop).';
    else if (panel === null) this.hint.textContent = 'Click a panel in the view to select it (the density brush must be off).';
    else {
      const name = shown === null ? `Panel ${panel}` : `P${shown + 1}`;
      const state = problems.length > 0 ? `: invalid (${problems.join(', ')}), so not locked: a lock would keep it so. Split it, merge it with a neighbour, or try another seed or panel count` : isLocked ? ' (locked: unlock it to split or merge)' : '';
      this.hint.textContent = `${name} selected${state}. Esc: clear.`;
    }
    const count = (op: PanelEdit['op']): number => edits.filter((e) => e.op === op).length;
    const parts = [`${count('split')} split`, `${count('merge')} merged`, `${locked.size} locked`];
    const panels = result ? Math.max(0, result.panelOffsets.length - 1) : 0;
    this.summary.textContent = edits.length === 0 ? 'No panel edits.' : `${edits.length} edit${edits.length === 1 ? '' : 's'}: ${parts.join(', ')}${result ? ` · ${panels} panels now` : ''}.`;
    document.body.dataset.editPanel = panel === null ? '' : String(panel);
    document.body.dataset.lockedPanels = [...locked].sort((a, b) => a - b).join(',');
    document.body.dataset.editCount = String(edits.length);
  }
}
