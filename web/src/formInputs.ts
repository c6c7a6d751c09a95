// Number inputs shared by the forms (paramsForm.ts, fabricationForm.ts): their ranges come
// from LIMITS (params.ts), and reading one gives NaN for an empty field, which the
// validators then name ("... must be a number").
export function setRange(input: HTMLInputElement, range: { min: number; max: number }): void {
  input.min = String(range.min);
  input.max = String(range.max);
}

export function readNumber(input: HTMLInputElement): number {
  return input.value.trim() === '' ? Number.NaN : Number(input.value);
}
