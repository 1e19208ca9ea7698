// Node test: the browser modules never parse strings as HTML. Option values, alt text, URLs and error
// messages reach the DOM only as textContent or attributes; the one HTML string is element.js's
// constant shadow-root template, which holds no value from outside.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const source = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../web/src');
const HTML_SINKS = /\b(innerHTML|outerHTML|insertAdjacentHTML|createContextualFragment|document\.write|DOMParser|srcdoc|setHTMLUnsafe)\b/g;

test('node: web/src writes no HTML from strings except element.js\'s constant template', () => {
  const found = [];
  for (const file of fs.readdirSync(source, { recursive: true }).filter((name) => name.endsWith('.js'))) {
    const text = fs.readFileSync(path.join(source, file), 'utf8');
    for (const match of text.matchAll(HTML_SINKS)) {
      const line = text.slice(0, match.index).split('\n').length;
      found.push(`${file}: ${text.split('\n')[line - 1].trim()}`);
    }
  }
  assert.deepEqual(found, ["element.js: this.attachShadow({ mode: 'open' }).innerHTML = TEMPLATE;"]);
  // The template is a plain string literal: no ${...} can bring a value into it.
  const element = fs.readFileSync(path.join(source, 'element.js'), 'utf8');
  const template = /const TEMPLATE = `([^`]*)`;/.exec(element);
  assert.ok(template, 'TEMPLATE is a template literal in element.js');
  assert.doesNotMatch(template[1], /\$\{/);
});
