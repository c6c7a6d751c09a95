// The "Example" select and the mesh caption over the view: which examples this site offers
// (the file examples only when shipped), which one is the default, and what the select and
// the caption show for the loaded mesh.
import type { MeshInfo } from '@flatfacet/wasm';
import { selfCrossingNote } from './crossings.ts';
import { element } from './dom.ts';
import { DEFAULT_EXAMPLE_ID, EXAMPLES, FALLBACK_EXAMPLE_ID, findExample } from './examples.ts';
import type { DesignMesh } from './share.ts';

export class ExamplePicker {
  private readonly select = element('example', HTMLSelectElement);
  private readonly fileOption = new Option('Your mesh', 'file');
  private defaultIdValue = DEFAULT_EXAMPLE_ID;

  constructor(onPick: (id: string) => void) {
    for (const example of EXAMPLES) this.select.add(new Option(example.label, example.id));
    this.select.add(this.fileOption);
    this.fileOption.hidden = true;
    this.select.addEventListener('change', () => {
      if (this.select.value !== 'file') onPick(this.select.value);
    });
  }

  get defaultId(): string {
    return this.defaultIdValue;
  }

  // The file examples this site ships (examples/index.json); the others are hidden, and
  // without the default one the page starts on a generated surface.
  setAvailableFiles(files: Set<string>): void {
    for (const option of Array.from(this.select.options)) {
      const example = findExample(option.value);
      if (example?.kind === 'file') option.hidden = !files.has(example.file);
    }
    const preferred = findExample(DEFAULT_EXAMPLE_ID);
    this.defaultIdValue = preferred?.kind === 'file' && !files.has(preferred.file) ? FALLBACK_EXAMPLE_ID : DEFAULT_EXAMPLE_ID;
  }

  // Shows the loaded design (or the default before any).
  sync(design: DesignMesh | undefined): void {
    this.select.value = design?.kind === 'example' ? design.id : design ? 'file' : this.defaultIdValue;
    this.fileOption.hidden = design?.kind !== 'file';
    this.fileOption.text = design?.kind === 'file' ? `Your mesh: ${design.name}` : 'Your mesh';
  }
}

// The caption over the view, what the page's reader left out or applied (a glTF's lines, its
// other scenes) and the repairs the core made on load.
export function showMeshInfo(label: string, info: MeshInfo, read: string[]): void {
  element('mesh-title', HTMLSpanElement).textContent = label;
  const loops = info.boundaryLoops === 1 ? '1 boundary loop' : `${info.boundaryLoops} boundary loops`;
  element('mesh-details', HTMLSpanElement).textContent = `${info.triangles.toLocaleString('en')} triangles · ${info.vertices.toLocaleString('en')} vertices · ${loops} · genus ${info.genus}`;
  const cleanup = element('mesh-cleanup', HTMLParagraphElement);
  const sentences = [];
  if (read.length > 0) sentences.push(`Read from the file: ${read.join('; ')}.`);
  if (info.cleanup.length > 0) sentences.push(`Repaired on load: ${info.cleanup.join('; ')}.`);
  cleanup.textContent = sentences.join(' ');
  cleanup.hidden = sentences.length === 0;
  const crossing = element('mesh-self-crossing', HTMLParagraphElement);
  crossing.textContent = selfCrossingNote(info);
  crossing.hidden = crossing.textContent === '';
  const prepared = element('mesh-prepared', HTMLParagraphElement);
  prepared.textContent = info.prepared.length > 0 ? `Prepared for the panels: ${info.prepared.join('; ')}.` : '';
  prepared.hidden = info.prepared.length === 0;
}
