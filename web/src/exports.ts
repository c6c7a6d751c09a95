// Downloads: a Blob URL clicked through an <a download>, which browsers (and Playwright's
// download event) treat as a real file download.

export function downloadText(fileName: string, text: string, mimeType: string): void {
  const url = URL.createObjectURL(new Blob([text], { type: mimeType }));
  const link = document.createElement('a');
  link.href = url;
  link.download = fileName;
  link.style.display = 'none';
  document.body.appendChild(link);
  link.click();
  link.remove();
  // Revoke later: the download reads the Blob after the click returns.
  setTimeout(() => URL.revokeObjectURL(url), 60_000);
}

// "hyperboloid_s4.off" -> "hyperboloid_s4": the stem for "<name>-panels.obj".
export function designStem(meshName: string): string {
  const base = meshName.replace(/^.*[\\/]/, '');
  const dot = base.lastIndexOf('.');
  const stem = (dot > 0 ? base.slice(0, dot) : base).replace(/[^A-Za-z0-9._-]+/g, '_');
  return stem.length > 0 ? stem : 'design';
}
