// Recorded narration played: the page's audio file in an <audio> element, and the word whose time
// holds the element's currentTime reported as it changes (each frame while it plays, and on seeks),
// behind the same { pause, resume, cancel } read-aloud.js has of a speech engine.

/** The index of the word said at `time` (the last word started by then; -1 before the first). */
export function wordAtTime(words, time) {
  let at = -1;
  for (let i = 0; i < words.length && words[i].start <= time; i++) at = i;
  return at;
}

/**
 * Plays `src` from the time of word `from`, at `rate`; onWord(index) as the word said changes,
 * onEnd() when the audio ends, onError(error) when it cannot play. Returns { audio, pause, resume, cancel }.
 */
export function playNarration(src, words, { from = 0, rate = 1, onWord, onEnd, onError }) {
  const audio = new Audio();
  audio.preload = 'auto';
  audio.src = src;
  audio.playbackRate = rate;
  let said = -1;
  let frame = 0;
  let over = false;
  // The word at currentTime; words a late frame passed over are still told, in order (a seek back is not).
  const follow = () => {
    const now = wordAtTime(words, audio.currentTime);
    if (now === said || now < 0) return;
    const from = now > said ? said + 1 : now;
    said = now;
    for (let i = from; i <= now; i++) onWord?.(i);
  };
  const tick = () => {
    follow();
    frame = audio.paused || over ? 0 : requestAnimationFrame(tick);
  };
  const failed = (error) => {
    if (over) return;
    over = true;
    onError?.(error);
  };
  const listeners = {
    playing: () => { cancelAnimationFrame(frame); frame = requestAnimationFrame(tick); },
    timeupdate: follow,
    seeked: follow,
    ended: () => {
      if (over) return;
      follow();
      over = true;
      onEnd?.();
    },
    error: () => failed(new Error(`conecurl: the narration ${src} could not be played (${audio.error?.message || `media error ${audio.error?.code}`})`)),
  };
  for (const [type, listener] of Object.entries(listeners)) audio.addEventListener(type, listener);
  const start = words[from]?.start ?? 0;
  const play = () => audio.play().catch((error) => {
    if (error?.name === 'AbortError') return;  // paused or cancelled before it began
    failed(error?.name === 'NotAllowedError'
      ? new Error('conecurl: the browser blocked the narration until the reader interacts with the page: start reading from a click or a key')
      : error);
  });
  if (start > 0) {
    audio.addEventListener('loadedmetadata', () => {
      audio.currentTime = start;
      play();
    }, { once: true });
    audio.load();
  } else {
    play();
  }
  return {
    audio,
    pause: () => audio.pause(),
    resume: () => { if (!over) play(); },
    cancel: () => {
      over = true;
      cancelAnimationFrame(frame);
      for (const [type, listener] of Object.entries(listeners)) audio.removeEventListener(type, listener);
      audio.pause();
      audio.removeAttribute('src');
      audio.load();  // lets the file go
    },
  };
}
