// Browser: the read-aloud voice choice and memory of issue 37 (engine/voice-choice.js, the keepChoice hook
// of read-aloud/book-reader.js, viewer/read-aloud-menu.js) on a real Flipbook over a speechSynthesis the
// test plays: what a reader chose survives a reload per language, where it is kept, 13,362 voices, the order.
import { test, expect } from '@playwright/test';
import { UTTERANCE_STUB } from './speech-stubs.js';
import { PDFDocument, StandardFonts } from 'pdf-lib';
import { openReady } from './helpers.js';

const HTML_FIXTURE = '/tests/browser/fixtures/html-fixture.html';
const MEMORY_KEY = 'conecurl-read-aloud';

// The voices of most tests, as getVoices() lists them (the browser's order, not read-aloud's).
const VOICES = [
  { name: 'Amélie', lang: 'fr-FR', localService: true },
  { name: 'Alex', lang: 'en-US', localService: true, default: true },
  { name: 'Daniel', lang: 'en-GB', localService: true },
  { name: 'Thomas', lang: 'fr-CA', localService: false },
  { name: 'Hans', lang: 'de-DE', localService: true },
];

/**
 * Run in the page before its scripts: a speechSynthesis listing `voices` (or, with `espeak`, that many
 * voices named as Firefox lists espeak-ng's through speech-dispatcher, the first the default, before `voices`), which says each
 * utterance in tasks of its own (start, then end) unless window.holdSpeech is true (then it starts and
 * waits for window.releaseSpeech()). What it was given: window.said, [{ text, voice, rate, lang }].
 * Utterances are a class of the test's: Chromium's own takes no voice but its own. `<option>`s made
 * through document.createElement are counted in window.optionsMade.
 */
function playedSpeech({ voices, espeak = 0 }) {
  const given = voices.map((v) => ({ default: false, localService: true, voiceURI: v.name, ...v }));
  const list = [];
  if (espeak > 0) {
    const languages = [
      ['en-US', 'English (America)'], ['en-GB', 'English (Great Britain)'], ['fr-FR', 'French (France)'],
      ['de-DE', 'German'], ['es-ES', 'Spanish (Spain)'], ['it-IT', 'Italian'], ['pt-BR', 'Portuguese (Brazil)'],
      ['nl-NL', 'Dutch'], ['sv-SE', 'Swedish'], ['pl-PL', 'Polish'], ['ru-RU', 'Russian'], ['fi-FI', 'Finnish'],
      ['cs-CZ', 'Czech'], ['el-GR', 'Greek'], ['hu-HU', 'Hungarian'], ['tr-TR', 'Turkish'], ['ja-JP', 'Japanese'],
      ['ko-KR', 'Korean'], ['zh-CN', 'Chinese (Mandarin)'], ['hi-IN', 'Hindi'], ['ar-SA', 'Arabic'], ['da-DK', 'Danish'],
      ['nb-NO', 'Norwegian Bokmål'], ['ro-RO', 'Romanian'], ['sk-SK', 'Slovak'], ['uk-UA', 'Ukrainian'], ['vi-VN', 'Vietnamese'],
      ['id-ID', 'Indonesian'], ['ca-ES', 'Catalan'], ['eu-ES', 'Basque'], ['bg-BG', 'Bulgarian'], ['hr-HR', 'Croatian'],
      ['et-EE', 'Estonian'], ['lv-LV', 'Latvian'], ['lt-LT', 'Lithuanian'], ['sl-SI', 'Slovenian'], ['sr-RS', 'Serbian'],
      ['he-IL', 'Hebrew'], ['fa-IR', 'Persian'], ['ta-IN', 'Tamil'], ['te-IN', 'Telugu'], ['bn-BD', 'Bengali'],
      ['ur-PK', 'Urdu'], ['sw-KE', 'Swahili'], ['af-ZA', 'Afrikaans'], ['is-IS', 'Icelandic'], ['ga-IE', 'Irish'],
      ['cy-GB', 'Welsh'], ['ka-GE', 'Georgian'], ['hy-AM', 'Armenian'], ['kk-KZ', 'Kazakh'], ['ms-MY', 'Malay'],
      ['mk-MK', 'Macedonian'], ['sq-AL', 'Albanian'], ['eo', 'Esperanto'], ['la', 'Latin'], ['mt-MT', 'Maltese'],
      ['ne-NP', 'Nepali'], ['pa-IN', 'Punjabi'], ['si-LK', 'Sinhala'], ['am-ET', 'Amharic'],
    ];
    const variants = ['Max', 'Annie', 'Andy', 'Alex', 'Diogo', 'Edward', 'f1', 'f2', 'f3', 'f4', 'f5', 'm1', 'm2', 'm3',
      'm4', 'm5', 'm6', 'm7', 'klatt', 'klatt2', 'klatt3', 'whisper', 'croak', 'Gene', 'Henrique', 'Hugo', 'Jacky', 'Lee',
      'Marco', 'shelby', 'Nguyen', 'Reed', 'RicishayMax', 'Steph', 'Storm', 'Tweaky', 'UniRobot', 'Zac', 'anika',
      'aunty', 'belinda', 'boris', 'caleb', 'david', 'edward2', 'emily', 'fast', 'grandma', 'grandpa', 'iven', 'iven2'];
    for (let i = 0; list.length < espeak; i++) {
      const [lang, language] = languages[i % languages.length];
      const variant = variants[Math.floor(i / languages.length) % variants.length];
      const round = Math.floor(i / (languages.length * variants.length));
      const name = `${language}+${variant}${round ? `-${round + 1}` : ''}`;
      list.push({ name, lang, default: i === 0, localService: true, voiceURI: `urn:moz-tts:speechd:${encodeURIComponent(name)}?${lang}` });
    }
  }
  list.push(...given);
  window.said = [];
  window.holdSpeech = false;
  let held = [];
  window.releaseSpeech = () => {
    window.holdSpeech = false;
    const now = held;
    held = [];
    for (const end of now) end();
  };
  const synth = new EventTarget();
  Object.assign(synth, {
    getVoices: () => list,
    speak(utterance) {
      window.said.push({ text: utterance.text.trim(), voice: utterance.voice?.name ?? null, rate: utterance.rate, lang: utterance.lang });
      setTimeout(() => {
        utterance.dispatchEvent(new Event('start'));
        const end = () => setTimeout(() => utterance.dispatchEvent(new Event('end')));
        if (window.holdSpeech) held.push(end); else end();
      });
    },
    cancel() { held = []; },
    pause() {},
    resume() {},
  });
  Object.defineProperty(window, 'speechSynthesis', { value: synth, configurable: true });
  window.optionsMade = 0;
  const create = Document.prototype.createElement;
  Document.prototype.createElement = function (name, ...rest) {
    if (String(name).toLowerCase() === 'option') window.optionsMade += 1;
    return create.call(this, name, ...rest);
  };
}

/**
 * Opens the HTML fixture (speech as playedSpeech(`speech`)) and a book of two text pages with the
 * toolbar, in a container of lang `lang` (null: the page's, en); `options` merged in. Returns the
 * page's errors, as they come.
 */
async function openTextBook(page, { lang = null, options = {}, speech = { voices: VOICES } } = {}) {
  await page.addInitScript({ path: UTTERANCE_STUB });
  await page.addInitScript(playedSpeech, speech);
  const problems = await openReady(page, HTML_FIXTURE);
  await makeBook(page, { lang, options });
  return problems;
}

/** A new book in the page (the one before destroyed), its readaloudend details in window.ends. */
async function makeBook(page, { lang = null, options = {} } = {}) {
  await page.evaluate(async ({ lang, options }) => {
    window.book?.destroy();
    if (lang) window.container.lang = lang; else window.container.removeAttribute('lang');
    const texts = lang?.startsWith('fr') ? ['Le chat dort.', 'Il fait beau.'] : ['The cat sat.', 'It was warm.'];
    window.book = await window.Flipbook.create(window.container, {
      pages: texts.map((t) => window.makeTextPage(t)), display: 'double', duration: 200, controls: true, ...options,
    });
    await window.book.whenIdle();
    window.ends = [];
    window.book.addEventListener('readaloudend', (e) => window.ends.push({ ...e.detail, error: e.detail.error?.message }));
  }, { lang, options });
}

/** readAloud(`options`) from the first page to its end; what was said meanwhile ([{ text, voice, rate, lang }]) and how it ended. */
const readToEnd = (page, options) => page.evaluate(async (options) => {
  await window.book.flip(0, { animate: false });
  const from = window.said.length;
  const reading = await window.book.readAloud(options);
  const end = await reading.finished;
  return { said: window.said.slice(from), reason: end.reason };
}, options);

const stored = (page, key = MEMORY_KEY) => page.evaluate((key) => JSON.parse(localStorage.getItem(key) ?? 'null'), key);

/** Opens the toolbar's Voice and speed popup; its locator. */
async function openPopup(page) {
  const button = page.getByRole('toolbar').getByRole('button', { name: 'Voice and speed' });
  await expect(button).toBeVisible();
  await button.click();
  const popup = page.getByRole('dialog', { name: 'Voice and speed' });
  await expect(popup).toBeVisible();
  return popup;
}

test('browser: a voice and speed chosen in the Voice and speed popup survive a reload, per language: the English book reads with them again, a French book is not given them', async ({ page }) => {
  let problems = await openTextBook(page);
  let popup = await openPopup(page);
  await expect(popup.getByLabel('Voice')).toHaveValue('');
  await expect(popup.getByLabel('Speed')).toHaveValue('1');
  await popup.getByLabel('Voice').selectOption('Daniel');
  await popup.getByLabel('Speed').selectOption('1.5');
  expect(await stored(page)).toEqual({ en: { voice: 'Daniel', rate: 1.5 } });
  await page.keyboard.press('Escape');
  await expect(popup).toBeHidden();
  expect(problems).toEqual([]);

  // A French book in the same origin after a reload: its own default voice and speed, the English kept.
  await page.reload();
  await page.waitForFunction(() => document.body.dataset.ready);
  await makeBook(page, { lang: 'fr' });
  popup = await openPopup(page);
  await expect(popup.getByLabel('Voice')).toHaveValue('');
  await expect(popup.getByLabel('Speed')).toHaveValue('1');
  await page.keyboard.press('Escape');
  let { said, reason } = await readToEnd(page);
  expect(reason).toBe('finished');
  expect(said.map(({ text, voice, rate }) => [text, voice, rate])).toEqual([['Le chat dort.', 'Amélie', 1], ['Il fait beau.', 'Amélie', 1]]);
  expect((await stored(page)).en).toEqual({ voice: 'Daniel', rate: 1.5 });

  // The English book after another reload: readAloud() and the popup start from Daniel at 1.5.
  await page.reload();
  await page.waitForFunction(() => document.body.dataset.ready);
  await makeBook(page);
  ({ said, reason } = await readToEnd(page));
  expect(reason).toBe('finished');
  expect(said.map(({ text, voice, rate }) => [text, voice, rate])).toEqual([['The cat sat.', 'Daniel', 1.5], ['It was warm.', 'Daniel', 1.5]]);
  popup = await openPopup(page);
  await expect(popup.getByLabel('Voice')).toHaveValue('Daniel');
  await expect(popup.getByLabel('Speed')).toHaveValue('1.5');
  await page.keyboard.press('Escape');
  // The toolbar's Read aloud reads with them too.
  const from = await page.evaluate(async () => { await window.book.flip(0, { animate: false }); return window.said.length; });
  await page.getByRole('toolbar').locator('[data-control=readAloud]').click();
  await page.waitForFunction(() => window.ends.length === 2);
  expect(await page.evaluate((from) => window.said.slice(from).map(({ voice, rate }) => [voice, rate]), from)).toEqual([['Daniel', 1.5], ['Daniel', 1.5]]);
});

test('browser: readAloudMemory: a key of its own keeps the voice and speed under that key, false keeps and reads nothing, and a localStorage that throws still lets the book read', async ({ page }) => {
  const problems = await openTextBook(page, { options: { readAloudMemory: 'my-book-voices' } });
  await readToEnd(page, { voice: 'Daniel', rate: 2 });
  expect(await stored(page, 'my-book-voices')).toEqual({ en: { voice: 'Daniel', rate: 2 } });
  expect(await stored(page)).toBeNull();
  // Chosen in the popup: under that key too.
  const popup = await openPopup(page);
  await expect(popup.getByLabel('Voice')).toHaveValue('Daniel');
  await popup.getByLabel('Speed').selectOption('0.75');
  await page.keyboard.press('Escape');
  expect(await stored(page, 'my-book-voices')).toEqual({ en: { voice: 'Daniel', rate: 0.75 } });
  expect(await page.evaluate(() => Object.keys(localStorage))).toEqual(['my-book-voices']);

  // false: nothing kept, and what another book kept is not read.
  await page.evaluate((key) => { localStorage.clear(); localStorage.setItem(key, JSON.stringify({ en: { voice: 'Daniel', rate: 1.5 } })); }, MEMORY_KEY);
  await makeBook(page, { options: { readAloudMemory: false } });
  let { said } = await readToEnd(page);
  expect(said.map(({ voice, rate }) => [voice, rate])).toEqual([['Alex', 1], ['Alex', 1]]);
  await readToEnd(page, { voice: 'Hans', rate: 0.5 });
  const off = await openPopup(page);
  await expect(off.getByLabel('Voice')).toHaveValue('');
  await expect(off.getByLabel('Speed')).toHaveValue('1');
  await off.getByLabel('Voice').selectOption('Thomas');
  await page.keyboard.press('Escape');
  expect(await page.evaluate(() => Object.keys(localStorage))).toEqual([MEMORY_KEY]);
  expect(await stored(page)).toEqual({ en: { voice: 'Daniel', rate: 1.5 } });
  expect(problems).toEqual([]);
});

test('browser: a localStorage whose getItem and setItem throw (private mode, a sandboxed frame) keeps nothing, and the book still reads, with the voice given and then its default one', async ({ page }) => {
  await page.addInitScript(() => {
    const refuse = () => { throw new DOMException('The operation is insecure.', 'SecurityError'); };
    Storage.prototype.getItem = refuse;
    Storage.prototype.setItem = refuse;
  });
  const problems = await openTextBook(page);
  let { said, reason } = await readToEnd(page, { voice: 'Daniel', rate: 1.25 });
  expect(reason).toBe('finished');
  expect(said.map(({ voice, rate }) => [voice, rate])).toEqual([['Daniel', 1.25], ['Daniel', 1.25]]);
  ({ said, reason } = await readToEnd(page));
  expect(reason).toBe('finished');
  expect(said.map(({ voice, rate }) => [voice, rate])).toEqual([['Alex', 1], ['Alex', 1]]);
  // The popup opens and a choice there still reaches the reading.
  const popup = await openPopup(page);
  await popup.getByLabel('Voice').selectOption('Hans');
  await popup.getByLabel('Speed').selectOption('2');
  await page.keyboard.press('Escape');
  const from = await page.evaluate(async () => { await window.book.flip(0, { animate: false }); return window.said.length; });
  await page.getByRole('toolbar').locator('[data-control=readAloud]').click();
  await page.waitForFunction(() => window.ends.length === 3);
  expect(await page.evaluate((from) => window.said.slice(from).map(({ voice, rate }) => [voice, rate]), from)).toEqual([['Hans', 2], ['Hans', 2]]);
  expect(await page.evaluate(() => window.ends.map((e) => e.reason))).toEqual(['finished', 'finished', 'finished']);
  expect(problems).toEqual([]);
});

test('browser: with 13,362 voices (eSpeak\'s as Firefox lists them, and a few others) the popup opens on a Language select and one language\'s voices, never thousands of <option>s, and a voice picked there reaches update() and the next readAloud()', async ({ page }) => {
  const speech = { voices: [{ name: 'Samantha', lang: 'en-US' }, { name: 'Daniel', lang: 'en-GB' }, { name: 'Amélie', lang: 'fr-FR' }], espeak: 13_362 - 3 };
  const problems = await openTextBook(page, { speech });
  expect(await page.evaluate(async () => (await window.book.readAloudVoices()).length)).toBe(13_362);
  const before = await page.evaluate(() => window.optionsMade);
  const popup = await openPopup(page);
  const language = popup.getByLabel('Language');
  const voice = popup.getByLabel('Voice');
  await expect(language).toBeVisible();
  await expect(language).toHaveValue('en');
  const counts = () => page.evaluate((before) => ({ made: window.optionsMade - before, inPage: document.querySelectorAll('option').length,
    voices: document.querySelector('select[name=voice]').options.length, languages: document.querySelector('select[name=language]').options.length }), before);
  let now = await counts();
  // English: Samantha, Daniel and eSpeak's 219 of en-US and 219 of en-GB, after Browser's default; with the
  // Language select's 60 (one a language) and Speed's 6, the options in the page.
  expect(now.voices).toBe(1 + 2 + 2 * 219);
  expect(now.made).toBeLessThan(1000);
  expect(now.languages).toBe(60);
  expect(now.inPage).toBe(now.voices + 60 + 6);
  const english = await voice.locator('option').allTextContents();
  expect(english.every((text, at) => at === 0 || /\(en-(US|GB)\)$/.test(text))).toBe(true);
  // readAloudVoices(): eSpeak's (known by their speech-dispatcher voiceURI) last in their region.
  const ordered = await page.evaluate(async () => (await window.book.readAloudVoices()).slice(0, 222).map((v) => v.name));
  expect(ordered.slice(0, 3)).toEqual(['Samantha', 'English (America)+Max', 'English (America)+Annie']);
  expect(ordered[220]).toBe('Daniel');
  // Another language: its voices alone, the English ones gone.
  let from = await page.evaluate(() => window.optionsMade);
  await language.selectOption('de');
  await expect(voice.locator('option')).toHaveCount(1 + 219);
  expect(await voice.locator('option').nth(1).textContent()).toBe('German+Max (de-DE)');
  expect(await page.evaluate((from) => window.optionsMade - from, from)).toBe(1 + 219);
  expect((await counts()).inPage).toBe(1 + 219 + 60 + 6);
  await page.keyboard.press('Escape');

  // While reading (each sentence held until released): a German eSpeak voice picked goes to update().
  await page.evaluate(() => {
    window.holdSpeech = true;
    window.book.readAloud();
  });
  await page.waitForFunction(() => window.said.length === 1);
  expect(await page.evaluate(() => window.said[0].voice)).toBe('Samantha');
  await openPopup(page);
  await expect(language).toHaveValue('de');  // where the reader left it
  await voice.selectOption('German+Annie');
  await page.waitForFunction(() => window.said.length === 2);
  expect(await page.evaluate(() => window.said[1])).toMatchObject({ text: 'The cat sat.', voice: 'German+Annie' });
  await page.keyboard.press('Escape');
  await page.evaluate(() => window.releaseSpeech());
  await page.waitForFunction(() => window.ends.length === 1);
  expect(await stored(page)).toEqual({ en: { voice: 'German+Annie' } });
  // The next readAloud() is given it, and the popup opens on its language.
  const { said } = await readToEnd(page);
  expect(said.map(({ voice }) => voice)).toEqual(['German+Annie', 'German+Annie']);
  from = await page.evaluate(() => window.optionsMade);
  await openPopup(page);
  await expect(language).toHaveValue('de');
  await expect(voice).toHaveValue('German+Annie');
  expect(await page.evaluate((from) => window.optionsMade - from, from)).toBe(60 + 1 + 219);  // languages, one language's voices
  expect(problems).toEqual([]);
});

test('browser: readAloudVoices() comes in the documented order: the book\'s language in the reader\'s region first (navigator.languages), then its main region, no region, the others A to Z; local before network, eSpeak last; other languages after by lang', async ({ page }) => {
  await page.addInitScript(() => {
    Object.defineProperty(Navigator.prototype, 'languages', { get: () => ['en-GB', 'fr-CA'], configurable: true });
    Object.defineProperty(Navigator.prototype, 'language', { get: () => 'en-GB', configurable: true });
  });
  const voices = [
    { name: 'Google US English', lang: 'en-US', localService: false },
    { name: 'Hans', lang: 'de-DE' },
    { name: 'English (Great Britain)+Max', lang: 'en-GB', voiceURI: 'urn:moz-tts:speechd:English%20(Great%20Britain)+Max?en-GB' },
    { name: 'Google UK English Female', lang: 'en-GB', localService: false },
    { name: 'Karen', lang: 'en-AU' },
    { name: 'Amélie', lang: 'fr-FR' },
    { name: 'eSpeak French', lang: 'fr-CA', voiceURI: 'espeak-fr' },
    { name: 'Alex', lang: 'en-US', default: true },
    { name: 'Moira', lang: 'en-IE' },
    { name: 'Thomas', lang: 'fr-CA', localService: false },
    { name: 'English', lang: 'en' },
    { name: 'Daniel', lang: 'en-GB' },
  ];
  const problems = await openTextBook(page, { speech: { voices } });
  const listed = () => page.evaluate(async () => (await window.book.readAloudVoices()).map((v) => `${v.name} ${v.lang}${v.local ? '' : ' network'}`));
  const english = [
    'Daniel en-GB', 'Google UK English Female en-GB network', 'English (Great Britain)+Max en-GB',  // the reader's region
    'Alex en-US', 'Google US English en-US network',  // English's main region
    'English en',                                     // no region
    'Karen en-AU', 'Moira en-IE',                     // the others, A to Z
    'Hans de-DE', 'Thomas fr-CA network', 'eSpeak French fr-CA', 'Amélie fr-FR',  // other languages, by lang
  ];
  expect(await listed()).toEqual(english);
  expect(await page.evaluate(async () => Object.keys((await window.book.readAloudVoices())[0]).sort())).toEqual(['default', 'lang', 'local', 'name', 'voiceURI']);
  // What readAloud() takes with none named: the first, Daniel.
  let { said } = await readToEnd(page);
  expect(said.map(({ voice }) => voice)).toEqual(['Daniel', 'Daniel']);

  // A French book: the reader's fr-CA first (local before network, eSpeak last), then France.
  await makeBook(page, { lang: 'fr' });
  expect(await listed()).toEqual([
    'Thomas fr-CA network', 'eSpeak French fr-CA', 'Amélie fr-FR',
    'Hans de-DE', 'English en', 'Karen en-AU', 'Daniel en-GB', 'Google UK English Female en-GB network', 'English (Great Britain)+Max en-GB',
    'Moira en-IE', 'Alex en-US', 'Google US English en-US network',
  ]);
  // Not eSpeak's where another speaks the language: Thomas.
  ({ said } = await readToEnd(page));
  expect(said.map(({ voice }) => voice)).toEqual(['Thomas', 'Thomas']);
  // The popup lists them so.
  const popup = await openPopup(page);
  expect((await popup.getByLabel('Voice').locator('option').allTextContents()).slice(1, 4)).toEqual(['Thomas (fr-CA)', 'eSpeak French (fr-CA)', 'Amélie (fr-FR)']);
  await page.keyboard.press('Escape');
  expect(problems).toEqual([]);
});

// The popup asks the book the language the reading uses (pageLanguage(): a PDF's /Lang), and
// readAloudVoices()' entries carry their voiceURI, which eSpeak's are known by in Firefox.
test('browser: in a PDF book whose own language (its /Lang, fr-FR) is not the web page\'s (en), the popup lists and keeps the voice and speed by the language the reading uses', async ({ page }) => {
  const pdf = await PDFDocument.create();
  pdf.setLanguage('fr-FR');
  const font = await pdf.embedFont(StandardFonts.Helvetica);
  for (const text of ['Le chat dort.', 'Il fait beau.']) pdf.addPage([300, 400]).drawText(text, { x: 30, y: 340, size: 18, font });
  const base64 = Buffer.from(await pdf.save()).toString('base64');
  await page.addInitScript({ path: UTTERANCE_STUB });
  await page.addInitScript(playedSpeech, { voices: VOICES });
  const problems = await openReady(page, '/tests/browser/fixtures/pdf-fixture.html');
  await page.evaluate(async (base64) => {
    window.book = await window.Flipbook.create(window.container, { pdf: window.bytesFromBase64(base64), display: 'double', duration: 200, controls: true });
    await window.book.whenIdle();
    window.ends = [];
    window.book.addEventListener('readaloudend', (e) => window.ends.push(e.detail));
  }, base64);
  // The PDF's language read (pdf.js metadata): readAloudVoices() puts French first.
  await page.waitForFunction(async () => (await window.book.readAloudVoices())[0].lang.startsWith('fr'));
  const voices = await page.evaluate(async () => (await window.book.readAloudVoices()).map((v) => `${v.name} (${v.lang})`));
  expect(voices.slice(0, 2)).toEqual(['Amélie (fr-FR)', 'Thomas (fr-CA)']);
  const popup = await openPopup(page);
  expect((await popup.getByLabel('Voice').locator('option').allTextContents()).slice(1)).toEqual(voices);
  await popup.getByLabel('Voice').selectOption('Thomas');
  await popup.getByLabel('Speed').selectOption('1.5');
  await page.keyboard.press('Escape');
  expect(await stored(page)).toEqual({ fr: { voice: 'Thomas', rate: 1.5 } });
  const { said, reason } = await readToEnd(page);
  expect(reason).toBe('finished');
  expect(said.length).toBeGreaterThan(0);
  expect(said.every(({ voice, rate }) => voice === 'Thomas' && rate === 1.5)).toBe(true);
  expect(said.map(({ text }) => text).join(' ')).toContain('Le chat dort.');
  expect(problems).toEqual([]);
});

test('browser: the popup lists the voices in readAloudVoices()\' order, eSpeak\'s known by their speech-dispatcher voiceURI last in their region', async ({ page }) => {
  const voices = [{ name: 'English (Great Britain)+Max', lang: 'en-GB', voiceURI: 'urn:moz-tts:speechd:English%20(Great%20Britain)%2BMax?en-GB' },
    { name: 'Google UK English Female', lang: 'en-GB', localService: false }, { name: 'Daniel', lang: 'en-GB' }, { name: 'Alex', lang: 'en-US', default: true }];
  const problems = await openTextBook(page, { speech: { voices } });
  const listed = await page.evaluate(async () => (await window.book.readAloudVoices()).map((v) => `${v.name} (${v.lang})`));
  expect(listed).toEqual(['Alex (en-US)', 'Daniel (en-GB)', 'Google UK English Female (en-GB)', 'English (Great Britain)+Max (en-GB)']);
  const popup = await openPopup(page);
  expect((await popup.getByLabel('Voice').locator('option').allTextContents()).slice(1)).toEqual(listed);
  expect(problems).toEqual([]);
});
