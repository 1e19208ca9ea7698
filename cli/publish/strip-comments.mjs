// The package's modules as a published site serves them: without their comments. They are written to be
// read (a good part of their bytes are comments), and a reader's phone downloads them before its first
// spread. A small lexer that knows strings, template literals and regular expressions, so that nothing
// inside one is touched; every stripped module is checked to parse and to keep its code (tests/node).

// After these, a `/` starts a regular expression, not a division.
const BEFORE_REGEX = new Set([...'(,=:[!&|?{};+-*%<>~^'].map((c) => c));
const KEYWORDS_BEFORE_REGEX = new Set(['return', 'typeof', 'case', 'in', 'of', 'delete', 'void', 'throw', 'new', 'else', 'do', 'yield', 'await']);

/** `source` (an ES module) without its comments; a block comment over lines leaves a line break (ASI holds). */
export function stripComments(source) {
  let out = '';
  let i = 0;
  let last = '';      // the last significant character written
  let lastWord = '';  // the last identifier written, when it was the last token
  const braces = [];  // for each `{` open: whether it opened a template literal's ${
  const copyQuoted = (quote) => {
    const start = i;
    for (i += 1; i < source.length && source[i] !== quote; i += 1) if (source[i] === '\\') i += 1;
    i += 1;
    out += source.slice(start, i);
  };
  // A template literal's text from i (just after ` or }) to its end or its next ${.
  const copyTemplate = () => {
    const start = i;
    while (i < source.length && source[i] !== '`' && !(source[i] === '$' && source[i + 1] === '{')) i += source[i] === '\\' ? 2 : 1;
    if (source[i] === '`') {
      i += 1;
    } else {
      i += 2;
      braces.push(true);
    }
    out += source.slice(start, i);
  };
  while (i < source.length) {
    const c = source[i];
    const next = source[i + 1];
    if (c === '/' && next === '/') {
      while (i < source.length && source[i] !== '\n') i += 1;
    } else if (c === '/' && next === '*') {
      const end = source.indexOf('*/', i + 2);
      const comment = source.slice(i, end < 0 ? source.length : end + 2);
      i += comment.length;
      out += comment.includes('\n') ? '\n' : ' ';
    } else if (c === '"' || c === "'") {
      copyQuoted(c);
      [last, lastWord] = [c, ''];
    } else if (c === '`') {
      out += c;
      i += 1;
      copyTemplate();
      [last, lastWord] = ['`', ''];
    } else if (c === '/' && (last === '' || BEFORE_REGEX.has(last) || KEYWORDS_BEFORE_REGEX.has(lastWord))) {
      const start = i;
      let inClass = false;
      for (i += 1; i < source.length; i += 1) {
        if (source[i] === '\\') i += 1;
        else if (source[i] === '[') inClass = true;
        else if (source[i] === ']') inClass = false;
        else if (source[i] === '/' && !inClass) break;
      }
      for (i += 1; /[a-z]/i.test(source[i] ?? ''); i += 1);  // its flags
      out += source.slice(start, i);
      [last, lastWord] = ['/', ''];
    } else if (c === '{') {
      braces.push(false);
      out += c;
      i += 1;
      [last, lastWord] = [c, ''];
    } else if (c === '}' && braces.pop()) {
      out += c;
      i += 1;
      copyTemplate();  // back in the template literal
      [last, lastWord] = ['`', ''];
    } else if (/[A-Za-z_$0-9]/.test(c)) {
      const start = i;
      while (i < source.length && /[A-Za-z_$0-9]/.test(source[i])) i += 1;
      lastWord = source.slice(start, i);
      last = 'a';
      out += lastWord;
    } else {
      out += c;
      i += 1;
      if (!/\s/.test(c)) [last, lastWord] = [c, ''];
    }
  }
  // Lines a comment leaves empty stay: folding them could change a template literal's own blank lines.
  return out;
}
