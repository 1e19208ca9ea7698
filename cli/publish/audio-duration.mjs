// How long a narration's audio file plays, read from its own bytes (no decoder, no package): so that
// `conecurl publish --narration` can say a word's time lies past the audio's end. WAV from its header,
// MP3 by walking its frames, Ogg (Vorbis, Opus) from its last page's granule position, M4A from its
// mvhd box. null where the length cannot be known this way; an Error where the bytes are not that format.

/** The audio extensions narration takes, each with the name of its format. */
export const AUDIO_FORMATS = { mp3: 'an MP3 file', m4a: 'an M4A (MPEG-4 audio) file', ogg: 'an Ogg file', opus: 'an Opus (Ogg) file', wav: 'a WAV file' };

const ascii = (bytes, at, length) => bytes.toString('latin1', at, at + length);

/** A WAV file's seconds: its data chunk's bytes over the fmt chunk's bytes a second. */
function wavSeconds(bytes) {
  if (ascii(bytes, 0, 4) !== 'RIFF' || ascii(bytes, 8, 4) !== 'WAVE') return undefined;
  let byteRate = 0;
  for (let at = 12; at + 8 <= bytes.length;) {
    const id = ascii(bytes, at, 4);
    const size = bytes.readUInt32LE(at + 4);
    if (id === 'fmt ' && at + 16 <= bytes.length) byteRate = bytes.readUInt32LE(at + 16);
    if (id === 'data') return byteRate > 0 ? Math.min(size, bytes.length - at - 8) / byteRate : null;
    at += 8 + size + (size % 2);
  }
  return null;
}

const MP3_BITRATES = {  // kbit/s by [MPEG-1 | MPEG-2 and 2.5][layer I, II, III], index 1 to 14
  1: [[32, 64, 96, 128, 160, 192, 224, 256, 288, 320, 352, 384, 416, 448],
    [32, 48, 56, 64, 80, 96, 112, 128, 160, 192, 224, 256, 320, 384],
    [32, 40, 48, 56, 64, 80, 96, 112, 128, 160, 192, 224, 256, 320]],
  2: [[32, 48, 56, 64, 80, 96, 112, 128, 144, 160, 176, 192, 224, 256],
    [8, 16, 24, 32, 40, 48, 56, 64, 80, 96, 112, 128, 144, 160],
    [8, 16, 24, 32, 40, 48, 56, 64, 80, 96, 112, 128, 144, 160]],
};
const MP3_RATES = { 3: [44100, 48000, 32000], 2: [22050, 24000, 16000], 0: [11025, 12000, 8000] };

/** The MPEG audio frame at `at`: { length, samples, rate }, or null where no frame header is there. */
function mp3Frame(bytes, at) {
  if (at + 4 > bytes.length || bytes[at] !== 0xff || (bytes[at + 1] & 0xe0) !== 0xe0) return null;
  const version = (bytes[at + 1] >> 3) & 3;  // 3 MPEG-1, 2 MPEG-2, 0 MPEG-2.5
  const layer = 4 - ((bytes[at + 1] >> 1) & 3);  // 1, 2 or 3 (4: reserved)
  const bitrateIndex = bytes[at + 2] >> 4;
  const rateIndex = (bytes[at + 2] >> 2) & 3;
  if (version === 1 || layer === 4 || bitrateIndex === 0 || bitrateIndex === 15 || rateIndex === 3) return null;
  const bitrate = MP3_BITRATES[version === 3 ? 1 : 2][layer - 1][bitrateIndex - 1] * 1000;
  const rate = MP3_RATES[version][rateIndex];
  const padding = (bytes[at + 2] >> 1) & 1;
  if (layer === 1) return { length: (Math.floor((12 * bitrate) / rate) + padding) * 4, samples: 384, rate };
  const samples = layer === 3 && version !== 3 ? 576 : 1152;
  return { length: Math.floor((samples / 8) * bitrate / rate) + padding, samples, rate };
}

/** An MP3 file's seconds: every frame's samples, after an ID3v2 tag; undefined where no two frames follow each other. */
function mp3Seconds(bytes) {
  let at = 0;
  if (ascii(bytes, 0, 3) === 'ID3' && bytes.length >= 10) {
    const size = ((bytes[6] & 0x7f) << 21) | ((bytes[7] & 0x7f) << 14) | ((bytes[8] & 0x7f) << 7) | (bytes[9] & 0x7f);
    at = 10 + size + (bytes[5] & 0x10 ? 10 : 0);
  }
  // The first frame: a header whose next frame's header follows it (a lone 0xFFE in a tag is no frame).
  const limit = Math.min(bytes.length, at + 65536);
  for (; at < limit; at++) {
    const frame = mp3Frame(bytes, at);
    if (frame && (at + frame.length === bytes.length || mp3Frame(bytes, at + frame.length))) break;
  }
  if (at >= limit) return undefined;
  let seconds = 0;
  for (let frame = mp3Frame(bytes, at); frame && at + frame.length <= bytes.length; frame = mp3Frame(bytes, at)) {
    seconds += frame.samples / frame.rate;
    at += frame.length;
  }
  return seconds;
}

/** An Ogg file's seconds: its last page's granule position over the rate its first packet gives (Vorbis, Opus). */
function oggSeconds(bytes) {
  if (ascii(bytes, 0, 4) !== 'OggS') return undefined;
  const packet = 27 + bytes[26];  // the first page's header and its segment table
  let rate;
  let skip = 0;
  if (ascii(bytes, packet, 7) === '\x01vorbis') rate = bytes.readUInt32LE(packet + 12);
  else if (ascii(bytes, packet, 8) === 'OpusHead') [rate, skip] = [48000, bytes.readUInt16LE(packet + 10)];
  else return null;  // FLAC or Speex in Ogg: not read here
  const last = bytes.lastIndexOf('OggS', bytes.length - 27, 'latin1');
  if (last < 0 || !(rate > 0)) return null;
  const granule = Number(bytes.readBigInt64LE(last + 6));
  return granule >= 0 ? Math.max(0, granule - skip) / rate : null;
}

/** An MPEG-4 file's seconds: the movie header's (moov/mvhd) duration over its timescale. */
function m4aSeconds(bytes) {
  if (ascii(bytes, 4, 4) !== 'ftyp') return undefined;
  const boxes = (from, to) => {
    const found = new Map();
    for (let at = from; at + 8 <= to;) {
      let size = bytes.readUInt32BE(at);
      let head = 8;
      if (size === 1 && at + 16 <= to) [size, head] = [Number(bytes.readBigUInt64BE(at + 8)), 16];
      else if (size === 0) size = to - at;
      if (size < head) break;
      found.set(ascii(bytes, at + 4, 4), { start: at + head, end: Math.min(to, at + size) });
      at += size;
    }
    return found;
  };
  const moov = boxes(0, bytes.length).get('moov');
  const mvhd = moov && boxes(moov.start, moov.end).get('mvhd');
  if (!mvhd) return null;
  const v1 = bytes[mvhd.start] === 1;
  if (mvhd.start + (v1 ? 32 : 20) > bytes.length) return null;
  const timescale = bytes.readUInt32BE(mvhd.start + (v1 ? 20 : 12));
  const duration = v1 ? Number(bytes.readBigUInt64BE(mvhd.start + 24)) : bytes.readUInt32BE(mvhd.start + 16);
  return timescale > 0 ? duration / timescale : null;
}

const READERS = { wav: wavSeconds, mp3: mp3Seconds, ogg: oggSeconds, opus: oggSeconds, m4a: m4aSeconds };

/**
 * The seconds the audio in `bytes` (a file with extension `ext`, an AUDIO_FORMATS key) plays, or null
 * where they cannot be read from its headers. Throws an Error (its message says what the bytes are not)
 * where the file is empty or is not that format at all.
 */
export function audioSeconds(bytes, ext) {
  if (bytes.length === 0) throw new Error('is empty');
  let seconds;
  try {
    seconds = READERS[ext](bytes);
  } catch {
    return null;  // a header cut short: its length is not known, the browser may still play what there is
  }
  if (seconds === undefined) throw new Error(`is not ${AUDIO_FORMATS[ext]} (its first bytes are not that format's)`);
  return seconds;
}
