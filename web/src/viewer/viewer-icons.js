// The toolbar's icons: small inline SVGs (24 x 24, drawn in currentColor) made with DOM calls, never
// parsed from HTML strings. Decorative: each button is named by its label.
const SVG = 'http://www.w3.org/2000/svg';

// One or more path outlines per icon (stroked, round joins).
const PATHS = {
  previous: ['M15 5l-7 7 7 7'],
  next: ['M9 5l7 7-7 7'],
  zoomIn: ['M10.5 4a6.5 6.5 0 1 0 0 13a6.5 6.5 0 1 0 0-13z', 'M15.5 15.5L20 20', 'M10.5 7.5v6M7.5 10.5h6'],
  zoomOut: ['M10.5 4a6.5 6.5 0 1 0 0 13a6.5 6.5 0 1 0 0-13z', 'M15.5 15.5L20 20', 'M7.5 10.5h6'],
  fullscreen: ['M4 9V4h5', 'M15 4h5v5', 'M20 15v5h-5', 'M9 20H4v-5'],
  thumbnails: ['M4 4h6v6H4z', 'M14 4h6v6h-6z', 'M4 14h6v6H4z', 'M14 14h6v6h-6z'],
  contents: ['M4 6h2M9 6h11', 'M4 12h2M9 12h11', 'M4 18h2M9 18h11'],
  search: ['M10.5 4a6.5 6.5 0 1 0 0 13a6.5 6.5 0 1 0 0-13z', 'M15.5 15.5L20 20'],
  download: ['M12 4v11', 'M7 10l5 5 5-5', 'M5 20h14'],
  keepOffline: ['M12 3a9 9 0 1 0 0 18a9 9 0 1 0 0-18z', 'M12 7.5v8', 'M8.5 12l3.5 3.5 3.5-3.5'],
  print: ['M7 9V4h10v5', 'M5 9h14v8h-2', 'M7 17H5', 'M7 14h10v6H7z'],
  close: ['M6 6l12 12', 'M18 6L6 18'],
  up: ['M6 15l6-6 6 6'],
  down: ['M6 9l6 6 6-6'],
  more: ['M5 12h.01', 'M12 12h.01', 'M19 12h.01'],
  read: ['M4 5h6a2 2 0 0 1 2 2v12a2 2 0 0 0-2-2H4z', 'M20 5h-6a2 2 0 0 0-2 2v12a2 2 0 0 1 2-2h6z'],
  exit: ['M9 4v5H4', 'M15 4v5h5', 'M15 20v-5h5', 'M9 20v-5H4'],
  readAloud: ['M4 9.5h3.5L12 5.5v13l-4.5-4H4z', 'M15.5 9a4 4 0 0 1 0 6', 'M18.5 6.5a7.5 7.5 0 0 1 0 11'],
  pauseReading: ['M9 5.5v13', 'M15 5.5v13'],
  readAloudSettings: ['M4 7h16', 'M4 17h16', 'M9 4.5v5', 'M15 14.5v5'],
};

/** The SVG icon named `name` (a key of PATHS), hidden from screen readers. */
export function icon(name) {
  const svg = document.createElementNS(SVG, 'svg');
  svg.setAttribute('viewBox', '0 0 24 24');
  svg.setAttribute('width', '20');
  svg.setAttribute('height', '20');
  svg.setAttribute('aria-hidden', 'true');
  svg.setAttribute('focusable', 'false');
  svg.setAttribute('class', 'conecurl-icon');
  for (const d of PATHS[name]) {
    const path = document.createElementNS(SVG, 'path');
    path.setAttribute('d', d);
    svg.append(path);
  }
  return svg;
}
