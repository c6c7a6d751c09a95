// What the designer takes away: the OBJ and parts-list downloads, the share link, and the
// note under the surface about keeping the session in this browser. No design state here: the
// controller (app.ts) passes in what to export or share.
import { element } from './dom.ts';
import type { ChainLoss } from './designMachine.ts';
import { designStem, downloadText } from './exports.ts';
import type { SolveResult } from './protocol.ts';
import { shareHash, type DesignState } from './share.ts';
import { forgetShareLink, publishShareLink } from './shareLink.ts';

export type ShareOutcome = { ok: true; text: string } | { ok: false; message: string };

export class Outputs {
  private readonly shareRow = element('share-row', HTMLDivElement);
  private readonly shareField = element('share-link', HTMLInputElement);
  private readonly sessionNote = element('session-note', HTMLParagraphElement);
  private lastWrittenHash = '';

  // The hash this page last put into the address bar.
  get currentHash(): string {
    return this.lastWrittenHash;
  }

  // The parts list comes from the Fabrication section (fabricationPanel.ts).
  exportFile(kind: 'obj', meshFileName: string, result: SolveResult): void {
    if (kind === 'obj') downloadText(`${designStem(meshFileName)}-panels.obj`, result.objText, 'model/obj');
  }

  // `lost`: why the result's warm-start chain cannot be replayed (the link then solves afresh).
  async share(state: DesignState, lost: ChainLoss | null): Promise<ShareOutcome> {
    const hash = shareHash(state);
    if (!hash.ok) return hash;
    const published = await publishShareLink(hash.value, this.shareField, this.shareRow);
    this.lastWrittenHash = published.hash;
    const caveat =
      lost === 'changed-mid-solve'
        ? ' A parameter changed while that solve ran, so the link solves afresh and its panels may differ slightly.'
        : lost === 'long-chain'
          ? ' That result came from a longer chain of warm starts than a link carries, so the link solves afresh and its panels may differ slightly.'
          : '';
    return { ok: true, text: published.copied ? `Share link copied to the clipboard.${caveat}` : `The clipboard is not available: copy the share link from the field below.${caveat}` };
  }

  // The design changed: a link in the address bar no longer describes it.
  forgetLink(): void {
    if (location.hash === '' && this.shareRow.hidden) return;
    forgetShareLink(this.shareField, this.shareRow);
    this.lastWrittenHash = '';
  }

  // Visible notes about the stored session: why the last one could not be restored (shown
  // until the page closes), and why the current design could not be kept (until it can).
  private restoreNote: string | null = null;
  private saveNote: string | null = null;

  noteRestore(text: string): void {
    this.restoreNote = text;
    this.showNotes();
  }

  noteSave(text: string | null): void {
    this.saveNote = text;
    this.showNotes();
  }

  private showNotes(): void {
    const notes = [this.restoreNote, this.saveNote].filter((note): note is string => note !== null);
    this.sessionNote.textContent = notes.map((note) => `${note[0]!.toUpperCase()}${note.slice(1)}.`).join(' ');
    this.sessionNote.hidden = notes.length === 0;
  }
}
