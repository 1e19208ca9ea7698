// The cross-engine suite in Webkit (journeys.mjs): `node --test tests/engines/webkit.test.mjs` runs it alone.
import { engineSuite } from './journeys.mjs';

engineSuite('webkit');
