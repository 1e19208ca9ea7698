// The CDN build's entry (dist/cdn/conecurl.js, made by scripts/build-bundles.mjs): the package's main
// entry and <cone-flipbook> in one module, for a page that loads conecurl with one <script type="module">.
export * from './index.js';
export { ConeFlipbookElement } from './element.js';
