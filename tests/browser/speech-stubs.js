// Where the speech tests' shared init scripts lie (page.addInitScript({ path })): init scripts are sent
// to the page as source, so they are files, not imported functions.
import path from 'node:path';
import { fileURLToPath } from 'node:url';

/** Utterances that take any voice object (fixtures/utterance-stub.js). */
export const UTTERANCE_STUB = path.join(path.dirname(fileURLToPath(import.meta.url)), 'fixtures/utterance-stub.js');
