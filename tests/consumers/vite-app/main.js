// The app's code: the Flipbook class and the element side by side; the page images are in public/pages.
import { Flipbook } from 'conecurl';
import 'conecurl/element';

const pages = Array.from({ length: 6 }, (_, i) => `pages/page-${i}.svg`);
try {
  const book = await Flipbook.create(document.getElementById('flipbook'), { pages, display: 'double' });
  const element = document.querySelector('cone-flipbook');
  await element.whenReady();
  window.app = { book, element };
  document.body.dataset.ready = 'true';
} catch (error) {
  document.body.dataset.error = String(error && error.message ? error.message : error);
}
