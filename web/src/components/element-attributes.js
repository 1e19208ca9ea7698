// <cone-flipbook>'s attributes: each one's Flipbook option and parser, which apply live, the options that
// have none and why, and the option properties frameworks set: which values a property keeps as given
// and how the others are written to the attribute (element.js uses them; the element's behaviour stays
// there). tests/node/typings.test.mjs holds every option to an attribute or a reason, and element.d.ts to these.
import { LIVE_OPTIONS, describeValue } from '../book/options.js';

export const TAG = 'cone-flipbook';

const parseText = (raw) => raw;
function parseNumber(raw, attribute) {
  const value = Number(raw);
  if (raw.trim() === '' || !Number.isFinite(value)) throw attributeError(attribute, 'a number', raw);
  return value;
}
// "true" or a bare attribute: true; "false": false; anything else: undefined.
const flag = (raw) => (raw === '' || raw === 'true' ? true : raw === 'false' ? false : undefined);
// read-aloud-memory: "false" keeps nothing; any other text is the key.
const parseMemory = (raw) => (raw === 'false' ? false : raw);
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
function parseResolution(raw, attribute) {
  if (raw === 'auto' || raw === 'full') return raw;
  const value = Number(raw);
  if (raw.trim() !== '' && Number.isFinite(value)) return value;  // its range is checked with the options
  throw attributeError(attribute, '"auto", "full" or device pixels per CSS pixel', raw);
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
// labels='{"next": "Suivant"}': a JSON object (checked as the option is).
function parseJsonObject(raw, attribute) {
  try {
    const value = JSON.parse(raw);
    if (value !== null && typeof value === 'object' && !Array.isArray(value)) return value;
  } catch { /* reported below */ }
  throw attributeError(attribute, 'a JSON object of texts by key', raw);
}
function parseList(raw, attribute) {
  const urls = raw.split(/\s+/).filter(Boolean);
  if (urls.length === 0) throw attributeError(attribute, 'image URLs separated by spaces', raw);
  return urls;
}

// docapi (issue 23): the outline as JSON text.
function parseOutline(raw, attribute) {
  try {
    return JSON.parse(raw);
  } catch {
    throw attributeError(attribute, 'JSON: an array of { "title", "page", "children"? }', raw);
  }
}

// attribute -> [Flipbook option, parser]; the parsers check syntax, Flipbook.create the values.
export const ATTRIBUTES = {
  pages: ['pages', parseList],
  display: ['display', parseText],
  'min-page-width': ['minPageWidth', parseNumber],
  direction: ['direction', parseText],
  'start-page': ['startPage', parseNumber],
  duration: ['duration', parseNumber],
  schedule: ['schedule', parseText],
  center: ['center', parseBoolean],
  'hard-covers': ['hardCovers', parseBoolean],
  lighting: ['lighting', parseBoolean],
  shadows: ['shadows', parseBoolean],
  gutter: ['gutter', parseBoolean],
  'show-through': ['showThrough', parseNumber],
  thickness: ['thickness', parseThickness],
  'load-window': ['loadWindow', parseNumber],
  hash: ['hash', parseBoolean],
  autoplay: ['autoplay', parseAutoplay],
  sound: ['sound', parseBoolean],
  muted: ['muted', parseBoolean],
  'remember-page': ['rememberPage', parseText],
  'read-aloud-memory': ['readAloudMemory', parseMemory],
  'wasm-url': ['wasmUrl', parseText],
  antialias: ['antialias', parseAntialias],
  resolution: ['resolution', parseResolution],
  'turn-area': ['turnArea', parseText],
  label: ['label', parseText],
  fallback: ['fallback', parseBoolean],
  pdf: ['pdf', parseText],
  'pdf-worker-src': ['pdfWorkerSrc', parseText],
  // publish (issue 30): a published document's book.json. Named src, not document: an element property
  // named document would be what `document` means in the element's inline event handlers (onclick="…").
  src: ['document', parseText],
  // docapi (issue 23)
  outline: ['outline', parseOutline],
  download: ['download', parseText],
  // edgemarks (issue 23)
  'edge-marks': ['edgeMarks', parseBoolean],
  // viewer (issue 23): a bare `controls` shows the whole toolbar; the parts as an object go through the property.
  controls: ['controls', parseBoolean],
  labels: ['labels', parseJsonObject],
  // textlayer (issue 23)
  'text-layer': ['textLayer', parseBoolean],
};
/** Options with no attribute, and why. */
export const NO_ATTRIBUTE = {
  on: "listeners by event name: the element dispatches every book event itself, so listen on it (addEventListener, or a framework's event binding)",
};
/**
 * The element's property of an option where it is not the option's name: a property `document` would
 * shadow the global document in inline event handler attributes (their scope starts at the element).
 */
export const PROPERTY_OF_OPTION = { document: 'src' };
/** The element's property name of `option`. */
export const propertyOf = (option) => PROPERTY_OF_OPTION[option] ?? option;
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

const plainObject = (value) => value !== null && typeof value === 'object' && Object.getPrototypeOf(value) === Object.prototype;

/**
 * Property values an attribute cannot hold, by option: given as a property, such a value is kept as
 * given (the property reads it back, the book gets it) and wins over the attribute (the pages, over
 * the child elements too). `strings`: the attribute takes only a string from a property.
 */
export const KEPT_VALUES = {
  pages: { keeps: Array.isArray, strings: true, allowed: 'an array of pages or a string of URLs' },
  pdf: { keeps: (value) => value instanceof ArrayBuffer || value instanceof Uint8Array, strings: true,
    allowed: 'a URL string, an ArrayBuffer or a Uint8Array' },
  autoplay: { keeps: plainObject, allowed: 'true, false, { interval, loop } or the milliseconds between turns' },
  outline: { keeps: Array.isArray, strings: true, allowed: 'an array of { title, page, children? } or its JSON text' },
  controls: { keeps: plainObject, allowed: 'true, false or an object of parts ({ search: false })' },
  labels: { keeps: plainObject, strings: true, allowed: 'an object of texts by key, or its JSON' },
};

/** Whether a property value for `option` is kept as given rather than written to the attribute. */
export const keepsValue = (option, value) => Boolean(KEPT_VALUES[option]?.keeps(value));

/**
 * Writes an option's property value to its attribute (a string, number or boolean as text); null or
 * undefined removes it. A TypeError naming the property for a value no attribute holds.
 */
export function setOptionAttribute(element, option, value) {
  const attribute = ATTRIBUTE_OF_OPTION[option];
  if (value === null || value === undefined) {
    element.removeAttribute(attribute);
    return;
  }
  const strings = KEPT_VALUES[option]?.strings;
  if (typeof value !== 'string' && (strings || !(typeof value === 'number' || typeof value === 'boolean'))) {
    throw new TypeError(`conecurl: <${TAG}> property '${propertyOf(option)}' must be ${KEPT_VALUES[option]?.allowed
      ?? 'a string, number or boolean (as its attribute takes)'}, got ${typeof value === 'object' ? describeValue(value) : typeof value}`);
  }
  element.setAttribute(attribute, String(value));
}

// Every option with an attribute is a property too (Svelte, Angular and others set properties when an
// element has them): reading gives the value kept (KEPT_VALUES) or the attribute's, parsed; writing
// keeps the value or sets (null: removes) the attribute. Each is named propertyOf(option).
export const PROPERTY_OPTIONS = Object.values(ATTRIBUTES).map(([option]) => option);

