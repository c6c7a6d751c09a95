// A small binary glTF written by hand (a wavy 16 x 16 grid under a scaled, translated node), so
// the test exercises the page's three.js import path without shipping a binary fixture.
export function wavyGridGlb(cells = 16) {
  const positions = [];
  for (let j = 0; j <= cells; j++) {
    for (let i = 0; i <= cells; i++) {
      const u = i / cells;
      const v = j / cells;
      positions.push(u, 0.25 * Math.sin(Math.PI * u) * Math.sin(Math.PI * v), v);
    }
  }
  const indices = [];
  for (let j = 0; j < cells; j++) {
    for (let i = 0; i < cells; i++) {
      const a = j * (cells + 1) + i;
      indices.push(a, a + cells + 1, a + 1, a + 1, a + cells + 1, a + cells + 2);
    }
  }
  const positionBytes = Buffer.from(new Float32Array(positions).buffer);
  const indexBytes = Buffer.from(new Uint32Array(indices).buffer);
  const bin = Buffer.concat([positionBytes, indexBytes]);
  const min = [0, 0, 0];
  const max = [1, 0.25, 1];
  const json = {
    asset: { version: '2.0', generator: 'flatfacet tests' },
    scene: 0,
    scenes: [{ nodes: [0] }],
    nodes: [{ mesh: 0, scale: [10, 10, 10], translation: [5, 0, -3] }],
    meshes: [{ primitives: [{ attributes: { POSITION: 0 }, indices: 1, mode: 4 }] }],
    buffers: [{ byteLength: bin.length }],
    bufferViews: [
      { buffer: 0, byteOffset: 0, byteLength: positionBytes.length, target: 34962 },
      { buffer: 0, byteOffset: positionBytes.length, byteLength: indexBytes.length, target: 34963 },
    ],
    accessors: [
      { bufferView: 0, componentType: 5126, count: positions.length / 3, type: 'VEC3', min, max },
      { bufferView: 1, componentType: 5125, count: indices.length, type: 'SCALAR' },
    ],
  };
  let jsonBytes = Buffer.from(JSON.stringify(json));
  jsonBytes = Buffer.concat([jsonBytes, Buffer.alloc((4 - (jsonBytes.length % 4)) % 4, 0x20)]);
  const binPadded = Buffer.concat([bin, Buffer.alloc((4 - (bin.length % 4)) % 4)]);
  const chunk = (type, data) => {
    const header = Buffer.alloc(8);
    header.writeUInt32LE(data.length, 0);
    header.write(type, 4, 'ascii');
    return Buffer.concat([header, data]);
  };
  const body = Buffer.concat([chunk('JSON', jsonBytes), chunk('BIN\0', binPadded)]);
  const header = Buffer.alloc(12);
  header.write('glTF', 0, 'ascii');
  header.writeUInt32LE(2, 4);
  header.writeUInt32LE(12 + body.length, 8);
  return { bytes: Buffer.concat([header, body]), triangles: indices.length / 3 };
}
