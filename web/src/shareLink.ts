// Publishing a share link: into the address bar (replaceState, so no reload and no history
// entry), the clipboard, and a read-only field for when the clipboard is refused.
import { stateToHash, type DesignState } from './share.ts';

export interface Published {
  hash: string;
  url: string;
  copied: boolean;
}

export async function publishShareLink(state: DesignState, field: HTMLInputElement, row: HTMLElement): Promise<Published> {
  const hash = stateToHash(state);
  history.replaceState(null, '', hash);
  const url = location.href;
  field.value = url;
  row.hidden = false;
  try {
    await navigator.clipboard.writeText(url);
    return { hash, url, copied: true };
  } catch {
    field.select();
    return { hash, url, copied: false };
  }
}
