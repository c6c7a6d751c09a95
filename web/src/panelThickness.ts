// Per-panel thickness (issue 5, the paper's future work): click a panel in the view to select
// it (a click, not an orbit drag), then set its own thickness under Fabrication; empty gives
// it the common thickness again. Panels are named by their parts-list labels (P3, glass
// pieces P3a, ...), which is how the settings, links and the core refer to them; a label
// the panels on show do not have is kept and ignored by the core.
import { element } from './dom.ts';
import type { FabricationResult } from './protocol.ts';
import type { Viewer } from './view/viewer.ts';

const CLICK_SLOP = 5; // px a pointer may move between down and up and still be a click

export class PanelThicknessControl {
  private readonly input = element('fab-panel-thickness', HTMLInputElement);
  private readonly selectedText = element('fab-selected-panel', HTMLParagraphElement);
  private selected: { panel: number; label: string } | null = null;
  private labels: string[] | null = null; // per panel, from the parts list of `result`
  private result: FabricationResult | null = null;
  private values: Record<string, number> = {};
  private units = '';

  constructor(
    private readonly viewer: Viewer,
    private readonly onSet: (label: string, value: number | null) => void,
  ) {
    let down: { x: number; y: number } | null = null;
    const canvas = viewer.canvas;
    canvas.addEventListener('pointerdown', (e) => (down = { x: e.clientX, y: e.clientY }));
    canvas.addEventListener('pointerup', (e) => {
      if (down && Math.hypot(e.clientX - down.x, e.clientY - down.y) <= CLICK_SLOP) this.pick(e.clientX, e.clientY);
      down = null;
    });
    this.input.addEventListener('change', () => {
      if (!this.selected) return;
      const text = this.input.value.trim();
      this.onSet(this.selected.label, text === '' ? null : Number(text));
    });
    this.show();
  }

  // The settings' per-panel thicknesses and units (after any change).
  setValues(values: Record<string, number>, units: string): void {
    this.values = values;
    this.units = units;
    this.show();
  }

  // New fabrication outputs for the same panels: labels may be read from them.
  setResult(result: FabricationResult | null): void {
    if (result !== this.result) this.labels = null;
    this.result = result;
  }

  // Other panels on show: nothing is selected.
  clear(): void {
    this.selected = null;
    this.labels = null;
    this.result = null;
    this.viewer.setSelectedPanel(null);
    this.show();
  }

  private labelOf(panel: number): string {
    if (!this.labels && this.result) {
      const parsed: unknown = JSON.parse(this.result.partsJson);
      const panels = (parsed as { panels?: { label?: unknown }[] }).panels ?? [];
      this.labels = panels.map((p, i) => (typeof p.label === 'string' ? p.label : `P${i + 1}`));
    }
    return this.labels?.[panel] ?? `P${panel + 1}`;
  }

  private pick(x: number, y: number): void {
    const panel = this.viewer.panelAt(x, y);
    this.selected = panel === null ? null : { panel, label: this.labelOf(panel) };
    this.viewer.setSelectedPanel(panel);
    this.show();
    if (this.selected) document.body.dataset.selectedPanel = this.selected.label;
    else delete document.body.dataset.selectedPanel;
  }

  private show(): void {
    const count = Object.keys(this.values).length;
    const others = count > 0 ? ` · ${count} panel${count === 1 ? '' : 's'} with their own` : '';
    this.input.disabled = this.selected === null;
    if (!this.selected) {
      this.input.value = '';
      this.selectedText.textContent = `click a panel in the view to give it its own thickness${others}`;
      return;
    }
    const own = this.values[this.selected.label];
    this.input.value = own === undefined ? '' : String(own);
    this.input.placeholder = 'common';
    this.selectedText.textContent = `selected ${this.selected.label}${own === undefined ? ' (common thickness)' : ` (${own} ${this.units})`}${others}`;
  }
}
