// The page's side of mesh repair (issue 7): the "Fill holes up to (edges)" input of the Surface
// section, and, when a mesh was refused for non-manifold edges or a stray part far off, the
// offer under the status to open its largest manifold part instead. What was chosen travels with the design's mesh
// (DesignMesh.repair, meshRepair.ts).
import { element } from './dom.ts';
import { failure, type Checked } from './params.ts';
import { MAX_FILL_HOLES, type MeshRepair } from './meshRepair.ts';
import type { DesignMesh } from './share.ts';

export class RepairControl {
  private readonly fillHoles = element('fill-holes', HTMLInputElement);
  private readonly offer = element('repair-offer', HTMLDivElement);
  private readonly useLargest = element('use-largest-part', HTMLButtonElement);
  private offered: (() => void) | null = null;

  constructor() {
    this.fillHoles.min = '0';
    this.fillHoles.max = String(MAX_FILL_HOLES);
    this.useLargest.addEventListener('click', () => {
      const reopen = this.offered;
      this.hideOffer();
      reopen?.();
    });
  }

  // Committed changes only (enter, blur, spinner).
  onChange(callback: () => void): void {
    this.fillHoles.addEventListener('change', callback);
  }

  // The repair for a mesh opened now: the holes to fill; the largest part only ever on request
  // (the offer). `largestPart` carries over when the same mesh is opened again.
  read(largestPart = false): Checked<MeshRepair | undefined> {
    this.fillHoles.removeAttribute('aria-invalid');
    const text = this.fillHoles.value.trim();
    const edges = text === '' ? 0 : Number(text);
    if (!Number.isInteger(edges) || edges < 0 || edges > MAX_FILL_HOLES) {
      this.fillHoles.setAttribute('aria-invalid', 'true');
      return failure(`Fill holes up to must be a whole number of edges from 0 to ${MAX_FILL_HOLES}`);
    }
    return { ok: true, value: edges > 0 || largestPart ? { fillHoles: edges, largestPart } : undefined };
  }

  // A design opened from a link or the stored session shows its own setting.
  show(mesh: DesignMesh): void {
    this.fillHoles.value = String(mesh.repair?.fillHoles ?? 0);
    this.fillHoles.removeAttribute('aria-invalid');
  }

  // Read-only while a mesh opens (as PrepareControl.setReadOnly).
  setReadOnly(readOnly: boolean): void {
    this.fillHoles.readOnly = readOnly;
  }

  // After a refusal for non-manifold edges or a far-off part: the button reopens with the largest part.
  showOffer(faces: number, of: number, reopen: () => void): void {
    this.useLargest.title = `Open the largest manifold part: ${faces.toLocaleString('en-US')} of ${of.toLocaleString('en-US')} faces`;
    this.offered = reopen;
    this.offer.hidden = false;
  }

  hideOffer(): void {
    this.offered = null;
    this.offer.hidden = true;
  }
}
