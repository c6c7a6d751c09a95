// The Density section's brush: the "Paint density" toggle, brush mode, radius and strength,
// "Clear paint", the colour map of the field on the surface and its legend. It owns no design
// state: the field on show comes from the editor (designEditor.ts), finished strokes go back
// to it. With a density expression set, the map shows the effective density the solver uses,
// expression x paint: the expression's values come from the core (they need curvature and the
// bounding box), asked for once per expression and surface.
import { element } from '../dom.ts';
import type { Viewer } from '../view/viewer.ts';
import { BrushController } from './brushController.ts';
import { BRUSH_MODES, type BrushMode } from './brushPainter.ts';
import { expressionLog2, fieldColors, log2Colors } from './densityColors.ts';

export interface DensityPanelHost {
  viewer: Viewer;
  field(): Int8Array | null; // the field of the design on show
  expression(): string; // the design's density expression ('' for none)
  requestExpression(expression: string): void; // answered by expressionValues()
  canPaint(): boolean; // a mesh loaded and no other opening
  strokeEnded(field: Int8Array): void;
  clear(): void;
}

export class DensityPanel {
  private readonly toggle = element('paint-toggle', HTMLButtonElement);
  private readonly clearButton = element('clear-paint', HTMLButtonElement);
  private readonly mode = element('brush-mode', HTMLSelectElement);
  private readonly radius = element('brush-radius', HTMLInputElement);
  private readonly strength = element('brush-strength', HTMLInputElement);
  private readonly radiusValue = element('brush-radius-value', HTMLSpanElement);
  private readonly strengthValue = element('brush-strength-value', HTMLSpanElement);
  private readonly legend = element('density-legend', HTMLDivElement);
  private readonly legendTitle = element('density-legend-title', HTMLSpanElement);
  private readonly brush: BrushController;
  private previewColors: Float32Array | null = null;
  // The expression whose values were asked for on this surface, and their log2 once answered.
  private expressionAsked: string | null = null;
  private expressionValues: Float32Array | null = null;

  constructor(private readonly host: DensityPanelHost) {
    this.brush = new BrushController({
      viewer: host.viewer,
      settings: () => ({
        radius: Number(this.radius.value) / 100,
        strength: Number(this.strength.value),
        mode: (BRUSH_MODES as readonly string[]).includes(this.mode.value) ? (this.mode.value as BrushMode) : 'add',
      }),
      field: () => host.field(),
      preview: (log2) => this.preview(log2),
      strokeEnded: (field) => host.strokeEnded(field),
    });
    this.toggle.addEventListener('click', () => this.setPainting(!this.brush.active));
    this.clearButton.addEventListener('click', () => host.clear());
    const showValues = (): void => {
      this.radiusValue.textContent = `${this.radius.value}%`;
      this.strengthValue.textContent = Number(this.strength.value).toFixed(2);
    };
    this.radius.addEventListener('input', showValues);
    this.strength.addEventListener('input', showValues);
    showValues();
  }

  get painting(): boolean {
    return this.brush.active;
  }

  setPainting(on: boolean): void {
    const allowed = on && this.host.canPaint();
    this.brush.setEnabled(allowed);
    this.toggle.setAttribute('aria-pressed', String(allowed));
    this.legend.hidden = !allowed;
    this.show();
  }

  // A new surface in the viewer (or a new worker): the expression's values are asked again.
  surfaceChanged(): void {
    this.brush.surfaceChanged();
    this.expressionAsked = null;
    this.expressionValues = null;
    this.show();
  }

  // The core's values of `expression` per vertex (empty: refused).
  expressionAnswered(expression: string, values: Float64Array): void {
    const surface = this.host.viewer.surface;
    if (expression !== this.expressionAsked || !surface) return;
    this.expressionValues = expressionLog2(values, surface.positions.length / 3);
    this.show();
  }

  // The expression's log2 per vertex for the map, asking the core when it changed.
  private expressionLog2(): Float32Array | null {
    const expression = this.host.expression();
    if (expression === '') return null;
    if (expression !== this.expressionAsked) {
      this.expressionAsked = expression;
      this.expressionValues = null;
      this.host.requestExpression(expression);
    }
    return this.expressionValues;
  }

  // The field on show changed (a stroke, undo, a design opened): repaint the colour map.
  show(): void {
    const surface = this.host.viewer.surface;
    if (!this.brush.active || !surface) {
      this.host.viewer.setDensityView(null);
      return;
    }
    const vertices = surface.positions.length / 3;
    const field = this.host.field();
    const expression = this.expressionLog2();
    this.showLegendTitle(expression !== null);
    this.host.viewer.setDensityView(fieldColors(field && field.length === vertices ? field : null, vertices, expression));
  }

  private showLegendTitle(effective: boolean): void {
    const pending = !effective && this.host.expression() !== '';
    this.legendTitle.textContent = effective ? 'Effective density: expression × paint' : pending ? 'Density paint (the expression is not shown)' : 'Density paint';
    document.body.dataset.densityMap = effective ? 'effective' : 'paint';
  }

  private preview(log2: Float32Array): void {
    if (!this.previewColors || this.previewColors.length !== log2.length * 3) this.previewColors = new Float32Array(log2.length * 3);
    const expression = this.expressionValues?.length === log2.length && this.host.expression() === this.expressionAsked ? this.expressionValues : null;
    log2Colors(log2, this.previewColors, expression);
    this.host.viewer.setDensityView(this.previewColors);
  }

  updateButtons(hasPaint: boolean): void {
    const can = this.host.canPaint();
    this.toggle.disabled = !can;
    this.clearButton.disabled = !can || !hasPaint;
    if (!can && this.brush.active && !this.host.viewer.surface) this.setPainting(false);
  }
}
