// The box a book fills, one rule for all three ways in: <cone-flipbook> sizes itself with it (:host),
// the React and Vue components render their container with it. A block as wide as its parent, 16:10
// unless the page's CSS (or the components' `style`) says otherwise.
export const BOX_STYLE = { display: 'block', position: 'relative', width: '100%', aspectRatio: '16 / 10' };

/** BOX_STYLE as CSS declarations: "display: block; position: relative; ...". */
export const BOX_CSS = Object.entries(BOX_STYLE)
  .map(([property, value]) => `${property.replace(/[A-Z]/g, (letter) => `-${letter.toLowerCase()}`)}: ${value};`).join(' ');
