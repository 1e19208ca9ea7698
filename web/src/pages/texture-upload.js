// How a page image becomes a texture's pixels: the size it is uploaded at (never up, within the GPU's
// limit, just covering what the screen needs) and a scaled copy on one shared scratch canvas when needed.

import { drawableFor, makeCanvas } from './step-down.js';

/** The largest image a page is decoded or drawn at; no browser keeps a bigger texture (BookView also fits the GPU's limit). */
export const MAX_IMAGE_SIZE = 16384;
const SAME_SIZE = 0.99;  // within 1 % of the size wanted is that size

export function naturalSize(source) {
  const width = source.naturalWidth || source.videoWidth || source.width;
  const height = source.naturalHeight || source.videoHeight || source.height;
  if (!(width > 0 && height > 0)) throw new TypeError('conecurl: page image has no size (not loaded yet?)');
  return { width, height };
}

/**
 * The size a `width` x `height` image is uploaded at: scaled down (never up), keeping its aspect, to
 * the smallest size that still covers `cover` (when given), and to fit the GPU's MAX_TEXTURE_SIZE.
 */
export function uploadSizeFor(width, height, { cover, maxTextureSize }) {
  let scale = 1;
  if (cover && cover.width > 0 && cover.height > 0) {
    scale = Math.min(1, Math.max(cover.width / width, cover.height / height));
    // An image already decoded at the size wanted can be off by a rounding: no rescaling pass for that.
    if (scale > SAME_SIZE) scale = 1;
  }
  scale = Math.min(scale, maxTextureSize / width, maxTextureSize / height);
  const fit = (length) => Math.max(1, Math.min(maxTextureSize, Math.round(length * scale)));
  return { width: fit(width), height: fit(height) };
}

let scratch = null;  // one canvas for every book's scaling: texImage2D copies it before it is reused

/**
 * What the texture is uploaded from: the source itself when it already has the size wanted, else the
 * source drawn at that size on a scratch canvas (`own`: a canvas of its own, for an upload in bands
 * spread over frames), stepped down where drawImage would sample the reduction. The pixels never pass
 * through getImageData or the wasm heap: the browser copies them from there into the texture.
 */
export function atSize(source, natural, { width, height }, { own = false } = {}) {
  if (natural.width === width && natural.height === height) return source;
  let drawable = source;
  if (source instanceof ImageData) {  // drawImage cannot scale ImageData: stage it as a bitmap-sized canvas
    drawable = makeCanvas(source.width, source.height);
    drawable.getContext('2d').putImageData(source, 0, 0);
  }
  const target = own ? makeCanvas(width, height) : (scratch ??= makeCanvas(width, height));
  if (target.width !== width || target.height !== height) Object.assign(target, { width, height });
  const context = target.getContext('2d');
  context.imageSmoothingQuality = 'high';  // a big reduction stays legible, not aliased
  context.clearRect(0, 0, width, height);
  context.drawImage(drawableFor(drawable, natural, { width, height }), 0, 0, width, height);
  return target;
}
