// The Surface section's preparation inputs: "Subdivide levels" and "Target edge length" (empty:
// automatic). How the design's mesh is prepared for panelling (Session.prepare); the
// preparation travels with the design (DesignMesh.prepare), so a link or a reload prepares the
// same mesh. When a change prepares the mesh again: preparation.ts.
import { element } from './dom.ts';
import { failure, type Checked, type DesignParams } from './params.ts';
import { prepareOf, type PrepareChoice } from './preparation.ts';
import { isEdgeLength, MAX_EDGE_LENGTH, MAX_SUBDIVIDE, type DesignMesh, type MeshPrepare } from './share.ts';

export class PrepareControl {
  private readonly subdivide = element('subdivide', HTMLInputElement);
  private readonly edgeLength = element('edge-length', HTMLInputElement);

  constructor() {
    this.subdivide.min = '0';
    this.subdivide.max = String(MAX_SUBDIVIDE);
    this.edgeLength.max = String(MAX_EDGE_LENGTH);
  }

  // Committed changes only (enter, blur, spinner).
  onChange(callback: () => void): void {
    this.subdivide.addEventListener('change', callback);
    this.edgeLength.addEventListener('change', callback);
  }

  // What the inputs ask for, checked.
  choice(): Checked<PrepareChoice> {
    this.subdivide.removeAttribute('aria-invalid');
    this.edgeLength.removeAttribute('aria-invalid');
    const text = this.subdivide.value.trim();
    const levels = text === '' ? 0 : Number(text);
    if (!Number.isInteger(levels) || levels < 0 || levels > MAX_SUBDIVIDE) {
      this.subdivide.setAttribute('aria-invalid', 'true');
      return failure(`Subdivide levels must be a whole number from 0 to ${MAX_SUBDIVIDE}`);
    }
    const edgeText = this.edgeLength.value.trim();
    if (edgeText === '') return { ok: true, value: { subdivide: levels } };
    const edge = Number(edgeText);
    if (!isEdgeLength(edge)) {
      this.edgeLength.setAttribute('aria-invalid', 'true');
      return failure('Target edge length must be a positive number in the mesh\'s units (empty: automatic)');
    }
    return { ok: true, value: { subdivide: levels, edgeLength: edge } };
  }

  // The preparation for a mesh opened now with these parameters.
  read(params: DesignParams): Checked<MeshPrepare> {
    const choice = this.choice();
    return choice.ok ? { ok: true, value: prepareOf(params.panels, choice.value) } : choice;
  }

  // A design opened from a link or the stored session, or prepared again, shows its own.
  show(mesh: DesignMesh): void {
    this.subdivide.value = String(mesh.prepare?.subdivide ?? 0);
    this.edgeLength.value = mesh.prepare?.edgeLength !== undefined ? String(mesh.prepare.edgeLength) : '';
    this.subdivide.removeAttribute('aria-invalid');
    this.edgeLength.removeAttribute('aria-invalid');
  }

  // Read-only while a mesh opens or is prepared: that open has read these values and shows its
  // mesh's own when it ends, so a value typed meanwhile would be dropped without a word.
  setReadOnly(readOnly: boolean): void {
    this.subdivide.readOnly = readOnly;
    this.edgeLength.readOnly = readOnly;
  }

  // A new mesh: an edge length in the previous mesh's units means nothing for it.
  forgetEdgeLength(): void {
    this.edgeLength.value = '';
  }
}
