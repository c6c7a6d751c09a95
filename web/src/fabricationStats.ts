// The Fabrication section's numbers: max node spread, sheets, material use.
import type { FabricationResult } from './protocol.ts';

export interface FabricationRow {
  label: string;
  value: string;
  hint: string;
}

function length(value: number, units: string): string {
  return `${Number(value.toPrecision(3))} ${units}`;
}

export function fabricationRows(result: FabricationResult): FabricationRow[] {
  const spread = result.spread;
  const rows: FabricationRow[] = [
    {
      label: 'Max node spread',
      value: spread.thickness > 0 ? length(spread.maxSpread, spread.units) : '– (no thickness)',
      hint: 'how far apart the inner corners of the panels meeting at a node are: the extra chamfering that node needs',
    },
  ];
  if (result.sheets.ok) {
    rows.push({ label: 'Sheets', value: String(result.sheets.stats.sheets), hint: 'sheets the cut parts are packed onto' });
    rows.push({ label: 'Material use', value: `${(100 * result.sheets.stats.materialUse).toFixed(1)} %`, hint: 'panel area / sheet area' });
  } else {
    rows.push({ label: 'Sheets', value: 'do not fit', hint: result.sheets.message });
  }
  return rows;
}

export function renderFabricationStats(container: HTMLElement, result: FabricationResult | null): void {
  container.replaceChildren();
  if (!result) return;
  const list = document.createElement('dl');
  for (const row of fabricationRows(result)) {
    const term = document.createElement('dt');
    term.textContent = row.label;
    term.title = row.hint;
    const detail = document.createElement('dd');
    detail.textContent = row.value;
    detail.title = row.hint;
    list.append(term, detail);
  }
  container.append(list);
}
