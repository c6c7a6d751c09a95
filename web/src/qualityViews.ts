// Everything on the page that shows a solve's quality report, in one call: the Quality section,
// the legends of the point farthest from the design, of the sharpest corner, of a collapsed
// panel and of panels passing through each other (their markers are the viewer's). null clears
// them (a new design, nothing solved yet).
import { renderCollapsedPanel } from './collapsedPanel.ts';
import { renderCrossings } from './crossings.ts';
import { renderDesignDistance } from './farthest.ts';
import type { SolveResult } from './protocol.ts';
import { renderSharpestCorner } from './sharpestCorner.ts';
import { renderStats } from './stats.ts';

export function renderQuality(statsBox: HTMLElement, result: SolveResult | null): void {
  renderStats(statsBox, result);
  renderDesignDistance(result);
  renderSharpestCorner(result);
  renderCollapsedPanel(result);
  renderCrossings(result);
}
