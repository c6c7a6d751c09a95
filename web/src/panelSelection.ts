// The one selected panel on the page (issue 6): a click on a panel in the view selects it for
// the panel edits (Split, Merge, Lock: edits/editPanel.ts) and for its own thickness
// (Fabrication: panelThickness.ts) alike, with one highlight. It is named by a triangle of the
// loaded mesh inside it, which keeps its meaning across solves (panel ids do not): the
// selected panel is the one that triangle lies in, in the result on show. No DOM.
import type { SolveResult } from './protocol.ts';

export interface SelectedPanel {
  face: number; // the clicked triangle of the loaded mesh
  cluster: number; // its panel as the edits and clusterIds name it
  panel: number; // its panel in the panel mesh (panelOffsets, the parts list, glass pieces apart)
}

export class PanelSelection {
  private selectedFace: number | null = null;
  private readonly listeners: (() => void)[] = [];

  get face(): number | null {
    return this.selectedFace;
  }

  // A triangle of the loaded mesh, or null for none; listeners hear of a change.
  select(face: number | null): void {
    if (face === this.selectedFace) return;
    this.selectedFace = face;
    for (const listener of this.listeners) listener();
  }

  onChange(listener: () => void): void {
    this.listeners.push(listener);
  }

  // The selected panel in `result`, or null when nothing is selected or the triangle lies in
  // no panel there.
  in(result: SolveResult | null): SelectedPanel | null {
    return selectedIn(this.selectedFace, result);
  }
}

export function selectedIn(face: number | null, result: Pick<SolveResult, 'clusterIds' | 'facePanels'> | null): SelectedPanel | null {
  if (face === null || !result) return null;
  const cluster = result.clusterIds[face];
  const panel = result.facePanels[face];
  if (cluster === undefined || cluster < 0 || panel === undefined || panel < 0) return null;
  return { face, cluster, panel };
}

// The panels (panel mesh ids) of the given clusters: a cluster is one panel, or several glass
// pieces, or none when its polygon could not be built.
export function panelsOfClusters(clusters: ReadonlySet<number>, result: Pick<SolveResult, 'clusterIds' | 'facePanels'>): Set<number> {
  const out = new Set<number>();
  if (clusters.size === 0) return out;
  const n = Math.min(result.clusterIds.length, result.facePanels.length);
  for (let f = 0; f < n; f++) {
    const panel = result.facePanels[f]!;
    if (panel >= 0 && clusters.has(result.clusterIds[f]!)) out.add(panel);
  }
  return out;
}
