// Turns a page source into an image the book can draw, and a failure into a PageLoadError whose
// `reason` says which thing went wrong (an HTTP status, the network, CORS, not an image), so a
// `pageerror` can tell a missing page from a broken one. URLs are fetched (not put in an <img>) because
// only fetch reports the status; nothing that would taint a canvas gets through.

import { imageSizeOf } from './image-header.js';
import { decodeReduced, makeCanvas } from './step-down.js';
import { MAX_IMAGE_SIZE, uploadSizeFor } from './texture-upload.js';

/**
 * Why a page could not be shown: `reason` is 'http' (`status` says which), 'network', 'cors', 'decode'
 * (not an image, or an image with no pixels) or 'source' (a page function threw or rejected).
 */
export class PageLoadError extends Error {
  constructor(message, { reason, status, url, cause } = {}) {
    super(message, cause === undefined ? undefined : { cause });
    this.name = 'PageLoadError';
    this.reason = reason;
    if (status !== undefined) this.status = status;
    if (url !== undefined) this.url = url;
  }
}

/**
 * A failed page as the `pageerror` event and pageState() report it: the error, and its reason. An
 * error without one (not a PageLoadError) came from handing the image to the book: 'upload'.
 */
export function pageFailure(error) {
  return { error: error instanceof Error ? error : new Error(String(error)), reason: error?.reason || 'upload' };
}

function sourceName(source) {
  if (typeof source === 'string') return `'${source}'`;
  if (typeof HTMLImageElement !== 'undefined' && source instanceof HTMLImageElement) {
    return `the <img> '${source.currentSrc || source.src}'`;
  }
  return `the ${Object.getPrototypeOf(source)?.constructor?.name || 'image'}`;
}

/**
 * Loads page `index` from `source` (a URL, Blob, HTMLImageElement, HTMLCanvasElement, ImageBitmap,
 * or a function of (index, size) returning one of these or a Promise of one). Resolves with
 * `{ image, owned, natural? }`: `owned` images were made here (close() an ImageBitmap when done with
 * it). An encoded image (URL, Blob) is decoded at the size that covers `size` where its header says it
 * is larger: then `natural` is the size it holds, for a sharper decode later (zoom).
 * Rejects with a PageLoadError, or the AbortError of `signal`.
 */
export async function loadPage(source, { index = 0, size, signal } = {}) {
  const label = `conecurl: page ${index}`;
  if (typeof source === 'function') {
    try {
      source = await source(index, size);
    } catch (cause) {
      throw new PageLoadError(`${label}: its source function failed (${cause && cause.message ? cause.message : cause})`,
        { reason: 'source', cause });
    }
  }
  if (typeof source === 'string') return { ...await fetchImage(source, label, signal, size), owned: true };
  if (typeof Blob !== 'undefined' && source instanceof Blob) {
    return { ...await decodeBlob(source, `${label} (${sourceName(source)})`, undefined, size), owned: true };
  }
  const isImg = typeof HTMLImageElement !== 'undefined' && source instanceof HTMLImageElement;
  const isCanvas = typeof HTMLCanvasElement !== 'undefined' && source instanceof HTMLCanvasElement;
  const isBitmap = typeof ImageBitmap !== 'undefined' && source instanceof ImageBitmap;
  if (!isImg && !isCanvas && !isBitmap) {
    throw new PageLoadError(`${label}: its source gave ${source === null ? 'null' : typeof source}, not an image`,
      { reason: 'decode' });
  }
  if (isImg) {
    if (!source.complete) {
      try {
        await source.decode();
      } catch (cause) {
        throw new PageLoadError(`${label}: ${sourceName(source)} could not be loaded or decoded`,
          { reason: 'decode', url: source.currentSrc || source.src, cause });
      }
    }
    if (!(source.naturalWidth > 0)) {
      throw new PageLoadError(`${label}: ${sourceName(source)} is broken (it failed to load or is not an image)`,
        { reason: 'decode', url: source.currentSrc || source.src });
    }
  } else if (!(source.width > 0 && source.height > 0)) {
    throw new PageLoadError(`${label}: ${sourceName(source)} has no pixels (0 wide or high, or closed)`, { reason: 'decode' });
  }
  assertReadable(source, label);
  return { image: source, owned: false };
}

async function fetchImage(url, label, signal, size) {
  const where = `${label} ('${url}')`;
  let resolved;
  try {
    resolved = new URL(url, document.baseURI);
  } catch (cause) {
    throw new PageLoadError(`${where}: not a valid URL`, { reason: 'network', url, cause });
  }
  let response;
  try {
    response = await fetch(resolved, { mode: 'cors', credentials: 'same-origin', signal });
  } catch (cause) {
    if (signal?.aborted) throw cause;
    // fetch says only "Failed to fetch" for a CORS refusal and for a dead server alike. A request the
    // page cannot read (no-cors) tells them apart: if it gets an answer, the server is there and
    // simply does not allow this origin to read its images.
    if (resolved.origin !== location.origin && /^https?:$/.test(resolved.protocol)
        && await answersWithoutCors(resolved, signal)) {
      throw new PageLoadError(`${where}: blocked by CORS: ${resolved.origin} does not let ${location.origin} read it `
        + '(its server must send Access-Control-Allow-Origin; or serve the image from this page\'s origin)',
      { reason: 'cors', url, cause });
    }
    throw new PageLoadError(`${where}: could not be fetched (network error or no answer)`, { reason: 'network', url, cause });
  }
  if (!response.ok) {
    throw new PageLoadError(`${where}: HTTP ${response.status}${response.statusText ? ` ${response.statusText}` : ''}`,
      { reason: 'http', status: response.status, url });
  }
  const blob = await response.blob();
  return decodeBlob(blob, where, url, size);
}

async function answersWithoutCors(url, signal) {
  try {
    await fetch(url, { mode: 'no-cors', credentials: 'omit', signal });
    return true;
  } catch {
    return false;
  }
}

// Decoded by the browser off the main thread; at the size that covers `size` (never up) when the header
// says the image is larger, so it reaches the texture without a scaling pass on the main thread
// (filtered: by halves where the browser's resize samples).
async function decodeBlob(blob, where, url, size) {
  try {
    const natural = size ? await imageSizeOf(blob) : null;
    const wanted = natural && uploadSizeFor(natural.width, natural.height, { cover: size, maxTextureSize: MAX_IMAGE_SIZE });
    if (wanted && wanted.width < natural.width) {
      return { image: await decodeReduced(blob, natural, wanted), natural };
    }
    return { image: await createImageBitmap(blob) };
  } catch (first) {
    // createImageBitmap refuses some formats an <img> shows (SVG in Chromium): try that before giving up.
    const objectUrl = URL.createObjectURL(blob);
    try {
      const image = new Image();
      image.src = objectUrl;
      await image.decode();
      if (image.naturalWidth > 0) return { image };
    } catch {
      // reported below, with what the bytes were
    } finally {
      URL.revokeObjectURL(objectUrl);
    }
    throw new PageLoadError(`${where}: not a decodable image (${blob.type || 'no content type'}, ${blob.size} bytes)`,
      { reason: 'decode', url, cause: first });
  }
}

// A cross-origin <img> without crossorigin="anonymous" (or a canvas or ImageBitmap made from one) can be
// drawn but not read: uploading it to WebGL throws a SecurityError. Refuse it here, by name.
function assertReadable(source, label) {
  const context = makeCanvas(1, 1).getContext('2d');
  context.drawImage(source, 0, 0, 1, 1);
  try {
    context.getImageData(0, 0, 1, 1);
  } catch (cause) {
    if (cause && cause.name === 'SecurityError') {
      throw new PageLoadError(`${label}: ${sourceName(source)} is cross-origin without CORS, so its pixels cannot be read `
        + '(load it with crossorigin="anonymous" from a server that sends Access-Control-Allow-Origin)',
      { reason: 'cors', url: source.currentSrc || source.src, cause });
    }
    throw cause;
  }
}
