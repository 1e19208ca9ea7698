// Benchmark adapter for page-flip (StPageFlip 2.0.7) in its image mode: pages drawn on a 2D canvas,
// stretched to the container, the cover shown alone like the other two; turns with flipNext().
import { PageFlip } from 'page-flip';

const PAGE_WIDTH = 640;
const PAGE_HEIGHT = 800;

export async function mount(container, { urls, display, duration }) {
  const flip = new PageFlip(container, {
    width: PAGE_WIDTH,
    height: PAGE_HEIGHT,
    size: 'stretch',
    minWidth: 100,
    maxWidth: 2000,
    minHeight: 100,
    maxHeight: 2000,
    usePortrait: display === 'single',
    showCover: true,
    flippingTime: duration,
  });
  const initialized = new Promise((resolve) => flip.on('init', resolve));
  flip.loadFromImages(urls);
  await initialized;
  // Ready when the pages on screen have loaded (ImagePage.isLoad; page-flip has no event for it).
  const shown = () => {
    const first = flip.getCurrentPageIndex();
    const count = flip.getOrientation() === 'portrait' || first === 0 ? 1 : 2;
    return Array.from({ length: count }, (_, i) => flip.getPage(first + i)).filter(Boolean);
  };
  while (!shown().every((page) => page.isLoad)) await new Promise((resolve) => requestAnimationFrame(resolve));
  return {
    turn() {
      return new Promise((resolve, reject) => {
        const before = flip.getCurrentPageIndex();
        const onState = (event) => {
          if (event.data !== 'read') return;
          flip.off('changeState');
          if (flip.getCurrentPageIndex() === before) reject(new Error(`page-flip: did not turn from page ${before}`));
          else resolve();
        };
        flip.on('changeState', onState);
        flip.flipNext();
      });
    },
    stats() {
      return { page: flip.getCurrentPageIndex() };
    },
  };
}
