// The viewer's look, in one style sheet themed by CSS custom properties (docs/api.md lists them), put
// where the book lives: adopted by its document or shadow root (works under a strict CSP), else a <style>.
const VIEWER_CSS = `
.conecurl-viewer {
  position: relative; box-sizing: border-box; height: var(--conecurl-toolbar-height, 44px);
  font: var(--conecurl-toolbar-font, 14px/1.2 system-ui, sans-serif);
  color: var(--conecurl-toolbar-fg, #f5f5f2); background: var(--conecurl-toolbar-bg, #24292e);
}
.conecurl-toolbar {
  display: flex; align-items: center; gap: 2px; height: 100%; padding: 0 6px; box-sizing: border-box;
  overflow-x: auto; scrollbar-width: none;
}
.conecurl-toolbar .conecurl-gap { flex: 1 1 0; min-width: 4px; }
.conecurl-viewer button, .conecurl-viewer input {
  font: inherit; color: inherit; background: transparent; border: 0; border-radius: 6px; margin: 0;
}
.conecurl-viewer button {
  display: inline-flex; align-items: center; gap: 6px; flex: none; height: 36px; min-width: 36px;
  padding: 0 8px; cursor: pointer; justify-content: center;
}
.conecurl-viewer button:hover { background: var(--conecurl-toolbar-hover, rgba(255, 255, 255, 0.14)); }
.conecurl-viewer button[aria-pressed="true"], .conecurl-viewer button[aria-expanded="true"], .conecurl-toolbar button[data-on="true"] {
  background: var(--conecurl-accent, #3d7be0); color: var(--conecurl-accent-fg, #ffffff);
}
.conecurl-viewer button[aria-disabled="true"] { opacity: 0.45; cursor: default; }
.conecurl-viewer :is(button, input, [tabindex]):focus { outline: none; }
.conecurl-viewer :is(button, input, [tabindex]):focus-visible {
  outline: var(--conecurl-focus-ring, 3px solid #8ab4ff); outline-offset: -3px;
}
.conecurl-icon { flex: none; fill: none; stroke: currentColor; stroke-width: 2; stroke-linecap: round; stroke-linejoin: round; }
.conecurl-page-field {
  flex: none; width: 7.5em; height: 30px; padding: 0 6px; box-sizing: border-box; text-align: center;
  background: var(--conecurl-field-bg, rgba(255, 255, 255, 0.12)) !important;
}
.conecurl-hidden-text, .conecurl-viewer:is([data-narrow], [data-compact]) .conecurl-text {
  position: absolute; width: 1px; height: 1px; margin: -1px; padding: 0; border: 0; overflow: hidden;
  clip: rect(0 0 0 0); clip-path: inset(50%); white-space: nowrap;
}
.conecurl-viewer[data-narrow] .conecurl-toolbar { gap: 0; padding: 0 4px; }
.conecurl-viewer[data-narrow] .conecurl-toolbar button { min-width: 32px; padding: 0 4px; }
.conecurl-viewer[data-narrow] .conecurl-gap { min-width: 0; }
.conecurl-viewer[data-narrow] .conecurl-page-field { width: 5.5em; padding: 0 2px; }
.conecurl-panel {
  position: absolute; left: 0; bottom: 100%; z-index: 2; display: flex; flex-direction: column;
  width: var(--conecurl-panel-width, 300px); max-width: 100%; box-sizing: border-box;
  color: var(--conecurl-panel-fg, #1d1d1b); background: var(--conecurl-panel-bg, #fbfaf7);
  box-shadow: 0 0 18px rgba(0, 0, 0, 0.28);
}
.conecurl-viewer[data-narrow] .conecurl-panel { width: 100%; border-radius: 12px 12px 0 0; }
.conecurl-panel[hidden] { display: none; }
.conecurl-panel-head { display: flex; align-items: center; gap: 8px; padding: 4px 4px 4px 12px; flex: none; }
.conecurl-panel-head h2 { flex: 1; margin: 0; font-size: 1em; font-weight: 600; }
.conecurl-panel-body { flex: 1; min-height: 0; overflow: auto; position: relative; }
.conecurl-panel button:hover { background: var(--conecurl-panel-hover, rgba(0, 0, 0, 0.07)); }
.conecurl-viewer .conecurl-panel :is(button, input, [tabindex]):focus-visible { outline-color: var(--conecurl-accent, #3d7be0); }
.conecurl-thumbs { position: relative; }
.conecurl-thumb {
  position: absolute; flex-direction: column; height: auto !important; padding: 4px !important; gap: 4px !important;
}
.conecurl-thumb-frame { display: block; background: #ffffff; box-shadow: 0 1px 3px rgba(0, 0, 0, 0.3); overflow: hidden; }
.conecurl-thumb-frame canvas { display: block; width: 100%; height: 100%; }
.conecurl-thumb[aria-current="page"] .conecurl-thumb-frame { outline: 3px solid var(--conecurl-accent, #3d7be0); }
.conecurl-thumb[aria-current="page"] { font-weight: 700; }
.conecurl-tree, .conecurl-tree ul, .conecurl-results { list-style: none; margin: 0; padding: 0; }
.conecurl-tree ul { padding-left: 14px; }
.conecurl-tree button, .conecurl-results button {
  display: flex; width: 100%; height: auto; min-height: 32px; justify-content: space-between; text-align: left;
  padding: 6px 12px; border-radius: 0;
}
.conecurl-tree button[aria-current] { box-shadow: inset 4px 0 var(--conecurl-accent, #3d7be0); font-weight: 700; }
.conecurl-results button { flex-direction: column; align-items: stretch; gap: 2px; }
.conecurl-results button[aria-current] { box-shadow: inset 4px 0 var(--conecurl-accent, #3d7be0); }
.conecurl-result-page { font-size: 0.85em; font-weight: 600; color: var(--conecurl-panel-muted, #55534e); }
.conecurl-search-row { display: flex; gap: 4px; padding: 4px 8px 8px; flex: none; align-items: center; }
.conecurl-search-row input {
  flex: 1; min-width: 0; height: 32px; padding: 0 8px; border: 1px solid #8d8a83 !important; border-radius: 6px;
  background: #ffffff !important; color: #1d1d1b !important;
}
.conecurl-search-status { padding: 0 12px 6px; min-height: 1.2em; flex: none; }
.conecurl-empty { padding: 12px; margin: 0; }
.conecurl-viewer button[hidden] { display: none; }
.conecurl-menu {
  position: absolute; right: 4px; bottom: 100%; z-index: 3; display: flex; flex-direction: column;
  min-width: 190px; max-width: calc(100vw - 8px); padding: 4px 0; box-sizing: border-box; overflow-y: auto;
  overscroll-behavior: contain; border-radius: 8px; box-shadow: 0 2px 18px rgba(0, 0, 0, 0.32);
  color: var(--conecurl-panel-fg, #1d1d1b); background: var(--conecurl-panel-bg, #fbfaf7);
}
.conecurl-menu[data-below] { bottom: auto; top: 100%; }
.conecurl-menu[hidden] { display: none; }
.conecurl-offline-status {
  position: absolute; right: 4px; bottom: 100%; z-index: 2; display: flex; flex-direction: column; gap: 4px;
  max-width: min(320px, calc(100% - 8px)); margin-bottom: 4px; padding: 8px 12px; border-radius: 6px;
  background: var(--conecurl-toolbar-bg, #24292e); color: var(--conecurl-toolbar-fg, #f5f5f2);
}
.conecurl-offline-status[hidden], .conecurl-offline-status progress[hidden] { display: none; }
.conecurl-offline-status progress { width: 100%; accent-color: var(--conecurl-accent, #3d7be0); }
.conecurl-viewer .conecurl-menu button {
  justify-content: flex-start; width: 100%; height: auto; min-height: 36px; padding: 0 14px; gap: 10px; border-radius: 0;
}
.conecurl-menu button:hover, .conecurl-menu button:focus { background: var(--conecurl-panel-hover, rgba(0, 0, 0, 0.07)); }
.conecurl-menu button[data-on="true"] { box-shadow: inset 4px 0 var(--conecurl-accent, #3d7be0); font-weight: 700; }
.conecurl-viewer .conecurl-menu :is(button):focus-visible { outline-color: var(--conecurl-accent, #3d7be0); }
.conecurl-read-menu {
  right: auto; gap: 10px; padding: 10px 12px 12px; width: max-content; min-width: 200px;
  max-width: min(320px, calc(100vw - 8px)); margin-bottom: 4px;
}
.conecurl-read-menu[data-below] { margin: 4px 0 0; }
.conecurl-read-field { display: flex; flex-direction: column; gap: 4px; min-width: 0; }
.conecurl-read-field[hidden] { display: none; }
.conecurl-read-field label { font-weight: 600; }
.conecurl-read-menu select {
  font: inherit; width: 100%; height: 34px; padding: 0 6px; box-sizing: border-box; border-radius: 6px;
  border: 1px solid #8d8a83; background: #ffffff; color: #1d1d1b; text-overflow: ellipsis; cursor: pointer;
}
.conecurl-read-menu select:focus { outline: none; }
.conecurl-read-menu select:focus-visible {
  outline: var(--conecurl-focus-ring, 3px solid #8ab4ff); outline-color: var(--conecurl-accent, #3d7be0); outline-offset: 1px;
}
.conecurl-viewer[data-reading] { position: absolute; left: 0; right: 0; bottom: 0; z-index: 2; }
.conecurl-viewer[data-reading][data-bar-hidden] { transform: translateY(100%); visibility: hidden; }
@media (prefers-reduced-motion: no-preference) {
  .conecurl-viewer[data-reading] { transition: transform 0.2s ease, visibility 0.2s; }
}
@media (pointer: coarse) {
  .conecurl-viewer .conecurl-toolbar { gap: 0; padding: 0 2px; }
  .conecurl-viewer.conecurl-viewer button, .conecurl-viewer.conecurl-viewer .conecurl-toolbar button { min-width: 44px; min-height: 44px; }
  .conecurl-viewer.conecurl-viewer :is(.conecurl-toolbar, .conecurl-panel-head, .conecurl-search-row) button { height: 44px; }
  .conecurl-viewer.conecurl-viewer .conecurl-menu button { min-height: 48px; }
  .conecurl-viewer.conecurl-viewer .conecurl-page-field { height: 44px; }
  .conecurl-viewer.conecurl-viewer[data-narrow] .conecurl-page-field { width: 5em; }
  .conecurl-viewer .conecurl-search-row input { height: 44px; }
  .conecurl-viewer .conecurl-read-menu select { height: 44px; }
}
.conecurl-viewer[data-coarse] .conecurl-panel {
  position: fixed; left: 0; right: 0; top: auto; bottom: 0; z-index: 2147483001; width: 100%; max-width: none;
  height: 45vh; height: 45dvh; border-radius: 12px 12px 0 0;
}
.conecurl-viewer[data-coarse][data-landscape] .conecurl-panel {
  top: 0; right: auto; width: min(360px, 45vw); height: 100vh; height: 100dvh; border-radius: 0 12px 12px 0;
}`;

let sharedSheet = null;

/** Puts the viewer's style sheet in the document or shadow root holding `element`; returns its removal. */
export function installViewerStyle(element) {
  const scope = element.getRootNode();
  const canAdopt = typeof CSSStyleSheet === 'function' && 'replaceSync' in CSSStyleSheet.prototype
    && scope && 'adoptedStyleSheets' in scope;
  if (canAdopt) {
    if (!sharedSheet) {
      sharedSheet = new CSSStyleSheet();
      sharedSheet.replaceSync(VIEWER_CSS);
    }
    if (!scope.adoptedStyleSheets.includes(sharedSheet)) scope.adoptedStyleSheets = [...scope.adoptedStyleSheets, sharedSheet];
    return () => {};  // shared by the books of that document: it stays
  }
  const style = document.createElement('style');
  style.textContent = VIEWER_CSS;
  element.append(style);
  return () => style.remove();
}
