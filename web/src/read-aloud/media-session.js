// A reading aloud as the system's media controls see it (navigator.mediaSession): lock screens,
// headphones and media keys show the book and pause, resume, stop and turn it while it reads.
// Started by book-reader.js for each reading and ended with it; where the API is missing it does nothing.

// What the reading's controls do (their names are the Media Session's actions).
const ACTIONS = ['play', 'pause', 'stop', 'nexttrack', 'previoustrack', 'seekto'];

/**
 * Shows `reading` in the Media Session while it lasts: the book's `title` and cover as metadata (the
 * cover's URL, or a promise of one, `cover()`; null for none), play, pause, stop, next and previous page
 * (`turn(direction)` turns and reads on), the playback state, and for recorded narration the audio's
 * position and seekto. Returns end(): the handlers cleared, metadata and position reset.
 * @param {import('./reading.js').Reading} reading
 * @param {{ title: string, cover: () => string|null|Promise<string|null>,
 *   turn: (direction: 'forward'|'backward') => void, on: (type: string, listener: () => void) => () => void }} book
 */
export function showInMediaSession(reading, { title, cover, turn, on }) {
  const session = globalThis.navigator?.mediaSession;
  if (!session) return () => {};
  let ended = false;
  let seeking = false;  // the seekto handler is set (while narration plays)
  const handle = (action, handler) => {
    try {
      session.setActionHandler(action, handler);
    } catch {
      // a browser without this action (older Safari has no 'stop', some no 'seekto')
    }
  };
  const metadata = (artwork) => {
    if (ended || typeof MediaMetadata !== 'function') return;
    session.metadata = new MediaMetadata({ title, artwork: artwork ? [{ src: artwork }] : [] });
  };
  const state = (value) => { session.playbackState = value; };
  const position = (details) => {
    try {
      session.setPositionState?.(details);  // nothing: the position cleared
    } catch {
      // a duration the browser refuses (not yet known)
    }
  };
  // Recorded narration: its audio's place, and seeking in it; speech has neither.
  const follow = () => {
    const { audio } = reading;
    const known = audio && Number.isFinite(audio.duration) && audio.duration > 0;
    if (known) {
      position({ duration: audio.duration, position: Math.min(audio.currentTime, audio.duration), playbackRate: audio.playbackRate || 1 });
    } else {
      position();
    }
    if (known !== seeking) {
      seeking = known;
      handle('seekto', known ? ({ seekTime }) => {
        const now = reading.audio;
        if (now && Number.isFinite(seekTime)) now.currentTime = Math.max(0, Math.min(seekTime, now.duration || seekTime));
      } : null);
    }
  };

  metadata(null);
  let artwork = null;
  Promise.resolve().then(cover).then((src) => {
    if (ended && src?.startsWith('blob:')) URL.revokeObjectURL(src);  // made after the reading ended
    if (ended || !src) return;
    artwork = src;
    metadata(src);
  }).catch(() => {});  // no cover then: the title alone
  handle('play', () => reading.resume());
  handle('pause', () => reading.pause());
  handle('stop', () => reading.stop());
  handle('nexttrack', () => turn('forward'));
  handle('previoustrack', () => turn('backward'));
  state('playing');
  const off = [
    on('readaloudpause', () => { state('paused'); follow(); }),
    on('readaloudresume', () => { state('playing'); follow(); }),
    on('readaloudpage', follow),
    on('readaloudword', follow),
  ];

  return () => {
    if (ended) return;
    ended = true;
    for (const stop of off) stop();
    for (const action of ACTIONS) handle(action, null);
    position();
    session.metadata = null;
    state('none');
    if (artwork?.startsWith('blob:')) URL.revokeObjectURL(artwork);
  };
}
