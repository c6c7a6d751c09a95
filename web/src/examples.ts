// The examples of the "Example" select: architectural meshes shipped beside the page (copied
// from ../shared/meshes at build time) and surfaces the core generates. No DOM.

export interface FileExample {
  kind: 'file';
  id: string;
  label: string;
  file: string; // under examples/ next to index.html
  panels: number; // a sensible count for this mesh
  up: 'y' | 'z';
}

export interface ShapeExample {
  kind: 'shape';
  id: string;
  label: string;
  shape: string; // Session.loadShape name
  triangles: number;
  panels: number;
  up: 'z';
}

export type Example = FileExample | ShapeExample;

export const EXAMPLES: readonly Example[] = [
  { kind: 'file', id: 'hyperboloid_s4', label: 'Hyperboloid tower (50k triangles)', file: 'hyperboloid_s4.off', panels: 300, up: 'y' },
  { kind: 'file', id: 'inspired_mesh', label: 'Freeform roof (scanned, 4k triangles)', file: 'inspired_mesh.obj', panels: 120, up: 'z' },
  { kind: 'file', id: 'YasIsland', label: 'Yas Island grid shell', file: 'YasIsland.off', panels: 150, up: 'z' },
  { kind: 'file', id: 'epcot', label: 'Geodesic sphere (Epcot)', file: 'epcot.off', panels: 100, up: 'z' },
  { kind: 'shape', id: 'saddle', label: 'Saddle (generated)', shape: 'saddle', triangles: 8000, panels: 120, up: 'z' },
  { kind: 'shape', id: 'barrel_vault', label: 'Barrel vault (generated)', shape: 'barrel_vault', triangles: 8000, panels: 120, up: 'z' },
  { kind: 'shape', id: 'groin_vault', label: 'Groin vault (generated)', shape: 'groin_vault', triangles: 8000, panels: 120, up: 'z' },
  { kind: 'shape', id: 'helicoid', label: 'Helicoid (generated)', shape: 'helicoid', triangles: 8000, panels: 120, up: 'z' },
  { kind: 'shape', id: 'freeform_roof', label: 'Freeform roof (generated)', shape: 'freeform_roof', triangles: 8000, panels: 120, up: 'z' },
  { kind: 'shape', id: 'cone', label: 'Conical tent (generated)', shape: 'cone', triangles: 8000, panels: 120, up: 'z' },
];

export const DEFAULT_EXAMPLE_ID = 'hyperboloid_s4';
// The default when the site was built without ../shared/meshes (no file examples).
export const FALLBACK_EXAMPLE_ID = 'freeform_roof';

export function findExample(id: string): Example | undefined {
  return EXAMPLES.find((example) => example.id === id);
}

// What the page calls a design's mesh, the file name its exports are named after, and which
// way is up (a file the designer opened: guessed from its shape).
export function describeDesign(design: { kind: 'example'; id: string } | { kind: 'file'; name: string }): { example: Example | undefined; label: string; fileName: string; up: 'y' | 'z' | 'guess' } {
  const example = design.kind === 'example' ? findExample(design.id) : undefined;
  if (example) return { example, label: example.label, fileName: example.kind === 'file' ? example.file : example.shape, up: example.up };
  return design.kind === 'file' ? { example, label: design.name, fileName: design.name, up: 'guess' } : { example, label: design.id, fileName: 'design', up: 'guess' };
}
