// The cross-engine suite in Firefox (journeys.mjs): `node --test tests/engines/firefox.test.mjs` runs it alone.
import { engineSuite } from './journeys.mjs';

engineSuite('firefox');
