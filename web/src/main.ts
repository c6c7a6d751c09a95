// Entry point: wires the page's inputs to the App and decides what to open first: a share
// link in the URL, else the last session kept in this browser, else the default example.
import { App } from './app.ts';
import { element } from './dom.ts';
import { availableExampleFiles } from './meshFiles.ts';
import { bindRhinoPicker } from './rhino/rhinoOpen.ts';
import { loadSession } from './sessionStore.ts';
import { hashToState, isShareHash } from './share.ts';
import type { Viewer } from './view/viewer.ts';
import './styles.css';

const app = new App();

function bindFileInput(): void {
  const input = element('open-mesh', HTMLInputElement);
  input.addEventListener('change', () => {
    const file = input.files?.[0];
    if (file) void app.openFile(file);
    input.value = ''; // opening the same file again still fires
  });
}

function bindDrop(): void {
  const viewport = element('viewport', HTMLElement);
  const hint = element('drop-hint', HTMLDivElement);
  const show = (on: boolean): void => {
    hint.hidden = !on;
    viewport.classList.toggle('dragging', on);
  };
  viewport.addEventListener('dragover', (event) => {
    event.preventDefault();
    if (event.dataTransfer) event.dataTransfer.dropEffect = 'copy';
    show(true);
  });
  viewport.addEventListener('dragleave', () => show(false));
  viewport.addEventListener('drop', (event) => {
    event.preventDefault();
    show(false);
    const file = event.dataTransfer?.files[0];
    if (file) void app.openFile(file);
  });
}

function bindViewToggles(viewer: Viewer): void {
  const ids = { clusters: 'show-clusters', panels: 'show-panels', edges: 'show-edges', problems: 'show-problems', beforeFix: 'show-before-fix', deviation: 'show-deviation', thick: 'show-thick' } as const;
  const read = (): void => {
    const beforeFix = element(ids.beforeFix, HTMLInputElement).checked;
    const deviation = element(ids.deviation, HTMLInputElement).checked;
    viewer.setToggles({
      clusters: element(ids.clusters, HTMLInputElement).checked,
      panels: element(ids.panels, HTMLInputElement).checked,
      edges: element(ids.edges, HTMLInputElement).checked,
      problems: element(ids.problems, HTMLInputElement).checked,
      beforeFix,
      deviation,
      thick: element(ids.thick, HTMLInputElement).checked,
    });
    element('view-legend', HTMLDivElement).hidden = !beforeFix;
    // Before the fix draws other polygons: the deviation colours are for the panels.
    element('deviation-legend', HTMLDivElement).hidden = !deviation || beforeFix;
  };
  for (const id of Object.values(ids)) element(id, HTMLInputElement).addEventListener('change', read);
  read();
}

// A hostile or broken link must not stop the page: say why, and keep (or, at start, show
// the default) surface.
async function openFromHash(hash: string, atStart: boolean): Promise<void> {
  const decoded = hashToState(hash);
  if (decoded.ok) {
    await app.openState(decoded.value, 'Opening the shared design', true);
    return;
  }
  if (atStart) await app.openExample(app.defaultExampleId, { solve: false, note: '' });
  app.showError(`this share link cannot be opened: ${decoded.message}.`);
}

// Enter in a parameter field solves (during a solve the field's change event updates it);
// Escape cancels. Enter in a Surface input is left to its change event, which opens or
// prepares the mesh anew and solves: a Remesh first would start a preparation, and the change
// that follows would find the mesh opening and be dropped.
const SURFACE_INPUTS = new Set(['subdivide', 'edge-length', 'fill-holes']);
function bindKeys(): void {
  const panel = document.querySelector('aside.panel');
  panel?.addEventListener('keydown', (event) => {
    const target = event.target;
    if (event instanceof KeyboardEvent && event.key === 'Enter' && target instanceof HTMLInputElement && target.type === 'number' && !SURFACE_INPUTS.has(target.id) && !app.isSolving) {
      app.remesh();
    }
  });
  window.addEventListener('keydown', (event) => {
    if (event.key === 'Escape' && app.isSolving) app.cancel();
  });
}

async function start(): Promise<void> {
  bindKeys();
  bindFileInput();
  bindDrop();
  bindRhinoPicker((file) => void app.openFile(file));
  bindViewToggles(app.viewerForToggles);
  window.addEventListener('hashchange', () => {
    if (isShareHash(location.hash) && location.hash !== app.currentHash) void openFromHash(location.hash, false);
  });
  app.setAvailableExampleFiles(await availableExampleFiles());
  if (isShareHash(location.hash)) {
    await openFromHash(location.hash, true);
    return;
  }
  const stored = await loadSession();
  if (stored.kind === 'ok') {
    await app.openState(stored.state, 'Restoring your last session', false);
    return;
  }
  if (stored.kind === 'error') app.noteRestoreFailure(stored.message);
  await app.openExample(app.defaultExampleId);
}

void start();
