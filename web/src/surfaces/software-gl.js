// Whether this browser's WebGL2 runs on a software rasterizer (no usable GPU: SwiftShader, llvmpipe, ...).
// There multisampling costs about a third of every frame, so Flipbook's antialias 'auto' leaves it off.

const SOFTWARE_RENDERERS = /swiftshader|llvmpipe|softpipe|software|basic render/i;
let verdict = null;

/** The renderer string says software. Probed once per page on a throwaway context that is let go at once. */
export function softwareWebGL() {
  if (verdict !== null) return verdict;
  verdict = false;
  if (typeof document === 'undefined') return verdict;
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) return verdict;
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const renderer = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  verdict = SOFTWARE_RENDERERS.test(renderer);
  gl.getExtension('WEBGL_lose_context')?.loseContext();  // it would count against the page's contexts
  return verdict;
}
