// The report's invalid panels (its "invalid" list, core/quality/report_json.cpp) in a designer's
// words: how many, what is wrong with them, and what to try. The CLI says the same on exit 3
// ("4 panels invalid (not_star 3, spike 1)"), with the report's names.
import type { QualityReport } from './protocol.ts';

// Every problem name the core writes for a built panel (panel_problems, then list_invalid_panels'
// "off_plane" and "quality_check"), in the core's order; "unbuilt" (a cluster without a panel) is counted apart.
// tests/web/invalidPanels.test.mjs checks this against the core's list.
export const PROBLEM_WORDS: Readonly<Record<string, string>> = {
  not_simple: 'self-intersecting',
  flipped: 'flipped',
  not_star: 'not star-shaped',
  spike: 'spike',
  too_few_vertices: 'under 3 corners',
  not_disk: 'not a disk',
  acute_corner: 'acute corner',
  off_plane: 'off its plane',
  quality_check: 'failed the quality check',
};

export interface InvalidSummary {
  panels: number; // built panels with a problem (shown red)
  unbuilt: number; // clusters that could not become a panel
  problems: [string, number][]; // designer's words and how many panels have that problem
}

interface Entry {
  panel: number;
  cluster: number;
  problems: string[];
}

function entries(report: QualityReport): Entry[] | null {
  const list = report.invalid;
  if (!Array.isArray(list)) return null;
  return list.map((item: unknown) => {
    const record = (typeof item === 'object' && item !== null ? item : {}) as Record<string, unknown>;
    const panel = typeof record.panel === 'number' ? record.panel : -1;
    const cluster = typeof record.cluster === 'number' ? record.cluster : -1;
    const problems = Array.isArray(record.problems) ? record.problems.filter((p): p is string => typeof p === 'string') : [];
    return { panel, cluster, problems };
  });
}

// null when the report has no "invalid" list (no panels yet).
export function summarizeInvalid(report: QualityReport): InvalidSummary | null {
  const list = entries(report);
  if (!list) return null;
  const counts = new Map<string, number>();
  let panels = 0;
  let unbuilt = 0;
  for (const entry of list) {
    if (entry.panel < 0 || entry.problems.includes('unbuilt')) {
      unbuilt++;
      continue;
    }
    panels++;
    for (const name of entry.problems) counts.set(name, (counts.get(name) ?? 0) + 1);
  }
  const problems: [string, number][] = [];
  for (const [name, words] of Object.entries(PROBLEM_WORDS)) {
    const count = counts.get(name);
    if (count) problems.push([words, count]);
  }
  // A name this page does not know yet still shows, as the core wrote it.
  for (const [name, count] of counts) if (!(name in PROBLEM_WORDS)) problems.push([name.replace(/_/g, ' '), count]);
  return { panels, unbuilt, problems };
}

// The problem names the report lists for one panel (by its number in the panel mesh): null
// when it is not listed (valid) or the report has no list.
export function panelProblems(report: QualityReport, panel: number): string[] | null {
  return entries(report)?.find((entry) => entry.panel === panel)?.problems ?? null;
}

// What is wrong with the panel of one cluster (as the edits and clusterIds name it; its glass
// pieces together), in the words above and their order: [] when the report lists nothing for it.
export function clusterProblems(report: QualityReport, cluster: number): string[] {
  const names = new Set<string>();
  for (const entry of entries(report) ?? []) if (entry.cluster === cluster) for (const name of entry.problems) names.add(name);
  const words = Object.entries(PROBLEM_WORDS)
    .filter(([name]) => names.has(name))
    .map(([, text]) => text);
  for (const name of names) if (!(name in PROBLEM_WORDS)) words.push(name === 'unbuilt' ? 'no panel built' : name.replace(/_/g, ' '));
  return words;
}

// "not star-shaped 2, spike 1": what is wrong with the panels, '' when nothing is named.
export function problemsPhrase(summary: InvalidSummary): string {
  return summary.problems.map(([words, count]) => `${words} ${count}`).join(', ');
}

// "2 invalid panels (shown red: not star-shaped 1, spike 1); 1 cluster could not become a
// panel; another seed or panel count (more or fewer) may make every panel valid", or '' when
// all are valid.
export function invalidPhrase(summary: InvalidSummary): string {
  const parts: string[] = [];
  if (summary.panels > 0) {
    const what = problemsPhrase(summary);
    parts.push(`${summary.panels} invalid panel${summary.panels === 1 ? '' : 's'} (shown red${what ? `: ${what}` : ''})`);
  }
  if (summary.unbuilt > 0) {
    parts.push(`${summary.unbuilt} cluster${summary.unbuilt === 1 ? '' : 's'} could not become ${summary.unbuilt === 1 ? 'a panel' : 'panels'}`);
  }
  if (parts.length === 0) return '';
  return `${parts.join('; ')}; another seed or panel count (more or fewer) may make every panel valid`;
}
