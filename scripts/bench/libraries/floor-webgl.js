// The WebGL floor (issue 24): the smallest WebGL book that turns a page, measured beside conecurl as
// what a WebGL flipbook must pay on this platform. A viewport-sized canvas (alpha, no MSAA, no depth),
// the open pages as textures, and per frame of a turn three textured quads, the leaf rotated about the
// spine with a simple perspective (a w divide); nothing else: no lighting, shadows, stacks or curl.
import { floorBook, viewportCanvas } from './floor-book.js';

const VERTEX = `#version 300 es
uniform vec4 u_page;   // spine x, top y, page width, page height (px)
uniform vec2 u_view;   // canvas size (px)
uniform float u_angle; // 0: flat right of the spine, PI: flat left of it
out vec2 v_uv;
void main() {
  vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1));
  float c = cos(u_angle);
  float across = corner.x * u_page.z;
  vec2 px = vec2(u_page.x + across * c, u_page.y + corner.y * u_page.w);
  float lift = across * sin(u_angle);  // towards the eye, 3 page heights away
  gl_Position = vec4(2.0 * px.x / u_view.x - 1.0, 1.0 - 2.0 * px.y / u_view.y, 0.0, 1.0 - lift / (3.0 * u_page.w));
  v_uv = vec2(c < 0.0 ? 1.0 - corner.x : corner.x, corner.y);  // a left page's spine is its right edge
}`;
const FRAGMENT = `#version 300 es
precision mediump float;
uniform sampler2D u_texture;
in vec2 v_uv;
out vec4 color;
void main() { color = texture(u_texture, v_uv); }`;

function program(gl) {
  const shader = (type, source) => {
    const s = gl.createShader(type);
    gl.shaderSource(s, source);
    gl.compileShader(s);
    return s;
  };
  const p = gl.createProgram();
  gl.attachShader(p, shader(gl.VERTEX_SHADER, VERTEX));
  gl.attachShader(p, shader(gl.FRAGMENT_SHADER, FRAGMENT));
  gl.linkProgram(p);
  if (!gl.getProgramParameter(p, gl.LINK_STATUS)) throw new Error(`floor-webgl: ${gl.getProgramInfoLog(p)}`);
  return p;
}

export async function mount(container, { urls, display, duration }) {
  const { canvas, width, height, ratio } = viewportCanvas(container);
  const gl = canvas.getContext('webgl2', { alpha: true, antialias: false, depth: false, stencil: false });
  if (!gl) throw new Error('floor-webgl: no WebGL2 context');
  gl.useProgram(program(gl));
  const uniform = (name) => gl.getUniformLocation(gl.getParameter(gl.CURRENT_PROGRAM), name);
  const [uPage, uView, uAngle] = ['u_page', 'u_view', 'u_angle'].map(uniform);
  gl.uniform2f(uView, canvas.width, canvas.height);  // sampler u_texture stays on unit 0
  gl.clearColor(0, 0, 0, 0);
  const textures = new Map();  // page -> WebGLTexture

  const surface = {
    has: (page) => textures.has(page),
    prepare(page, bitmap, images) {
      const texture = gl.createTexture();
      gl.bindTexture(gl.TEXTURE_2D, texture);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA, gl.RGBA, gl.UNSIGNED_BYTE, bitmap);
      textures.set(page, texture);
      images.drop(page);  // the texture holds it now
    },
    draw(quads, place) {
      gl.clear(gl.COLOR_BUFFER_BIT);
      gl.uniform4f(uPage, place.spineX * ratio, place.top * ratio, place.pageWidth * ratio, place.pageHeight * ratio);
      for (const { page, angle } of quads) {
        gl.bindTexture(gl.TEXTURE_2D, textures.get(page));
        gl.uniform1f(uAngle, angle);
        gl.drawArrays(gl.TRIANGLE_STRIP, 0, 4);
      }
    },
    keep(from, to) {
      for (const [page, texture] of textures) {
        if (page < from || page > to) {
          gl.deleteTexture(texture);
          textures.delete(page);
        }
      }
    },
  };
  return floorBook({ urls, display, duration, width, height, ratio, surface });
}
