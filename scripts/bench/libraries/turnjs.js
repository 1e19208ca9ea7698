// Benchmark adapter for turn.js 1.0.5 with the jQuery it pins (1.12.0): the documented HTML usage,
// one <div><img></div> per page, the book sized to fit the viewport; turns with turn('next').
import $ from 'jquery';
import 'turn.js';

const PAGE_ASPECT = 640 / 800;

export async function mount(container, { urls, display, duration }) {
  const { width: boxWidth, height: boxHeight } = container.getBoundingClientRect();
  const spreadPages = display === 'double' ? 2 : 1;
  const height = Math.floor(Math.min(boxHeight, boxWidth / (spreadPages * PAGE_ASPECT)));
  const width = Math.floor(height * PAGE_ASPECT) * spreadPages;
  const book = document.createElement('div');
  book.style.cssText = `position:absolute;left:${Math.round((boxWidth - width) / 2)}px;top:${Math.round((boxHeight - height) / 2)}px`;
  for (const url of urls) {
    const page = document.createElement('div');
    const image = document.createElement('img');
    image.src = url;
    image.style.cssText = 'width:100%;height:100%;display:block';
    page.append(image);
    book.append(page);
  }
  container.append(book);
  const $book = $(book);
  $book.turn({ width, height, display, duration, acceleration: true, gradients: true });
  // Ready when the images of the pages on screen are decoded.
  const shown = [...book.querySelectorAll('img')].filter((img) => img.getBoundingClientRect().width > 0);
  await Promise.all(shown.map((img) => img.decode().catch(() => {})));
  return {
    turn() {
      // Resolves when turn.js reports the turn landed; a turn that never lands hits the harness timeout.
      return new Promise((resolve) => {
        $book.one('turned', () => resolve());
        $book.turn('next');
      });
    },
    stats() {
      return { page: $book.turn('page') };
    },
  };
}
