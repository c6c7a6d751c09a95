// The Fabrication section's numbers: max node spread, sheets, material use.
import type { FabricationResult } from './protocol.ts';
import { statsList, type StatRow } from './statsList.ts';

export type FabricationRow = StatRow;

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
  if (spread.thickness > 0) {
    const folded = spread.folded;
    const shown = folded.slice(0, 6).join(', ') + (folded.length > 6 ? ', …' : '');
    rows.push({
      label: 'Folded parts',
      value: folded.length === 0 ? '0' : `${folded.length}: ${shown}`,
      hint: 'parts whose inner face folds over at this thickness: they cannot be cut as drawn',
    });
  }
  if (result.sheets.ok) {
    rows.push({ label: 'Sheets', value: String(result.sheets.stats.sheets), hint: 'sheets the cut parts are packed onto' });
    rows.push({ label: 'Material use', value: `${(100 * result.sheets.stats.materialUse).toFixed(1)} %`, hint: 'panel area / sheet area' });
  } else {
    rows.push({ label: 'Sheets', value: 'do not fit', hint: result.sheets.message });
  }
  return rows;
}

// Why parts may not fit, in words: the page cannot know what a mesh unit is, and a
// generated example read in metres has panels metres wide.
export function sheetFitHint(result: FabricationResult, meshUnits: string): string | null {
  if (result.sheets.ok) return null;
  return `${result.sheets.message}. The mesh is read in ${meshUnits} (Mesh units): if it was modelled in other units, set them; otherwise choose a larger sheet.`;
}

// What to do about parts too thick for their panels, in words; null when none fold.
export function foldedHint(result: FabricationResult): string | null {
  const n = result.spread.thickness > 0 ? result.spread.folded.length : 0;
  if (n === 0) return null;
  return `At ${Number(result.spread.thickness.toPrecision(3))} ${result.spread.units} the inner face folds over on ${n} part${n === 1 ? '' : 's'}: they cannot be cut as drawn. Use thinner material, or fewer and larger panels.`;
}

export function renderFabricationStats(container: HTMLElement, result: FabricationResult | null, meshUnits = 'm'): void {
  container.replaceChildren();
  if (!result) return;
  container.append(statsList(fabricationRows(result)));
  // Notes under the numbers: folded parts first, then sheets the parts do not fit.
  for (const [id, text] of [['fab-folded-hint', foldedHint(result)], ['fab-fit-hint', sheetFitHint(result, meshUnits)]] as const) {
    if (!text) continue;
    const note = document.createElement('p');
    note.className = 'hint note';
    note.id = id;
    note.textContent = text;
    container.append(note);
  }
}
