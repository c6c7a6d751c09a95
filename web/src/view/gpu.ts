// Whether WebGL runs on a software rasteriser (SwiftShader, llvmpipe: headless browsers, VMs,
// blocklisted GPUs). There, multisampling and frequent redraws cost the main thread whole
// frames, so the viewer draws without MSAA and updates the live view less often.
export function isSoftwareRenderer(): boolean {
  const canvas = document.createElement('canvas');
  const gl = canvas.getContext('webgl2') ?? canvas.getContext('webgl');
  if (!gl) return true;
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const renderer = info ? String(gl.getParameter(info.UNMASKED_RENDERER_WEBGL)) : '';
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return /swiftshader|llvmpipe|softpipe|software|basic render/i.test(renderer);
}
