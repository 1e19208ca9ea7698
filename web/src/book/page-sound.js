// The page sound (option `sound`): a paper rustle synthesised with Web Audio from noise, no audio files,
// whose loudness and brightness follow the fastest leaf's angular speed as the engine measures it each
// frame (FrameLoop.motion), and a soft tap as a leaf lands; hard leaves sound lower and heavier. No
// AudioContext before a user gesture on the book (or one that turns it), none while muted, under
// prefers-reduced-motion or on still pages (the 2D surface has no moving leaf: it stays silent). While
// a voice reads the book aloud, the whole sound is ducked under it.

/** Angular speed (rad/s) at which the rustle is at its loudest and brightest: a fling. */
export const FULL_SPEED = 8;
const MAX_GAIN = 0.35;
const LOUDNESS_CURVE = 1.5;          // gain = MAX_GAIN x (speed / FULL_SPEED)^1.5: a slow drag whispers
const CUTOFF_HZ = { soft: [700, 7000], hard: [250, 1800] };  // band centre from a whisper to a fling
const FOLLOW_S = 0.03;               // time constant the rustle follows the leaf with
const HOLD_S = 0.1;                  // no new frame for this long (a held leaf lying still): it fades
const FADE_S = 0.06;
const TAP = {
  soft: { cutoff: 2400, seconds: 0.05, level: 0.35 },
  hard: { cutoff: 500, seconds: 0.14, level: 0.8 },
};
const NOISE_SECONDS = 2;
/** The page sound's level while a voice reads aloud (read-aloud): the turns stay heard, under the voice. */
export const DUCKED_LEVEL = 0.3;
const DUCK_S = 0.08;
const GESTURES = ['pointerdown', 'keydown', 'touchstart'];

/**
 * The rustle for a leaf turning at `speed` rad/s: its gain (0 at rest, MAX_GAIN from FULL_SPEED on)
 * and the band-pass centre in Hz, lower for a hard leaf. Monotonic in speed.
 */
export function rustleFor(speed, hard) {
  const x = Math.min(1, Math.max(0, Number.isFinite(speed) ? speed / FULL_SPEED : 0));
  const [low, high] = hard ? CUTOFF_HZ.hard : CUTOFF_HZ.soft;
  return { gain: MAX_GAIN * x ** LOUDNESS_CURVE, cutoff: low * (high / low) ** x };
}

// Paper noise: white noise with sparse crackles (short louder grains), seeded so every book sounds alike.
function paperNoise(context) {
  const length = Math.round(NOISE_SECONDS * context.sampleRate);
  const buffer = context.createBuffer(1, length, context.sampleRate);
  const data = buffer.getChannelData(0);
  let seed = 0x2545f491;
  const random = () => {
    seed ^= seed << 13; seed ^= seed >>> 17; seed ^= seed << 5;
    return (seed >>> 0) / 4294967296;
  };
  let crackle = 0;
  const decay = Math.exp(-1 / (0.004 * context.sampleRate));  // a crackle dies in ~4 ms
  for (let i = 0; i < length; i++) {
    if (random() < 60 / context.sampleRate) crackle = 1;  // ~60 crackles a second
    crackle *= decay;
    data[i] = (random() * 2 - 1) * (0.35 + 0.65 * crackle);
  }
  return buffer;
}

// Sets an AudioParam towards `value` from `at` with time constant `tau`, from wherever it is now.
function glide(param, value, at, tau) {
  if (param.cancelAndHoldAtTime) param.cancelAndHoldAtTime(at);
  else {
    param.cancelScheduledValues(at);
    param.setValueAtTime(param.value, at);
  }
  param.setTargetAtTime(value, at, tau);
}

/**
 * Starts the sound of `book` (its `options`, `surface`, `turnstart` events) laid in `root`.
 * `animates()` says whether leaves move (false on still pages and under reduced motion).
 * Returns { update() (options changed), duck(on) (a voice reads aloud), stop(), status }.
 */
export function startPageSound(book, root, { animates }) {
  let graph = null;       // { context, rustle, band, master, noise } once a gesture made it
  let settings = { sound: false, muted: false };
  let target = 0;
  let speed = 0;
  let taps = 0;
  let ducked = false;
  const wanted = () => settings.sound && !settings.muted && animates();
  const AudioContextClass = globalThis.AudioContext ?? globalThis.webkitAudioContext;

  function build() {
    const context = new AudioContextClass();
    const master = context.createGain();
    master.gain.value = ducked ? DUCKED_LEVEL : 1;
    master.connect(context.destination);
    const band = context.createBiquadFilter();
    band.type = 'bandpass';
    band.Q.value = 0.8;
    band.frequency.value = rustleFor(0, false).cutoff;
    const rustle = context.createGain();
    rustle.gain.value = 0;
    const noise = paperNoise(context);
    const source = context.createBufferSource();
    source.buffer = noise;
    source.loop = true;
    source.connect(band).connect(rustle).connect(master);
    source.start();
    return { context, master, band, rustle, noise };
  }

  function listen(on) {
    const view = book.surface;
    if (view && 'onMotion' in view) view.onMotion = on ? hear : null;
  }

  // A frame of the engine: the rustle follows the fastest leaf, and fades if no frame follows.
  function hear({ speed: now, hard, landings, landedHard }) {
    if (!graph || !wanted()) return silence();
    const t = graph.context.currentTime;
    const { gain, cutoff } = rustleFor(now, hard);
    target = gain;
    glide(graph.rustle.gain, gain, t, FOLLOW_S);
    graph.rustle.gain.setTargetAtTime(0, t + HOLD_S, FADE_S);
    glide(graph.band.frequency, cutoff, t, FOLLOW_S);
    if (landings > 0) tap(landedHard, Math.max(speed, now));
    speed = now;
    return undefined;
  }

  function tap(hard, lastSpeed) {
    const { context, master, noise } = graph;
    const { cutoff, seconds, level } = hard ? TAP.hard : TAP.soft;
    const t = context.currentTime;
    const source = context.createBufferSource();
    source.buffer = noise;
    const filter = context.createBiquadFilter();
    filter.type = 'lowpass';
    filter.frequency.value = cutoff;
    const envelope = context.createGain();
    envelope.gain.setValueAtTime(level * (0.4 + 0.6 * Math.min(1, lastSpeed / FULL_SPEED)), t);
    envelope.gain.setTargetAtTime(0, t, seconds / 4);
    source.connect(filter).connect(envelope).connect(master);
    source.start(t, (taps * 0.37) % (NOISE_SECONDS - 0.5), seconds * 2);
    taps++;
  }

  function silence() {
    target = 0;
    speed = 0;
    if (!graph) return;
    graph.rustle.gain.cancelScheduledValues(0);
    graph.rustle.gain.value = 0;
  }

  // A user gesture: the browser lets an AudioContext start now.
  function onGesture() {
    if (!wanted() || !AudioContextClass) return;
    if (!graph) graph = build();
    else if (graph.context.state === 'suspended') graph.context.resume().catch(() => {});
    listen(true);
  }
  // A turn a gesture asked for (a button of the page calling next()) counts as one on the book.
  const onTurnStart = () => { if (globalThis.navigator?.userActivation?.isActive) onGesture(); };

  function update() {
    settings = { sound: book.options.sound, muted: book.options.muted };
    if (wanted()) {
      if (graph) {
        graph.context.resume().catch(() => {});
        listen(true);
      }
      return;
    }
    listen(false);
    silence();
    graph?.context.suspend().catch(() => {});
  }

  for (const type of GESTURES) root.addEventListener(type, onGesture, { capture: true, passive: true });
  book.addEventListener('turnstart', onTurnStart);
  update();

  return {
    update,
    /** A voice reads aloud (on): the page sound goes down to DUCKED_LEVEL until it stops (off). */
    duck(on) {
      ducked = Boolean(on);
      if (graph) glide(graph.master.gain, ducked ? DUCKED_LEVEL : 1, graph.context.currentTime, DUCK_S);
    },
    stop() {
      for (const type of GESTURES) root.removeEventListener(type, onGesture, { capture: true });
      book.removeEventListener('turnstart', onTurnStart);
      listen(false);
      graph?.context.close().catch(() => {});
      graph = null;
    },
    /** What the sound is doing, for tools and tests (a fresh snapshot each read). */
    get status() {
      let state = 'waiting';  // for a gesture
      if (!settings.sound) state = 'off';
      else if (settings.muted) state = 'muted';
      else if (!animates()) state = 'silent';
      else if (graph) state = graph.context.state;
      return Object.freeze({ state, gain: graph ? graph.rustle.gain.value : 0, target, speed, taps, ducked, level: graph ? graph.master.gain.value : 0 });
    },
  };
}
