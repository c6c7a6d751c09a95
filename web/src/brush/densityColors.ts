// The density paint as colours: a diverging ramp over log2 density -4 .. 4, neutral grey at 1x
// (unpainted), blues where panels get larger, yellow -> orange -> red -> magenta where they get
// smaller. The legend's CSS gradient (styles.css, .density-ramp) uses the same stops.
import { MAX_LOG2, STEPS_PER_OCTAVE } from './densityField.ts';

// [log2 density, r, g, b] (0..1).
const STOPS: readonly (readonly [number, number, number, number])[] = [
  [-4, 0.16, 0.3, 0.78],
  [-2, 0.36, 0.55, 0.9],
  [0, 0.66, 0.68, 0.71],
  [1, 0.95, 0.82, 0.25],
  [2, 0.95, 0.51, 0.2],
  [3, 0.88, 0.2, 0.2],
  [4, 0.78, 0.12, 0.55],
];

export function densityColor(log2: number, out: Float32Array, offset: number): void {
  const x = Math.min(MAX_LOG2, Math.max(-MAX_LOG2, log2));
  let i = 0;
  while (i < STOPS.length - 2 && x > STOPS[i + 1]![0]) i++;
  const a = STOPS[i]!;
  const b = STOPS[i + 1]!;
  const t = (x - a[0]) / (b[0] - a[0]);
  for (let k = 1; k <= 3; k++) out[offset + k - 1] = a[k]! + (b[k]! - a[k]!) * t;
}

// RGB per vertex of a field of levels (densityField.ts), or of a working log2 buffer. With
// `expression` (log2 of the density expression per vertex, expressionLog2), the colours show
// the effective density the solver uses: expression x paint, i.e. the sum of the log2s.
export function fieldColors(levels: Int8Array | null, vertexCount: number, expression: Float32Array | null = null): Float32Array {
  const rgb = new Float32Array(vertexCount * 3);
  for (let v = 0; v < vertexCount; v++) densityColor((levels ? levels[v]! / STEPS_PER_OCTAVE : 0) + (expression?.[v] ?? 0), rgb, v * 3);
  return rgb;
}

export function log2Colors(log2: Float32Array, rgb: Float32Array, expression: Float32Array | null = null): void {
  for (let v = 0; v < log2.length; v++) densityColor(Math.round(log2[v]! * STEPS_PER_OCTAVE) / STEPS_PER_OCTAVE + (expression?.[v] ?? 0), rgb, v * 3);
}

// The expression's values (the core's, Session.expressionDensity) as log2 per vertex; null
// when there are none or not one per vertex (another mesh, an expression the core refused).
export function expressionLog2(values: Float64Array, vertexCount: number): Float32Array | null {
  if (values.length === 0 || values.length !== vertexCount) return null;
  const out = new Float32Array(vertexCount);
  for (let v = 0; v < vertexCount; v++) {
    const value = values[v]!;
    if (!(value > 0) || !Number.isFinite(value)) return null;
    out[v] = Math.log2(value);
  }
  return out;
}
