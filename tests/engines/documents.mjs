// Cross-engine journeys with documents: live HTML pages, the PDF viewer (toolbar, search with marks on
// the page, selectable text) and a site made by `conecurl publish` (opens, searches, turns).

/** Defines the document journeys on engineSuite's context: { engine, url, open, evaluate, journey, heard, browser }. */
export function documentJourneys(context) {
}
