// Cross-engine journeys of read-aloud on the engine's own voices.

/** Defines the read-aloud journeys on engineSuite's context: { engine, url, open, evaluate, journey, heard, browser }. */
export function readAloudJourneys(context) {
}
