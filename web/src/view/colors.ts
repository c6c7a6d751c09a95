// Stable, distinguishable colours per id: neighbouring ids (which are often neighbouring
// clusters) land far apart on the hue circle. The same id always gets the same colour, so a
// cluster keeps its colour while the solve converges.

const GOLDEN = 0.6180339887498949;

function hash32(id: number): number {
  let x = (id + 0x9e3779b9) | 0;
  x = Math.imul(x ^ (x >>> 16), 0x85ebca6b);
  x = Math.imul(x ^ (x >>> 13), 0xc2b2ae35);
  return (x ^ (x >>> 16)) >>> 0;
}

function hslToRgb(h: number, s: number, l: number, out: Float32Array, offset: number): void {
  const k = (n: number): number => (n + h * 12) % 12;
  const a = s * Math.min(l, 1 - l);
  const f = (n: number): number => l - a * Math.max(-1, Math.min(k(n) - 3, Math.min(9 - k(n), 1)));
  out[offset] = f(0);
  out[offset + 1] = f(8);
  out[offset + 2] = f(4);
}

// Writes the colour of `id` as linear-ish RGB floats at out[offset..offset+3).
export function idColor(id: number, out: Float32Array, offset: number): void {
  if (id < 0) {
    out[offset] = out[offset + 1] = out[offset + 2] = 0.55;
    return;
  }
  const h = hash32(id);
  const hue = ((id * GOLDEN) % 1 + (h & 0xff) / 2560) % 1;
  const saturation = 0.42 + ((h >>> 8) & 0xff) / 255 * 0.18;
  const lightness = 0.56 + ((h >>> 16) & 0xff) / 255 * 0.14;
  hslToRgb(hue, saturation, lightness, out, offset);
}

export const PROBLEM_RED: readonly [number, number, number] = [0.93, 0.16, 0.14];

// Deviation from the design as a share t (0..1) of the largest: blue through yellow to red
// (styles.css .deviation-ramp).
const DEVIATION_STOPS: readonly (readonly [number, number, number])[] = [
  [0.25, 0.45, 0.85],
  [0.95, 0.85, 0.3],
  [0.93, 0.16, 0.14],
];
export function deviationColor(t: number, out: Float32Array, offset: number): void {
  const x = Math.min(1, Math.max(0, Number.isFinite(t) ? t : 0)) * (DEVIATION_STOPS.length - 1);
  const i = Math.min(DEVIATION_STOPS.length - 2, Math.floor(x));
  const f = x - i;
  for (let k = 0; k < 3; k++) out[offset + k] = DEVIATION_STOPS[i]![k]! * (1 - f) + DEVIATION_STOPS[i + 1]![k]! * f;
}

// Planarity error (distance / panel diameter) -> colour: up to the fabrication tolerance
// (1e-4) a cool grey, then yellow to red at 1e-1 and beyond (log scale).
export const PLANARITY_TOLERANCE = 1e-4;
export function planarityColor(error: number, out: Float32Array, offset: number): void {
  if (!(error > PLANARITY_TOLERANCE)) {
    out[offset] = 0.52;
    out[offset + 1] = 0.58;
    out[offset + 2] = 0.66;
    return;
  }
  const t = Math.min(1, Math.log10(error / PLANARITY_TOLERANCE) / 3);
  out[offset] = 0.95;
  out[offset + 1] = 0.82 - 0.62 * t;
  out[offset + 2] = 0.25 - 0.1 * t;
}
