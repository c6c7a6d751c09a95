// Typed element lookup: the page's markup is fixed, so a missing element is a programming error.
export function element<T extends HTMLElement>(id: string, type: new () => T): T {
  const found = document.getElementById(id);
  if (!(found instanceof type)) throw new Error(`page element #${id} is missing or not a ${type.name}`);
  return found;
}

// Counters on <body> (data-solves, data-errors, data-saves: sessions written to this
// browser's storage, fabrications: fabrication outputs received, strokes: paint strokes recorded, edits: panel edits recorded) let tests and scripts wait for the next outcome rather than for a status
// text that may already be showing.
export function countOutcome(name: 'solves' | 'errors' | 'saves' | 'fabrications' | 'strokes' | 'edits'): void {
  document.body.dataset[name] = String(Number(document.body.dataset[name] ?? '0') + 1);
}

// A legend line in the view (#NAME-legend with its text in #NAME-legend-text): shown with
// `note`, hidden for null. False when the page has no such line (a page without a view).
export function showLegendLine(name: string, note: string | null): boolean {
  const legend = document.getElementById(`${name}-legend`);
  const text = document.getElementById(`${name}-legend-text`);
  if (!legend || !text) return false;
  legend.hidden = note === null;
  text.textContent = note ?? '';
  return true;
}
