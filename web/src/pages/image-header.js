// An image's pixel size read from its first bytes (PNG, JPEG, GIF, WebP), so a page can be decoded
// straight at the size it is drawn (createImageBitmap's resize, off the main thread) instead of at full
// size and then scaled on the main thread. Null whenever it is not sure: the caller decodes as before.

const HEAD_BYTES = 65536;  // a JPEG's frame header usually sits within its first few KB (after EXIF)

/** `{ width, height }` as the image shows (EXIF orientation applied), or null. */
export async function imageSizeOf(blob) {
  try {
    return sizeFromBytes(new Uint8Array(await blob.slice(0, HEAD_BYTES).arrayBuffer()));
  } catch {
    return null;
  }
}

/** The size encoded in an image file's first bytes, or null (unknown format, or not found). */
export function sizeFromBytes(b) {
  const u16 = (i, little) => (little ? b[i] | (b[i + 1] << 8) : (b[i] << 8) | b[i + 1]);
  const u32 = (i, little) => (little
    ? (b[i] | (b[i + 1] << 8) | (b[i + 2] << 16) | (b[i + 3] << 24)) >>> 0
    : ((b[i] << 24) | (b[i + 1] << 16) | (b[i + 2] << 8) | b[i + 3]) >>> 0);
  const ascii = (i, n) => String.fromCharCode(...b.subarray(i, i + n));
  const sized = (width, height) => (width > 0 && height > 0 ? { width, height } : null);
  if (b.length >= 24 && u32(0) === 0x89504e47 && ascii(12, 4) === 'IHDR') return sized(u32(16), u32(20));
  if (b.length >= 10 && ascii(0, 4) === 'GIF8') return sized(u16(6, true), u16(8, true));
  if (b.length >= 30 && ascii(0, 4) === 'RIFF' && ascii(8, 4) === 'WEBP') {
    const chunk = ascii(12, 4);
    if (chunk === 'VP8X') return sized(1 + (b[24] | (b[25] << 8) | (b[26] << 16)), 1 + (b[27] | (b[28] << 8) | (b[29] << 16)));
    if (chunk === 'VP8L') {
      const bits = u32(21, true);
      return sized(1 + (bits & 0x3fff), 1 + ((bits >>> 14) & 0x3fff));
    }
    if (chunk === 'VP8 ') return sized(u16(26, true) & 0x3fff, u16(28, true) & 0x3fff);
    return null;
  }
  if (b.length >= 4 && b[0] === 0xff && b[1] === 0xd8) return jpegSize(b, u16, u32, ascii, sized);
  return null;
}

function jpegSize(b, u16, u32, ascii, sized) {
  let swap = false;  // EXIF orientations 5 to 8 turn the picture a quarter
  for (let i = 2; i + 9 < b.length;) {
    if (b[i] !== 0xff) return null;
    const marker = b[i + 1];
    if (marker === 0xff) { i++; continue; }
    const length = u16(i + 2);
    if (marker === 0xe1 && ascii(i + 4, 6) === 'Exif\0\0') {
      const orientation = exifOrientation(b, i + 10, u16, u32);
      if (orientation === null) return null;
      swap = orientation >= 5;
    }
    // Start of frame (baseline, progressive, ...), not DHT (c4), JPG (c8) or DAC (cc).
    if (marker >= 0xc0 && marker <= 0xcf && marker !== 0xc4 && marker !== 0xc8 && marker !== 0xcc) {
      const height = u16(i + 5);
      const width = u16(i + 7);
      return swap ? sized(height, width) : sized(width, height);
    }
    i += 2 + length;
  }
  return null;
}

// The Orientation tag (0x0112) of IFD0 in the TIFF block at `t`: 1 when absent, null when unreadable.
function exifOrientation(b, t, u16, u32) {
  if (t + 8 > b.length) return null;
  const little = b[t] === 0x49;  // 'II' little-endian, 'MM' big-endian
  const ifd = t + u32(t + 4, little);
  if (ifd + 2 > b.length) return null;
  const count = u16(ifd, little);
  for (let k = 0; k < count; k++) {
    const entry = ifd + 2 + 12 * k;
    if (entry + 12 > b.length) return null;
    if (u16(entry, little) === 0x0112) return u16(entry + 8, little);
  }
  return 1;
}
