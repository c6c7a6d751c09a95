// The painted density field, quantised: one signed byte per vertex of the cleaned mesh, the
// density's log2 in 1/16 steps over [-4, 4] (1/16x .. 16x). The page paints in this form,
// stores and shares it in this form, and the worker solves with exactly the values it
// decodes to, so a link or a stored session gives the same panels as the page that made it.
// No DOM, no three.js: unit-tested in Node.

export const STEPS_PER_OCTAVE = 16;
export const MAX_LOG2 = 4;
export const MAX_LEVEL = STEPS_PER_OCTAVE * MAX_LOG2; // 64: levels run -64 .. 64

// 2^(r/16) for r = 0..15, written out: the decoded densities are these times a power of two,
// exact in binary and the same in every browser (Math.pow need not be correctly rounded).
const FRACTIONS = [
  1, 1.0442737824274138, 1.0905077326652577, 1.1387886347566916, 1.189207115002721, 1.241857812073484,
  1.2968395546510096, 1.3542555469368927, 1.4142135623730951, 1.4768261459394993, 1.542210825407941,
  1.6104903319492543, 1.6817928305074292, 1.7562521603732995, 1.8340080864093424, 1.9152065613971474,
];

// A level for a log2 density (clamped to the range, rounded to the nearest step).
export function levelOf(log2Density: number): number {
  if (!Number.isFinite(log2Density)) return 0;
  const level = Math.round(Math.min(MAX_LOG2, Math.max(-MAX_LOG2, log2Density)) * STEPS_PER_OCTAVE);
  return level === 0 ? 0 : level; // never -0
}

export function densityOfLevel(level: number): number {
  const octave = Math.floor(level / STEPS_PER_OCTAVE);
  return FRACTIONS[level - octave * STEPS_PER_OCTAVE]! * 2 ** octave;
}

// The densities the core solves with.
export function decodeField(field: Int8Array): Float64Array {
  const out = new Float64Array(field.length);
  for (let i = 0; i < field.length; i++) out[i] = densityOfLevel(field[i]!);
  return out;
}

export function quantiseField(log2: Float32Array | Float64Array): Int8Array {
  const out = new Int8Array(log2.length);
  for (let i = 0; i < log2.length; i++) out[i] = levelOf(log2[i]!);
  return out;
}

export function isUniform(field: Int8Array): boolean {
  for (let i = 0; i < field.length; i++) if (field[i] !== 0) return false;
  return true;
}

// A 64-bit content key (two FNV-1a passes with different offsets, the length mixed in) as 16
// hex digits: names a field in the parameters, and a link's field must hash to its key.
export function fieldKey(field: Int8Array): string {
  let a = 0x811c9dc5 ^ field.length;
  let b = 0x01000193 ^ Math.imul(field.length, 0x9e3779b1);
  for (let i = 0; i < field.length; i++) {
    const byte = field[i]! & 0xff;
    a = Math.imul(a ^ byte, 0x01000193);
    b = Math.imul(b ^ byte, 0x5bd1e995);
    b ^= b >>> 15;
  }
  return (a >>> 0).toString(16).padStart(8, '0') + (b >>> 0).toString(16).padStart(8, '0');
}

// A field from untrusted bytes (a link, the browser's storage): every level in range, the key
// matching. Returns why not, or null.
export function fieldProblem(bytes: Uint8Array, key: string): string | null {
  const field = new Int8Array(bytes.buffer, bytes.byteOffset, bytes.length);
  for (let i = 0; i < field.length; i++) {
    const level = field[i]!;
    if (level < -MAX_LEVEL || level > MAX_LEVEL) return `value ${i + 1} is outside the paint range`;
  }
  return fieldKey(field) === key ? null : 'it does not match its key (it was cut or altered)';
}
