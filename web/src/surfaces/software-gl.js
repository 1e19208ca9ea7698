// Whether this browser's WebGL2 runs on a software rasterizer (no usable GPU: SwiftShader, llvmpipe, ...).
// There multisampling costs about a third of every frame, so Flipbook's antialias 'auto' leaves it off.

const SOFTWARE_RENDERERS = /swiftshader|llvmpipe|softpipe|software|basic render/i;
/**
 * The context BookRenderer asks for (cpp/renderer/book_renderer.cpp, over Emscripten's defaults), less its
 * antialias: a canvas's context is made once, so one made here first is the one the renderer gets there.
 */
export const RENDERER_CONTEXT = Object.freeze({
  alpha: true, depth: true, stencil: false, premultipliedAlpha: true, preserveDrawingBuffer: false,
  powerPreference: 'default', failIfMajorPerformanceCaveat: false,
});
let verdict = null;

/** What a book found this page's WebGL2 to be: true in software, false on a GPU, null before any found out. */
export function knownSoftwareWebGL() { return verdict; }

/**
 * Finds out on the book's own `canvas`, making there the context its renderer would make on a GPU
 * (multisampled) and reading the renderer string; once per page (knownSoftwareWebGL). Returns that
 * context (null without WebGL2: the renderer will say so). On a GPU the renderer, made on `canvas`, gets
 * it: one context, where a probe of its own made two. In software it is not the one wanted: the book
 * needs a fresh canvas, and lets this context go (WEBGL_lose_context: it counts against the page's).
 */
export function probeWebGL(canvas) {
  const gl = canvas.getContext('webgl2', { ...RENDERER_CONTEXT, antialias: true });
  if (!gl) return null;
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  verdict = SOFTWARE_RENDERERS.test(String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER)));
  return gl;
}
