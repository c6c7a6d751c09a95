// rhino3dm's ES module build (its package only declares the CommonJS entry).
declare module 'rhino3dm/rhino3dm.module.js' {
  export { default } from 'rhino3dm';
}

// The wasm's URL from Vite (declared here too for the unit-test build, which has no vite/client types).
declare module 'rhino3dm/rhino3dm.wasm?url' {
  const url: string;
  export default url;
}
