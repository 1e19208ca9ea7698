// A page image reduced stays legible in every engine: Firefox's drawImage and WebKit's drawImage and
// createImageBitmap resize take one sample a pixel, so a page's thin strokes drop out. Each road is asked
// once a document whether it filters; where it samples, the image steps down by halves.

/** A canvas for pixels that are never shown: an OffscreenCanvas where the browser has one. */
export function makeCanvas(width, height) {
  return typeof OffscreenCanvas === 'function'
    ? new OffscreenCanvas(width, height)
    : Object.assign(document.createElement('canvas'), { width, height });
}

const PATTERN = 16;  // the probe: 1-px black columns every 4 px on white, reduced 8x to 2 x 2
const FILTERED = [64, 240];  // a filtered reduction reads about 191 (a quarter black); a sampled one 255 or 0

function pattern() {
  const canvas = makeCanvas(PATTERN, PATTERN);
  const g = canvas.getContext('2d');
  g.fillStyle = '#fff';
  g.fillRect(0, 0, PATTERN, PATTERN);
  g.fillStyle = '#000';
  for (let x = 1; x < PATTERN; x += 4) g.fillRect(x, 0, 1, PATTERN);
  return canvas;
}

// The red of the probe's reduced top-left pixel, drawn unscaled (or, for drawImage, reduced) on a 2 x 2 canvas.
function reads(draw) {
  const g = makeCanvas(2, 2).getContext('2d', { willReadFrequently: true });
  g.imageSmoothingQuality = 'high';
  draw(g);
  const red = g.getImageData(0, 0, 1, 1).data[0];
  return red > FILTERED[0] && red < FILTERED[1];
}

let drawVerdict;
/** Whether this browser's drawImage (smoothing 'high') filters a large reduction. Asked once; synchronous. */
export function drawFilters() {
  drawVerdict ??= reads((g) => g.drawImage(pattern(), 0, 0, 2, 2));
  return drawVerdict;
}

let bitmapVerdict;
/** Whether createImageBitmap's resize (resizeQuality 'high') filters a large reduction. Asked once. */
export function bitmapFilters() {
  bitmapVerdict ??= createImageBitmap(pattern(), { resizeWidth: 2, resizeHeight: 2, resizeQuality: 'high' })
    .then((bitmap) => {
      try {
        return reads((g) => g.drawImage(bitmap, 0, 0));
      } finally {
        bitmap.close();
      }
    }, () => true);  // no resize at all: nothing to step around
  return bitmapVerdict;
}

const DIRECT = 1.25;  // a last step of at most this one sampled pass keeps 3/4 of a 1-px stroke's ink

/**
 * The sizes a `from` image passes through on its way down to `to` where each pass takes one bilinear
 * sample a pixel: each side halved (rounded up) while over 2x its target, so each pass is a 2 x 2 box;
 * then, where a side is left over DIRECT times its target, that side enlarged to exactly twice its target,
 * so the last pass halves it too (one sample at 1.25-2x falls between strokes: a 1-px line drops out).
 * Empty within DIRECT of `to`.
 */
export function reductionSteps(from, to) {
  const steps = [];
  let { width, height } = from;
  while (width > 2 * to.width || height > 2 * to.height) {
    if (width > 2 * to.width) width = Math.ceil(width / 2);
    if (height > 2 * to.height) height = Math.ceil(height / 2);
    steps.push({ width, height });
  }
  const last = (length, target) => (length > DIRECT * target ? 2 * target : length);
  const enlarged = { width: last(width, to.width), height: last(height, to.height) };
  if (enlarged.width !== width || enlarged.height !== height) steps.push(enlarged);
  return steps;
}

const resize = ({ width, height }) => ({ resizeWidth: width, resizeHeight: height, resizeQuality: 'high' });

/**
 * `blob` (whose header said `natural`) decoded at `wanted`, filtered: in one resize where the browser's
 * resize filters, else through reductionSteps, each bitmap made from the one before (those are closed).
 */
export async function decodeReduced(blob, natural, wanted) {
  const steps = reductionSteps(natural, wanted);
  const onePass = () => createImageBitmap(blob, resize(wanted));
  if (!steps.length) return onePass();
  if (bitmapVerdict === undefined) {
    // The first time: the probe beside the one-pass decode, so a browser that filters waits for nothing more.
    const [filters, image] = await Promise.all([bitmapFilters(), onePass()]);
    if (filters) return image;
    image.close();
  } else if (await bitmapVerdict) {
    return onePass();
  }
  let image = await createImageBitmap(blob, resize(steps[0]));
  for (const size of [...steps.slice(1), wanted]) {
    const next = await createImageBitmap(image, resize(size));
    image.close();
    image = next;
  }
  return image;
}

/**
 * What to draw `source` (of `natural` size) from at `to` with drawImage: the source itself where
 * drawImage filters or the reduction is small, else a canvas of it through reductionSteps but the last.
 */
export function drawableFor(source, natural, to) {
  const steps = reductionSteps(natural, to);
  if (!steps.length || drawFilters()) return source;
  let drawable = source;
  for (const { width, height } of steps) {
    const canvas = makeCanvas(width, height);
    const g = canvas.getContext('2d');
    g.imageSmoothingQuality = 'high';
    g.drawImage(drawable, 0, 0, width, height);
    if (drawable !== source) Object.assign(drawable, { width: 0, height: 0 });  // its pixels let go now
    drawable = canvas;
  }
  return drawable;
}
