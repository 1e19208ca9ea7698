// The wasm objects behind one BookView, made from its options: the engine's Book, a BookRenderer on the
// canvas (reached through an Emscripten target name) and the FrameLoop, the clock that drives both.
import { directionFacts } from '../engine/direction.js';

let nextTargetId = 1;

/**
 * Makes the Book, the BookRenderer on `canvas` and their FrameLoop; throws a TypeError naming a bad
 * direction, or what the renderer throws without WebGL2 (then nothing is left behind).
 * @returns {{ book: object, renderer: object, loop: object, target: string }}  target: the canvas's
 *   name in engine.specialHTMLTargets, to delete with the renderer
 */
export function createEngineObjects(engine, canvas, options) {
  const { binding } = directionFacts(options.direction ?? 'ltr');  // a TypeError names a bad direction
  const book = engine.Book.create({
    pageCount: options.pageCount,
    display: options.display ?? 'double',
    binding,
    pageWidth: options.pageWidth,
    pageHeight: options.pageHeight,
    turnSeconds: options.turnSeconds,
    hardPages: options.hardPages,
    schedule: options.schedule,
    center: options.center,
    thickness: options.thickness ?? true,
  });
  const target = `!conecurl-canvas-${nextTargetId++}`;
  engine.specialHTMLTargets[target] = canvas;
  let renderer;
  try {
    renderer = engine.BookRenderer.create(target, options.antialias ?? true);
  } catch (error) {
    delete engine.specialHTMLTargets[target];
    book.delete();
    throw error;
  }
  renderer.setOptions({
    lighting: options.lighting ?? true, shadows: options.shadows ?? true, gutter: options.gutter ?? true,
    ...(options.showThrough === undefined ? {} : { showThrough: options.showThrough }),
  });
  return { book, renderer, loop: new engine.FrameLoop(book, renderer), target };
}
