// <cone-flipbook>'s attributes: each one's Flipbook option and parser, which apply live, and the option
// properties frameworks set (element.js uses them; the element's behaviour stays there).
import { LIVE_OPTIONS } from '../book/options.js';

export const TAG = 'cone-flipbook';

const parseText = (raw) => raw;
function parseNumber(raw, attribute) {
  const value = Number(raw);
  if (raw.trim() === '' || !Number.isFinite(value)) throw attributeError(attribute, 'a number', raw);
  return value;
}
// "true" or a bare attribute: true; "false": false; anything else: undefined.
const flag = (raw) => (raw === '' || raw === 'true' ? true : raw === 'false' ? false : undefined);
function parseBoolean(raw, attribute) {
  const value = flag(raw);
  if (value === undefined) throw attributeError(attribute, '"true" or "false"', raw);
  return value;
}
function parseAntialias(raw, attribute) {
  const value = raw === 'auto' ? 'auto' : flag(raw);
  if (value === undefined) throw attributeError(attribute, '"auto", "true" or "false"', raw);
  return value;
}
function parseThickness(raw, attribute) {
  if (flag(raw) !== undefined) return flag(raw);
  const value = Number(raw);
  if (raw.trim() !== '' && Number.isFinite(value)) return value;  // its range is checked with the options
  throw attributeError(attribute, '"true", "false" or a leaf\'s thickness as a fraction of the page width', raw);
}
function parseAutoplay(raw, attribute) {
  if (flag(raw) !== undefined) return flag(raw);
  const interval = Number(raw);
  if (raw.trim() !== '' && Number.isFinite(interval) && interval > 0) return { interval };
  throw attributeError(attribute, '"true", "false" or the milliseconds between turns', raw);
}
function parseList(raw, attribute) {
  const urls = raw.split(/\s+/).filter(Boolean);
  if (urls.length === 0) throw attributeError(attribute, 'image URLs separated by spaces', raw);
  return urls;
}

// attribute -> [Flipbook option, parser]; the parsers check syntax, Flipbook.create the values.
export const ATTRIBUTES = {
  pages: ['pages', parseList],
  display: ['display', parseText],
  direction: ['direction', parseText],
  'start-page': ['startPage', parseNumber],
  duration: ['duration', parseNumber],
  schedule: ['schedule', parseText],
  center: ['center', parseBoolean],
  'hard-covers': ['hardCovers', parseBoolean],
  lighting: ['lighting', parseBoolean],
  shadows: ['shadows', parseBoolean],
  gutter: ['gutter', parseBoolean],
  thickness: ['thickness', parseThickness],
  'load-window': ['loadWindow', parseNumber],
  hash: ['hash', parseBoolean],
  autoplay: ['autoplay', parseAutoplay],
  sound: ['sound', parseBoolean],
  muted: ['muted', parseBoolean],
  'remember-page': ['rememberPage', parseText],
  'wasm-url': ['wasmUrl', parseText],
  antialias: ['antialias', parseAntialias],
  pdf: ['pdf', parseText],
  'pdf-worker-src': ['pdfWorkerSrc', parseText],
};
export const ATTRIBUTE_OF_OPTION = Object.fromEntries(Object.entries(ATTRIBUTES).map(([name, [option]]) => [option, name]));
/** Attributes applied to the running book (Flipbook.setOptions), no rebuild. */
export const LIVE_ATTRIBUTES = LIVE_OPTIONS.map((option) => ATTRIBUTE_OF_OPTION[option]);

function attributeError(attribute, expected, raw) {
  return new TypeError(`conecurl: <${TAG}> attribute '${attribute}' must be ${expected}, got "${raw}"`);
}

/** An option's attribute on `element`, parsed (undefined when absent; as written when it does not parse). */
export function readOptionAttribute(element, option) {
  const attribute = ATTRIBUTE_OF_OPTION[option];
  const raw = element.getAttribute(attribute);
  if (raw === null) return undefined;
  try { return ATTRIBUTES[attribute][1](raw, attribute); } catch { return raw; }  // a bad value is reported by the build
}

/** Writes an option to its attribute (String(value)); null or undefined removes it. */
export function setOptionAttribute(element, option, value) {
  const attribute = ATTRIBUTE_OF_OPTION[option];
  if (value === null || value === undefined) element.removeAttribute(attribute);
  else element.setAttribute(attribute, String(value));
}

// Every other option is a property too (Svelte, Angular and others set properties when an element has
// them): reading gives the attribute's value, parsed; writing sets or (null) removes the attribute.
export const PROPERTY_OPTIONS = Object.values(ATTRIBUTES).map(([option]) => option);

/** Defines the option properties `prototype` does not define itself (display, pages and pdf it does). */
export function defineOptionProperties(prototype) {
  for (const [option] of Object.values(ATTRIBUTES)) {
    if (option in prototype) continue;
    Object.defineProperty(prototype, option, {
      configurable: true,
      get() { return readOptionAttribute(this, option); },
      set(value) { setOptionAttribute(this, option, value); },
    });
  }
}

