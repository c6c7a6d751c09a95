// Which way is up for an uploaded mesh: roofs and shells are flattest along their up axis, and
// files come y-up (most modelling tools) or z-up (CAD, GIS).
export function guessUpAxis(positions: Float32Array): 'y' | 'z' {
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i++) {
    const axis = i % 3;
    min[axis] = Math.min(min[axis]!, positions[i]!);
    max[axis] = Math.max(max[axis]!, positions[i]!);
  }
  const extent = max.map((m, axis) => m - min[axis]!);
  return extent[2]! < extent[1]! && extent[2]! < extent[0]! ? 'z' : 'y';
}
