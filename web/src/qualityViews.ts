// Everything on the page that shows a solve's quality report, in one call: the Quality section,
// the legend of the point farthest from the design and that of the sharpest corner (their
// markers are the viewer's). null clears them (a new design, nothing solved yet).
import { renderDesignDistance } from './farthest.ts';
import type { SolveResult } from './protocol.ts';
import { renderSharpestCorner } from './sharpestCorner.ts';
import { renderStats } from './stats.ts';

export function renderQuality(statsBox: HTMLElement, result: SolveResult | null): void {
  renderStats(statsBox, result);
  renderDesignDistance(result);
  renderSharpestCorner(result);
}
