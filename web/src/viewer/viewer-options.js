// The viewer's two options, `controls` and `labels`, checked as options.js checks the others (a
// message saying what is allowed), and the parts of the toolbar a `controls` value shows.
import { LABEL_KEYS } from './viewer-labels.js';

/**
 * The toolbar's parts; `controls: { thumbnails: false }` hides one. `readAloud` (Read aloud and Voice
 * and speed) shows only once the book says it can read aloud (`canReadAloud()`). `keepOffline` (a More
 * menu item) is off unless given, and shows only while a service worker that keeps the site (a published
 * site's sw.js) controls the page.
 */
export const CONTROL_PARTS = ['previous', 'next', 'page', 'zoom', 'fullscreen', 'thumbnails', 'contents', 'search', 'download', 'print', 'readAloud', 'keepOffline'];

const plain = (value) => value !== null && typeof value === 'object' && Object.getPrototypeOf(value) === Object.prototype;

/** true, or what the `controls` option allows. */
export function checkControls(value) {
  return typeof value === 'boolean'
    || (plain(value) && Object.entries(value).every(([key, on]) => CONTROL_PARTS.includes(key) && typeof on === 'boolean'))
    || `true, false or an object of parts to show or hide (${CONTROL_PARTS.join(', ')}), each true or false`;
}

/** true, or what the `labels` option allows. */
export function checkLabels(value) {
  return (plain(value) && Object.entries(value).every(([key, text]) => LABEL_KEYS.includes(key) && typeof text === 'string' && text !== ''))
    || `an object of texts by key (${LABEL_KEYS.join(', ')}), each a non-empty string`;
}

/** Throws a TypeError naming the option, where `controls` or `labels` (unset: their defaults) is not what it allows. */
export function checkViewerOptions(controls = true, labels = {}) {
  for (const [name, value, check] of [['controls', controls, checkControls], ['labels', labels, checkLabels]]) {
    const verdict = check(value);
    if (verdict !== true) throw new TypeError(`conecurl: attachControls option '${name}' must be ${verdict}`);
  }
}

/**
 * The parts shown for a `controls` value: every part is on unless set false, except Download (on
 * for a PDF or a `download` URL) and Print (on for a PDF), which `{ download: true }` or `{ print: true }` shows anyway,
 * and Keep offline, on only with `{ keepOffline: true }`.
 * @param {boolean|object} controls @param {{ pdf: boolean, downloadUrl: boolean }} book
 */
export function shownParts(controls, { pdf, downloadUrl }) {
  const given = plain(controls) ? controls : {};
  const automatic = { download: pdf || downloadUrl, print: pdf, keepOffline: false };
  return Object.fromEntries(CONTROL_PARTS.map((part) => [part, given[part] ?? automatic[part] ?? true]));
}
