// Search hits (and the word and sentence read aloud) drawn into a page's image: a copy of the image with highlight rectangles multiplied over
// it, handed to the surface in place of the clean image while the page has marks. So the marks are in
// the page's texture and curl with the paper through a turn; the clean image is kept by the page store
// and handed over again when the marks go.

const MAX_SIDE = 4096;  // the copy is never larger than this on a side (a texture's usual limit)
export const HIT_FILL = 'rgba(255, 214, 0, 0.55)';       // a hit: yellow, multiplied (text stays dark)
export const CURRENT_FILL = 'rgba(255, 140, 0, 0.65)';   // the hit shown now: orange
export const READING_FILL = 'rgba(90, 170, 255, 0.5)';   // the word read aloud: blue, multiplied
export const SENTENCE_FILL = 'rgba(90, 170, 255, 0.18)';  // the sentence read aloud: the word's blue, lighter

/**
 * `image` with `marks` drawn over it: a new canvas (the image itself is not changed).
 * @param {CanvasImageSource|ImageData} image
 * @param {Array<{ rect: number[], current?: boolean, reading?: boolean, sentence?: boolean }>} marks  rects [x, y, w, h] as fractions of the page
 */
export function markedPageImage(image, marks) {
  const width = image.naturalWidth || image.width;
  const height = image.naturalHeight || image.height;
  const scale = Math.min(1, MAX_SIDE / Math.max(width, height));
  const canvas = document.createElement('canvas');
  canvas.width = Math.max(1, Math.round(width * scale));
  canvas.height = Math.max(1, Math.round(height * scale));
  const g = canvas.getContext('2d');
  if (typeof ImageData !== 'undefined' && image instanceof ImageData) {
    const copy = document.createElement('canvas');
    copy.width = width;
    copy.height = height;
    copy.getContext('2d').putImageData(image, 0, 0);
    g.drawImage(copy, 0, 0, canvas.width, canvas.height);
  } else {
    g.drawImage(image, 0, 0, canvas.width, canvas.height);
  }
  g.globalCompositeOperation = 'multiply';
  const pad = Math.max(1, canvas.height * 0.002);
  for (const { rect: [x, y, w, h], current, reading, sentence } of marks) {
    g.fillStyle = reading ? READING_FILL : sentence ? SENTENCE_FILL : current ? CURRENT_FILL : HIT_FILL;
    g.fillRect(x * canvas.width - pad, y * canvas.height - pad, w * canvas.width + 2 * pad, h * canvas.height + 2 * pad);
  }
  return canvas;
}
