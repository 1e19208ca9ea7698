// Put first into every page the cross-engine suite opens (its server adds it to each <head>): what the
// page throws, rejects or logs as an error, kept on window.__heard, since WebKit's driver hears no console.
(() => {
  const heard = (window.__heard = []);
  const say = (kind, what) => heard.push(`${kind}: ${what instanceof Error ? `${what.name}: ${what.message}` : String(what)}`);
  window.addEventListener('error', (event) => { if (event instanceof ErrorEvent) say('error', event.error || event.message); });
  window.addEventListener('unhandledrejection', (event) => say('unhandled rejection', event.reason && (event.reason.message || event.reason)));
  const consoleError = console.error;
  console.error = (...args) => { say('console.error', args.map(String).join(' ')); consoleError.apply(console, args); };
})();
