// Numbers far from 1 as a designer reads them: 1.5×10⁻⁶.
export function scientific(value: number | null): string {
  if (value === null) return '–';
  if (value === 0) return '0';
  return value.toExponential(1).replace('e', '×10^').replace(/\^\+?(-?\d+)$/, (_, e: string) => superscript(e));
}

function superscript(exponent: string): string {
  const map: Record<string, string> = { '-': '⁻', '0': '⁰', '1': '¹', '2': '²', '3': '³', '4': '⁴', '5': '⁵', '6': '⁶', '7': '⁷', '8': '⁸', '9': '⁹' };
  return [...exponent].map((c) => map[c] ?? c).join('');
}
