// Per-panel thickness (issue 5, the paper's future work): click a panel in the view to select
// it (the page's one selection, panelSelection.ts, shared with the panel edits), then set its
// own thickness under Fabrication; empty gives it the common thickness again. Panels are
// named by their parts-list labels (P3, glass pieces P3a, ...), which is how the settings,
// links and the core refer to them; a label the panels on show do not have is kept and
// ignored by the core.
import { element } from './dom.ts';
import type { PanelSelection } from './panelSelection.ts';
import type { FabricationResult, SolveResult } from './protocol.ts';

export class PanelThicknessControl {
  private readonly input = element('fab-panel-thickness', HTMLInputElement);
  private readonly selectedText = element('fab-selected-panel', HTMLParagraphElement);
  private labels: string[] | null = null; // per panel, from the parts list of `result`
  private result: FabricationResult | null = null;
  private values: Record<string, number> = {};
  private units = '';

  // `selection`: the page's one selected panel (panelSelection.ts), chosen by a click in the
  // view; `panels`: the panels on show it is looked up in.
  constructor(
    private readonly selection: PanelSelection,
    private readonly panels: () => SolveResult | null,
    private readonly onSet: (label: string, value: number | null) => void,
  ) {
    selection.onChange(() => this.show());
    this.input.addEventListener('change', () => {
      const selected = this.selected();
      if (!selected) return;
      const text = this.input.value.trim();
      this.onSet(selected.label, text === '' ? null : Number(text));
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
    this.show();
  }

  // Other panels on show: their labels are not known yet (the selection stays: it names a
  // triangle, so it is the panel there now).
  clear(): void {
    this.labels = null;
    this.result = null;
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

  private selected(): { panel: number; label: string } | null {
    const selected = this.selection.in(this.panels());
    return selected ? { panel: selected.panel, label: this.labelOf(selected.panel) } : null;
  }

  private show(): void {
    const count = Object.keys(this.values).length;
    const others = count > 0 ? ` · ${count} panel${count === 1 ? '' : 's'} with their own` : '';
    const selected = this.selected();
    this.input.disabled = selected === null;
    if (selected) document.body.dataset.selectedPanel = selected.label;
    else delete document.body.dataset.selectedPanel;
    if (!selected) {
      this.input.value = '';
      this.selectedText.textContent = `click a panel in the view to give it its own thickness${others}`;
      return;
    }
    const own = this.values[selected.label];
    if (document.activeElement !== this.input) this.input.value = own === undefined ? '' : String(own);
    this.input.placeholder = 'common';
    this.selectedText.textContent = `selected ${selected.label}${own === undefined ? ' (common thickness)' : ` (${own} ${this.units})`}${others}`;
  }
}
