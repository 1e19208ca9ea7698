// Node: the package's hand-written typings (.d.ts) say what the runtime tables say, one fact from one
// source: the options (options.js), the events and their detail fields (book-events.js), the element's
// attributes and properties (element-attributes.js), the framework components' props and events
// (framework-props.js, vue.js). The .d.ts files are read by the TypeScript compiler itself (the
// `typescript` devDependency, v7: its sync API runs the native compiler and answers the checker's
// questions), so inherited, Omit-ted and Partial members count as a user's editor sees them.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { API, SignatureKind, SymbolFlags } from 'typescript/unstable/sync';
import { BOOK_EVENTS, EVENT_DETAILS } from '../../web/src/book/book-events.js';
import { CREATE_OPTIONS, DEFAULTS, LIVE_OPTIONS } from '../../web/src/book/options.js';
import { ATTRIBUTES, NO_ATTRIBUTE, PROPERTY_OPTIONS, propertyOf } from '../../web/src/components/element-attributes.js';
import { EVENT_HANDLERS, OPTION_PROPS, PAGE_PROPS } from '../../web/src/components/framework-props.js';
import { LABEL_KEYS } from '../../web/src/viewer/viewer-labels.js';
import { CONTROL_PARTS } from '../../web/src/viewer/viewer-options.js';
import * as viewerEntry from '../../web/src/viewer.js';

const root = fileURLToPath(new URL('../../', import.meta.url));
const src = join(root, 'web/src');
const ENTRY_TYPES = ['index.d.ts', 'element.d.ts', 'react.d.ts', 'vue.d.ts', 'engine.d.ts', 'viewer.d.ts'].map((file) => join(src, file));

let api;
let checker;
let project;
let scratch;

before(() => {
  // A project of the entries' typings alone, strict, as a consumer's compiler reads them.
  scratch = mkdtempSync(join(tmpdir(), 'conecurl-typings-'));
  writeFileSync(join(scratch, 'tsconfig.json'), JSON.stringify({
    compilerOptions: {
      target: 'ES2022', module: 'ESNext', moduleResolution: 'bundler', lib: ['ES2022', 'DOM', 'DOM.Iterable'],
      strict: true, noEmit: true, types: [],
    },
    files: ENTRY_TYPES,
  }));
  api = new API({ cwd: scratch });
  project = api.updateSnapshot({ openProject: join(scratch, 'tsconfig.json') }).getProjects()[0];
  checker = project.checker;
  const problems = project.program.getSyntacticDiagnostics().concat(project.program.getSemanticDiagnostics());
  assert.deepEqual(problems.map((d) => `${d.fileName ?? ''}: ${typeof d.text === 'string' ? d.text : JSON.stringify(d.text)}`), [],
    'the typings compile');
});

after(() => {
  api?.close();
  if (scratch) rmSync(scratch, { recursive: true, force: true });
});

/** The symbol `name` exported by web/src/`file`. */
function exported(file, name) {
  const sourceFile = project.program.getSourceFile(join(src, file));
  assert.ok(sourceFile, `${file} is in the program`);
  const symbol = checker.getExportsOfModule(checker.getSymbolAtLocation(sourceFile)).find((s) => s.name === name);
  assert.ok(symbol, `${file} exports ${name}`);
  return symbol;
}
/** The type an exported interface, class (its instances) or type alias declares. */
const declared = (file, name) => checker.getDeclaredTypeOfSymbol(exported(file, name));
const properties = (type) => checker.getPropertiesOfType(type);
const names = (type) => properties(type).map((s) => s.name).sort();
const optional = (symbol) => (symbol.flags & SymbolFlags.Optional) !== 0;
const typeOfMember = (type, name) => checker.getTypeOfSymbol(checker.getPropertyOfType(type, name));
const sorted = (list) => [...new Set(list)].sort();
/** A detail's fields as EVENT_DETAILS writes them: 'name', or 'name?' when optional. */
const fields = (type) => properties(type).map((s) => (optional(s) ? `${s.name}?` : s.name)).sort();
const detailOf = (eventType) => checker.getTypeOfSymbol(checker.getPropertyOfType(eventType, 'detail'));
/** Members of `type` declared in web/src/`file` (an element also has every HTMLElement member). */
const declaredIn = (type, file) => properties(type).filter((s) => s.declarations.some((d) => d.path.endsWith(`/web/src/${file}`)));

test('node: FlipbookOptions (flipbook.d.ts) has exactly the options Flipbook.create takes (options.js CREATE_OPTIONS)', () => {
  assert.deepEqual(names(declared('book/flipbook.d.ts', 'FlipbookOptions')), sorted(CREATE_OPTIONS));
});

test('node: book.options is typed with a value for exactly the options that always have one (DEFAULTS, pages, turnArea, edgeMarks); setOptions takes LIVE_OPTIONS', () => {
  const controller = declared('book/flipbook.d.ts', 'BookController');
  const always = properties(typeOfMember(controller, 'options')).filter((s) => !optional(s)).map((s) => s.name);
  assert.deepEqual(sorted(always), sorted([...Object.keys(DEFAULTS), 'pages', 'turnArea', 'edgeMarks']));
  const [setOptions] = checker.getSignaturesOfType(typeOfMember(controller, 'setOptions'), SignatureKind.Call);
  assert.deepEqual(names(checker.getParameterType(setOptions, 0)), sorted(LIVE_OPTIONS));
});

test('node: FlipbookEventMap names every book event (BOOK_EVENTS) with the detail fields book-events.js lists, turnstart\'s riffle too', () => {
  const events = declared('book/flipbook.d.ts', 'FlipbookEventMap');
  assert.deepEqual(names(events), sorted(BOOK_EVENTS));
  for (const type of BOOK_EVENTS) {
    assert.deepEqual(fields(detailOf(typeOfMember(events, type))), sorted(EVENT_DETAILS[type]), `${type}'s detail`);
  }
  // The element's map passes the same events on, error widened to the element's own failures.
  const elementEvents = declared('element.d.ts', 'ConeFlipbookEventMap');
  for (const type of BOOK_EVENTS) {
    assert.deepEqual(fields(detailOf(typeOfMember(elementEvents, type))), sorted(EVENT_DETAILS[type]), `<cone-flipbook> ${type}'s detail`);
  }
});

test('node: flip()\'s documentation says how it turns: leaf by leaf up to NEAR_LEAVES leaves away, a riffle farther', () => {
  const controller = declared('book/flipbook.d.ts', 'BookController');
  const doc = checker.getPropertyOfType(controller, 'flip').getDocumentationComment(checker);
  const book = join(src, 'book');
  const near = readdirSync(book).map((file) => /const NEAR_LEAVES = (\d+)/.exec(readFileSync(join(book, file), 'utf8'))?.[1]).find(Boolean);
  assert.ok(near, 'NEAR_LEAVES is defined under web/src/book');
  const word = ['zero', 'one', 'two', 'three', 'four', 'five'][Number(near)] ?? near;
  assert.match(doc, /leaf by leaf/);
  assert.match(doc, new RegExp(`more than\\s+(${word}|${near})\\s+leaves`));
  assert.match(doc, /riffle/);
});

test('node: every option is an attribute of <cone-flipbook> or says why not, and element.d.ts types each option property as the option is', () => {
  const withAttribute = Object.values(ATTRIBUTES).map(([option]) => option);
  const missing = CREATE_OPTIONS.filter((option) => !withAttribute.includes(option) && !(option in NO_ATTRIBUTE));
  assert.deepEqual(missing, [], 'options without an attribute or a reason (element-attributes.js NO_ATTRIBUTE)');
  for (const [option, reason] of Object.entries(NO_ATTRIBUTE)) {
    assert.ok(CREATE_OPTIONS.includes(option) && !withAttribute.includes(option), `NO_ATTRIBUTE.${option}`);
    assert.ok(typeof reason === 'string' && reason.length > 20, `NO_ATTRIBUTE.${option} says why`);
  }
  assert.deepEqual(sorted(withAttribute), sorted(PROPERTY_OPTIONS));

  const element = declared('element.d.ts', 'ConeFlipbookElement');
  const own = declaredIn(element, 'element.d.ts').filter((s) => !(s.flags & SymbolFlags.Method)).map((s) => s.name);
  const state = ['book', 'page', 'pageCount'];  // the book's state, read only: not options
  assert.deepEqual(sorted(own.filter((name) => !state.includes(name))), sorted(PROPERTY_OPTIONS.map(propertyOf)));
  // What a property reads back holds every value the option takes (a property keeps what it is given).
  // display reads the display shown ('single' or 'double'), not the option ('auto' too).
  const options = declared('book/flipbook.d.ts', 'FlipbookOptions');
  const wrong = PROPERTY_OPTIONS.filter((option) => option !== 'display'
    && !checker.isTypeAssignableTo(checker.getNonNullableType(typeOfMember(options, option)), typeOfMember(element, propertyOf(option))))
    .map((option) => `${option}: the option is ${checker.typeToString(typeOfMember(options, option))}, the property ${checker.typeToString(typeOfMember(element, propertyOf(option)))}`);
  assert.deepEqual(wrong, []);
  // The class's documentation names every attribute.
  const doc = exported('element.d.ts', 'ConeFlipbookElement').getDocumentationComment(checker);
  assert.deepEqual(Object.keys(ATTRIBUTES).filter((name) => !new RegExp(`(^|[\\s(,])${name}([\\s),.]|$)`).test(doc)), [],
    'attributes the ConeFlipbookElement documentation does not name');
});

test('node: the components\' props and events (framework-props.d.ts, react.d.ts, vue.d.ts) are framework-props.js\'s and vue.js\'s', async () => {
  assert.deepEqual(names(declared('components/framework-props.d.ts', 'FlipbookOptionProps')), sorted(OPTION_PROPS));
  const handlers = Object.values(EVENT_HANDLERS);
  assert.deepEqual(names(declared('react.d.ts', 'FlipbookEventProps')), sorted(handlers));
  // react.js reads these by name beside the options, handlers and page props.
  const reactOwn = ['onPageChange', 'children', 'id', 'className', 'style'];
  assert.deepEqual(names(declared('react.d.ts', 'FlipbookProps')), sorted([...OPTION_PROPS, ...handlers, ...PAGE_PROPS, ...reactOwn]));

  const { Flipbook } = await import('../../web/src/vue.js');
  assert.deepEqual(sorted(Flipbook.props), sorted([...OPTION_PROPS, ...PAGE_PROPS]));
  assert.deepEqual(names(declared('vue.d.ts', 'FlipbookProps')), sorted(Flipbook.props));
  assert.deepEqual(sorted(Flipbook.emits), sorted([...BOOK_EVENTS, 'update:page']));
  assert.deepEqual(names(declared('vue.d.ts', 'FlipbookEmits')), sorted(Flipbook.emits));
});

test('node: loadEngine\'s documentation names only classes the Embind bindings define', () => {
  const bindings = readdirSync(join(root, 'cpp/bindings')).map((file) => readFileSync(join(root, 'cpp/bindings', file), 'utf8')).join('\n');
  const defined = [...bindings.matchAll(/class_<\w+>\("(\w+)"\)/g)].map((m) => m[1]);
  assert.ok(defined.includes('Book'), 'the bindings define Book');
  const doc = /\/\*\*((?:(?!\*\/)[\s\S])*)\*\/\s*export function loadEngine/.exec(readFileSync(join(src, 'engine/load-engine.js'), 'utf8'))[1];
  const named = [...doc.replace(/^.*@param.*$/m, '').matchAll(/\b([A-Z][a-z]+[A-Z]\w*|Book)\b/g)].map((m) => m[1])
    .filter((name) => name !== 'ConeCurlEngine');  // the module's type in load-engine.d.ts
  assert.ok(named.length > 0);
  assert.deepEqual(named.filter((name) => !defined.includes(name)), []);
});

test('node: the viewer\'s typings hold its tables: ControlParts has the toolbar\'s parts (CONTROL_PARTS), ViewerLabels the label keys, and viewer.d.ts types what viewer.js exports', () => {
  assert.deepEqual(names(declared('book/flipbook.d.ts', 'ControlParts')), sorted(CONTROL_PARTS));
  assert.deepEqual(names(declared('book/flipbook.d.ts', 'ViewerLabels')), sorted(LABEL_KEYS));
  for (const name of Object.keys(viewerEntry)) exported('viewer.d.ts', name);
  const controls = declared('viewer.d.ts', 'Controls');
  assert.deepEqual(names(controls), ['element', 'panels', 'remove', 'toolbar']);
  assert.deepEqual(names(declared('viewer.d.ts', 'AttachControlsOptions')), ['controls', 'labels', 'pdf']);
});
