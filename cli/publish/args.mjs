// The arguments of `conecurl publish`: parsed into one options object, each bad one refused in a line
// that says what to write instead (exit code 2). The help text lives here, beside what it describes.
import os from 'node:os';
import path from 'node:path';
import { usageError } from './errors.mjs';

export const FORMATS = { webp: 'webp', avif: 'avif', jpeg: 'jpg' };  // --format -> file extension
export const DEFAULTS = { format: 'webp', quality: 80, height: 1600, zoom: 2, thumbWidth: 240, coverWidth: 1200 };

export const HELP = `Usage: conecurl publish <book.pdf> --out <folder> [options]

Turns a PDF into a static site: index.html, the reader, and book/ (page images, text, book.json).

Options:
  --out <folder>      where to write the site (new, empty, or one conecurl published before)
  --title <text>      the book's title (default: the PDF's Title, else the file name)
  --password <text>   the PDF's password, if it is encrypted
  --pages <list>      which pages to publish, e.g. 1-40 or 3,5,10-12 (default: all)
  --format <f>        webp, avif or jpeg (default: ${DEFAULTS.format})
  --quality <1-100>   image quality (default: ${DEFAULTS.quality})
  --height <px>       reading image height in pixels (default: ${DEFAULTS.height})
  --scale <s>         or: reading image size as a multiple of the PDF's size (1 = 72 px per inch)
  --zoom <factor>     zoom image size relative to the reading one; 0 = no zoom images (default: ${DEFAULTS.zoom})
  --jobs <n>          pages rendered at once, one worker thread each (default: one per core)
  --url <https://...> where the site will live: makes the link-preview image and URL absolute
  --no-download       leave the PDF out of the site (by default readers can download it)
  --narration <dir>   recorded narration: page-N.mp3 (.m4a .ogg .opus .wav) with page-N.vtt or
                      page-N.json (word times) for PDF page N; checked, copied, and played by Read aloud
  --debug             show stack traces
  --help              this text
`;

/** Page numbers (from 1) of a list like "1-40" or "3,5,10-12"; a usage error names the bad part. */
export function parsePageList(text) {
  const pages = new Set();
  for (const part of String(text).split(',')) {
    const match = /^\s*(\d+)\s*(?:-\s*(\d+)\s*)?$/.exec(part);
    const first = match && Number(match[1]);
    const last = match && (match[2] === undefined ? first : Number(match[2]));
    if (!match || first < 1 || last < first) {
      throw usageError(`--pages "${text}": "${part.trim()}" is not a page or a range like 3 or 10-12 (pages count from 1)`);
    }
    for (let page = first; page <= last; page++) pages.add(page);
  }
  return [...pages].sort((a, b) => a - b);
}

const number = (name, value, { min, max = Infinity, integer = false }) => {
  const n = Number(value);
  if (value === undefined || value === '' || !Number.isFinite(n) || n < min || n > max || (integer && !Number.isInteger(n))) {
    const range = max === Infinity ? `from ${min}` : `from ${min} to ${max}`;
    throw usageError(`${name} needs ${integer ? 'a whole number' : 'a number'} ${range}, got ${value === undefined ? 'nothing' : `"${value}"`}`);
  }
  return n;
};

/** The options of `conecurl publish` from its arguments (after the word `publish`). */
export function parsePublishArgs(argv) {
  const options = {
    input: null, out: null, title: null, password: undefined, pages: null, format: DEFAULTS.format,
    quality: DEFAULTS.quality, height: DEFAULTS.height, scale: null, zoom: DEFAULTS.zoom,
    jobs: os.availableParallelism(), url: null, download: true, narration: null, debug: false, help: false,
  };
  for (let i = 0; i < argv.length; i++) {
    const arg = argv[i];
    const [name, inline] = arg.startsWith('--') && arg.includes('=') ? [arg.slice(0, arg.indexOf('=')), arg.slice(arg.indexOf('=') + 1)] : [arg, undefined];
    const value = () => {
      if (inline !== undefined) return inline;
      if (i + 1 >= argv.length) throw usageError(`${name} needs a value (see conecurl publish --help)`);
      return argv[++i];
    };
    switch (name) {
      case '--help': case '-h': options.help = true; break;
      case '--debug': options.debug = true; break;
      case '--no-download': options.download = false; break;
      case '--out': case '-o': options.out = value(); break;
      case '--title': options.title = value(); break;
      case '--password': options.password = value(); break;
      case '--narration': options.narration = value(); break;
      case '--pages': options.pages = parsePageList(value()); break;
      case '--format': {
        const format = value();
        if (!(format in FORMATS)) throw usageError(`--format "${format}" is not one of ${Object.keys(FORMATS).join(', ')}`);
        options.format = format;
        break;
      }
      case '--quality': options.quality = number(name, value(), { min: 1, max: 100, integer: true }); break;
      case '--height': options.height = number(name, value(), { min: 16, max: 16384, integer: true }); options.scale = null; break;
      case '--scale': options.scale = number(name, value(), { min: 0.05, max: 20 }); break;
      case '--zoom': {
        const zoom = number(name, value(), { min: 0, max: 8 });
        if (zoom !== 0 && zoom <= 1) throw usageError(`--zoom ${zoom}: the zoom image must be larger than the reading one (above 1), or 0 for none`);
        options.zoom = zoom;
        break;
      }
      case '--jobs': options.jobs = number(name, value(), { min: 1, max: 256, integer: true }); break;
      case '--url': {
        const url = value();
        if (!/^https?:\/\/[^\s]+$/.test(url)) throw usageError(`--url "${url}" is not an http(s) address like https://example.com/book/`);
        options.url = url.endsWith('/') ? url : `${url}/`;
        break;
      }
      default:
        if (arg.startsWith('-')) throw usageError(`unknown option ${name} (see conecurl publish --help)`);
        if (options.input !== null) throw usageError(`one PDF at a time: got "${options.input}" and "${arg}"`);
        options.input = arg;
    }
  }
  if (options.help) return options;
  if (options.input === null) throw usageError('which PDF? Usage: conecurl publish <book.pdf> --out <folder>');
  if (options.out === null) throw usageError(`where to? Add --out <folder>, e.g. conecurl publish ${options.input} --out site`);
  options.input = path.resolve(options.input);
  options.out = path.resolve(options.out);
  if (options.narration !== null) options.narration = path.resolve(options.narration);
  return options;
}
