// The status line (role="status": the text people and tests read), the progress bar and its
// stage label. The status ends with "Done: N panels" after a solve and starts with "Error:"
// when something failed.
import type { Progress } from '@flatfacet/wasm';
import { countOutcome, element } from './dom.ts';
import { invalidPhrase, summarizeInvalid } from './invalidPanels.ts';
import { planarityWarning } from './planarity.ts';
import type { SolveResult } from './protocol.ts';

// "Done: N panels" after a solve, with what went wrong in front of it (invalidPanels.ts), or
// that the model is too far from the origin for flat panels (planarity.ts).
export function solvedSummary(result: SolveResult): { text: string; warning: boolean } {
  const panels = typeof result.report.panels === 'number' ? result.report.panels : result.panelOffsets.length - 1;
  // Without panels the report has no "invalid" list: the problem list still has the clusters.
  const summary = summarizeInvalid(result.report) ?? {
    panels: result.problems.invalidPanels.length,
    unbuilt: result.problems.unbuiltClusters.length,
    problems: [],
  };
  const warning = invalidPhrase(summary) || planarityWarning(result.report);
  const done = `${glassNote(result, panels)}Done: ${panels} panels`;
  return { text: warning ? `${warning}. ${done}` : done, warning: warning !== '' };
}

// Glass mode cuts concave panels into convex pieces, so a solve for 120 panels ends "Done: 197
// panels": said, or the count looks like a fault.
function glassNote(result: Pick<SolveResult, 'report' | 'clusterIds'>, panels: number): string {
  if (result.report.glass !== true || !result.clusterIds) return '';
  const clusters = new Set(Array.from(result.clusterIds).filter((c) => c >= 0)).size;
  return panels > clusters ? `Glass mode cut the concave ones of ${clusters} panels into convex pieces. ` : '';
}

// A retry starts the stages over (RemeshParams.retries): say so, or the bar going back looks
// like a fault.
export function retryNote(progress: Pick<Progress, 'attempt' | 'attempts'>): string {
  return progress.attempt > 1 ? ` · panels stayed invalid: new seeding, try ${progress.attempt} of ${progress.attempts}` : '';
}

// The needle rounds take the stage back from Optimize to Panels (Progress.needleRounds): say
// why, as for a retry.
export function needleNote(progress: Pick<Progress, 'needleRounds'>): string {
  return progress.needleRounds ? ' · valid, but a corner is below 1°: more rounds to widen it' : '';
}

// The panels the rounds are still working on. In the needle rounds a corner below 1° counts as
// a problem, and the valid result is kept whatever they do: "invalid" beside "valid" would
// contradict the note above, so the count is worded as what is left to mend.
export function invalidNote(progress: Pick<Progress, 'invalidPanels' | 'needleRounds'>): string {
  const count = progress.invalidPanels;
  if (count <= 0) return '';
  if (!progress.needleRounds) return ` · ${count} invalid`;
  return ` · ${count} ${count === 1 ? 'panel' : 'panels'} to mend (a corner below 1° counts)`;
}

// The stage as the progress line names it: the core's "Panels" counts panel rounds, which read
// as a count of panels ("panels 1 of 100 · 1414 invalid" while solving 2,000 panels).
export function stageName(stage: Progress['stage']): string {
  switch (stage) {
    case 'Lloyd':
      return 'Lloyd iteration';
    case 'Panels':
      return 'panel round';
    default:
      return stage.toLowerCase();
  }
}

export type StatusTone = 'info' | 'done' | 'error';

export class StatusView {
  private readonly status = element('status', HTMLParagraphElement);
  private readonly progress = element('progress', HTMLProgressElement);
  private readonly label = element('progress-label', HTMLSpanElement);

  show(text: string, tone: StatusTone = 'info'): void {
    this.pendingProgress = null; // a newer message wins over a progress line not yet drawn
    this.status.textContent = text;
    this.status.classList.toggle('error', tone === 'error');
    this.status.classList.toggle('done', tone === 'done');
  }

  error(text: string): void {
    this.show(text.startsWith('Error') ? text : `Error: ${text}`, 'error');
    countOutcome('errors');
  }

  private pendingProgress: { progress: Progress; elapsedSeconds: number } | null = null;
  private shownAttempt = 1;
  private shownNeedleRounds = false;

  // Steps can come faster than frames: draw the latest progress once per frame. A new attempt
  // (a retry) and the start of the needle rounds are drawn at once: either can be over within
  // a frame, and the line must still have said so (screen readers announce each change of
  // role="status").
  showProgress(progress: Progress, elapsedSeconds: number): void {
    if (progress.attempt !== this.shownAttempt || progress.needleRounds !== this.shownNeedleRounds) {
      this.shownAttempt = progress.attempt;
      this.shownNeedleRounds = progress.needleRounds;
      this.drawProgress(progress, elapsedSeconds);
      return;
    }
    const scheduled = this.pendingProgress !== null;
    this.pendingProgress = { progress, elapsedSeconds };
    if (scheduled) return;
    requestAnimationFrame(() => {
      const latest = this.pendingProgress;
      this.pendingProgress = null;
      if (latest) this.drawProgress(latest.progress, latest.elapsedSeconds);
    });
  }

  // Stages run in order; the bar shows the stage's share of its iteration limit.
  private drawProgress(progress: Progress, elapsedSeconds: number): void {
    const order = ['Seeding', 'Lloyd', 'Panels', 'Optimize', 'Done'];
    const stageIndex = Math.max(0, order.indexOf(progress.stage));
    const within = progress.of > 0 ? Math.min(1, progress.iteration / progress.of) : 0;
    const weights = [0.02, 0.45, 0.45, 0.08];
    let value = 0;
    for (let i = 0; i < stageIndex && i < weights.length; i++) value += weights[i]!;
    if (stageIndex < weights.length) value += weights[stageIndex]! * within;
    this.progress.value = progress.done ? 1 : value;
    const stage = stageName(progress.stage);
    this.label.textContent = progress.done ? 'done' : `${stage} ${progress.iteration}/${progress.of}`;
    this.show(`Solving: ${stage} ${progress.iteration} of ${progress.of}${needleNote(progress)}${invalidNote(progress)}${retryNote(progress)} · ${elapsedSeconds.toFixed(1)} s`);
  }

  resetProgress(label = 'idle'): void {
    this.progress.value = 0;
    this.label.textContent = label;
  }

  finishProgress(): void {
    this.progress.value = 1;
    this.label.textContent = 'done';
  }
}
