// The 2D-canvas floor (issue 24): the WebGL floor's book drawn with a 2D canvas instead, measured
// beside conecurl as what the same turn costs without WebGL: a viewport-sized canvas, drawImage of the
// open pages, and the leaf drawn narrower by cos(angle) about the spine (no perspective); nothing else.
import { floorBook, viewportCanvas } from './floor-book.js';

export async function mount(container, { urls, display, duration }) {
  const { canvas, width, height, ratio } = viewportCanvas(container);
  const context = canvas.getContext('2d');
  if (!context) throw new Error('floor-2d: no 2D context');
  const bitmaps = new Map();  // page -> ImageBitmap (PageImages owns and closes them)

  const surface = {
    has: (page) => bitmaps.has(page),
    prepare(page, bitmap) { bitmaps.set(page, bitmap); },
    draw(quads, place) {
      context.setTransform(ratio, 0, 0, ratio, 0, 0);
      context.clearRect(0, 0, width, height);
      for (const { page, angle } of quads) {
        const across = place.pageWidth * Math.cos(angle);  // negative: left of the spine
        context.drawImage(bitmaps.get(page), Math.min(place.spineX, place.spineX + across), place.top, Math.abs(across), place.pageHeight);
      }
    },
    keep(from, to) {
      for (const page of bitmaps.keys()) if (page < from || page > to) bitmaps.delete(page);
    },
  };
  return floorBook({ urls, display, duration, width, height, ratio, surface });
}
