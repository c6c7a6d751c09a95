// The "Subdivide levels" input of the Surface section: how an opened mesh is prepared for
// panelling (Session.prepare). The levels and the panel count at opening time travel with the
// design (DesignMesh.prepare), so a link or a reload prepares the same mesh.
import { element } from './dom.ts';
import { failure, type Checked, type DesignParams } from './params.ts';
import { MAX_SUBDIVIDE, type DesignMesh, type MeshPrepare } from './share.ts';

export class PrepareControl {
  private readonly subdivide = element('subdivide', HTMLInputElement);

  constructor() {
    this.subdivide.min = '0';
    this.subdivide.max = String(MAX_SUBDIVIDE);
  }

  // Committed changes only (enter, blur, spinner).
  onChange(callback: () => void): void {
    this.subdivide.addEventListener('change', callback);
  }

  // The preparation for a mesh opened now with these parameters.
  read(params: DesignParams): Checked<MeshPrepare> {
    this.subdivide.removeAttribute('aria-invalid');
    const text = this.subdivide.value.trim();
    const levels = text === '' ? 0 : Number(text);
    if (!Number.isInteger(levels) || levels < 0 || levels > MAX_SUBDIVIDE) {
      this.subdivide.setAttribute('aria-invalid', 'true');
      return failure(`Subdivide levels must be a whole number from 0 to ${MAX_SUBDIVIDE}`);
    }
    return { ok: true, value: { panels: params.panels, subdivide: levels } };
  }

  // A design opened from a link or the stored session shows its own levels.
  show(mesh: DesignMesh): void {
    this.subdivide.value = String(mesh.prepare?.subdivide ?? 0);
    this.subdivide.removeAttribute('aria-invalid');
  }
}
