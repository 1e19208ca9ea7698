// Types of the CDN build (dist/cdn/conecurl.js, from cdn.js): the main entry's and the element's.
export * from './index.js';
export { ConeFlipbookElement } from './element.js';
