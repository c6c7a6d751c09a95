// Publishing a share link: into the address bar (replaceState, so no reload and no history
// entry), the clipboard, and a read-only field for when the clipboard is refused. Once the
// design changes the link is taken out of the address bar again, so that a reload restores
// the latest design (from this browser's storage) rather than the older linked one.
export interface Published {
  hash: string;
  url: string;
  copied: boolean;
}

export async function publishShareLink(hash: string, field: HTMLInputElement, row: HTMLElement): Promise<Published> {
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

// The address bar's link (one published here or the one the page was opened with) no longer
// describes the design: remove it, and hide the field holding a link that is now stale.
export function forgetShareLink(field: HTMLInputElement, row: HTMLElement): void {
  if (location.hash !== '') history.replaceState(null, '', `${location.pathname}${location.search}`);
  row.hidden = true;
  field.value = '';
}
