// The demo's HTML book: a small interactive magazine whose pages are live DOM (a form, an animated
// canvas, selectable text) between two drawn covers. Made once; the book shows the same elements again
// when it is rebuilt.
import { drawBookPage } from './book-pages.js';

let pages = null;

function section(title, ...content) {
  const page = document.createElement('section');
  page.className = 'mag-page';
  page.setAttribute('aria-label', title);
  const heading = document.createElement('h2');
  heading.textContent = title;
  page.append(heading, ...content);
  return page;
}

function paragraph(text) {
  const p = document.createElement('p');
  p.textContent = text;
  return p;
}

function orderForm() {
  const form = document.createElement('form');
  const name = Object.assign(document.createElement('input'), { name: 'name', placeholder: 'Your name' });
  const size = document.createElement('select');
  for (const label of ['Paperback', 'Hardback', 'Folio']) size.append(new Option(label));
  const count = Object.assign(document.createElement('input'), { type: 'number', min: 1, value: 1, name: 'count' });
  const button = Object.assign(document.createElement('button'), { type: 'submit', textContent: 'Order' });
  const said = document.createElement('p');
  said.className = 'said';
  form.append(name, size, count, button, said);
  form.addEventListener('submit', (event) => {
    event.preventDefault();
    said.textContent = `Thank you${name.value ? `, ${name.value}` : ''}: ${count.value} × ${size.value}.`;
  });
  return section('Order a copy', paragraph('Type, pick and press: the page stays put while you use it.'), form);
}

function animatedCanvas() {
  const canvas = Object.assign(document.createElement('canvas'), { width: 320, height: 240 });
  const g = canvas.getContext('2d');
  const draw = (now) => {
    if (canvas.isConnected) {
      g.fillStyle = '#f4efe4';
      g.fillRect(0, 0, 320, 240);
      for (let i = 0; i < 12; i++) {
        const a = now / 1000 + (i * Math.PI) / 6;
        g.fillStyle = `hsl(${i * 30}, 60%, 50%)`;
        g.beginPath();
        g.arc(160 + 90 * Math.cos(a), 120 + 70 * Math.sin(a * 1.3), 12, 0, 2 * Math.PI);
        g.fill();
      }
    }
    requestAnimationFrame(draw);
  };
  requestAnimationFrame(draw);
  return section('A canvas that moves', paragraph('Live while the page lies open; caught mid-motion when it turns.'), canvas);
}

function essay() {
  return section('On the curl of a page',
    paragraph('A page that turns is a cone: its apex slides down below the book while the cone narrows, '
      + 'and the whole sheet rotates about the spine. Select this text, copy it, search it: it is text.'),
    paragraph('While the page moves it is a picture of itself, drawn the moment the turn starts, so the '
      + 'curl stays smooth and the words come back as words when it lies down again.'));
}

// A page with what rasterisers find hard: a web font (the headings' Lora), an image, inline SVG and a
// CSS transform.
function gallery() {
  const image = new Image();
  image.src = drawBookPage(5).toDataURL();
  image.alt = 'A page of the drawn book';
  image.className = 'mag-thumb';
  const svgNs = 'http://www.w3.org/2000/svg';
  const svg = document.createElementNS(svgNs, 'svg');
  svg.setAttribute('viewBox', '0 0 120 80');
  svg.setAttribute('class', 'mag-figure');
  svg.setAttribute('role', 'img');
  svg.setAttribute('aria-label', 'A cone and the page wrapped around it');
  const shape = (name, attributes) => {
    const node = document.createElementNS(svgNs, name);
    for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, value);
    svg.append(node);
  };
  shape('path', { d: 'M60 6 L20 74 L100 74 Z', fill: '#e7d7b8', stroke: '#7a2e1d', 'stroke-width': 1.5 });
  shape('path', { d: 'M60 6 Q88 40 100 74', fill: 'none', stroke: '#2e86c1', 'stroke-width': 2 });
  const badge = document.createElement('span');
  badge.className = 'mag-badge';
  badge.textContent = 'New';
  return section('Pictures', badge, image, svg, paragraph('An image, a drawing in SVG and a tilted label: the texture keeps them.'));
}

/** The magazine's pages: drawn covers around live HTML pages. */
export function magazinePages() {
  pages ??= [
    { src: () => drawBookPage(0), alt: 'Front cover', hard: true },
    essay(),
    orderForm(),
    animatedCanvas(),
    gallery(),
    section('Colophon', paragraph('Set in DejaVu, headings in Lora (a web font). Pages are HTML elements given to the book as they are.')),
    { src: () => drawBookPage(39), alt: 'Back cover', hard: true },
  ];
  return pages;
}
