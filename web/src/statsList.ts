// A <dl> of labelled numbers with hover hints, as the Quality and Fabrication sections show
// them (stats.ts, fabricationStats.ts).
export interface StatRow {
  label: string;
  value: string;
  hint: string;
  warn?: boolean;
}

export function statsList(rows: readonly StatRow[]): HTMLDListElement {
  const list = document.createElement('dl');
  for (const row of rows) {
    const term = document.createElement('dt');
    term.textContent = row.label;
    term.title = row.hint;
    const detail = document.createElement('dd');
    detail.textContent = row.value;
    detail.title = row.hint;
    if (row.warn) detail.classList.add('warn');
    list.append(term, detail);
  }
  return list;
}
