// Node tests of web/src/pages/image-header.js: the pixel size read from an image file's first bytes (so a
// page decodes straight at the size it is drawn), for each format it knows, and null where unsure.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { imageSizeOf, sizeFromBytes } from '../../web/src/pages/image-header.js';

const bytes = (...parts) => Uint8Array.from(parts.flatMap((p) => (typeof p === 'string' ? [...p].map((c) => c.charCodeAt(0)) : p)));
const be16 = (n) => [n >> 8, n & 255];
const be32 = (n) => [n >>> 24, (n >> 16) & 255, (n >> 8) & 255, n & 255];
const le16 = (n) => [n & 255, n >> 8];
const le24 = (n) => [n & 255, (n >> 8) & 255, (n >> 16) & 255];

const png = (w, h) => bytes([0x89], 'PNG\r\n\x1a\n', be32(13), 'IHDR', be32(w), be32(h), [8, 6, 0, 0, 0]);
const gif = (w, h) => bytes('GIF89a', le16(w), le16(h), [0, 0, 0]);
const webpX = (w, h) => bytes('RIFF', [0, 0, 0, 0], 'WEBP', 'VP8X', [10, 0, 0, 0], [0, 0, 0, 0], le24(w - 1), le24(h - 1));
const webpL = (w, h) => {
  const bits = ((w - 1) & 0x3fff) | (((h - 1) & 0x3fff) << 14);
  return bytes('RIFF', [0, 0, 0, 0], 'WEBP', 'VP8L', [0, 0, 0, 0], [0x2f], [bits & 255, (bits >> 8) & 255, (bits >> 16) & 255, bits >>> 24], [0, 0, 0, 0, 0]);
};
// A JPEG with an optional EXIF block (big-endian TIFF, IFD0 holding Orientation), a DQT segment, then SOF0.
function jpeg(w, h, orientation) {
  const exif = orientation === undefined ? [] : (() => {
    const tiff = [...'MM'].map((c) => c.charCodeAt(0)).concat(be16(42), be32(8), be16(1), be16(0x0112), be16(3), be32(1), be16(orientation), [0, 0], be32(0));
    const body = bytes('Exif\0\0', tiff);
    return [0xff, 0xe1, ...be16(body.length + 2), ...body];
  })();
  const dqt = [0xff, 0xdb, ...be16(67), ...new Array(65).fill(1)];
  const sof = [0xff, 0xc0, ...be16(17), 8, ...be16(h), ...be16(w), 3, ...new Array(9).fill(0)];
  return Uint8Array.from([0xff, 0xd8, ...exif, ...dqt, ...sof, 0xff, 0xd9]);
}

test('node: image sizes are read from PNG, GIF, WebP (VP8X, VP8L) and JPEG headers, EXIF quarter turns swapping them', () => {
  assert.deepEqual(sizeFromBytes(png(2000, 2500)), { width: 2000, height: 2500 });
  assert.deepEqual(sizeFromBytes(gif(321, 123)), { width: 321, height: 123 });
  assert.deepEqual(sizeFromBytes(webpX(4000, 3000)), { width: 4000, height: 3000 });
  assert.deepEqual(sizeFromBytes(webpL(777, 555)), { width: 777, height: 555 });
  assert.deepEqual(sizeFromBytes(jpeg(1600, 1200)), { width: 1600, height: 1200 });
  assert.deepEqual(sizeFromBytes(jpeg(1600, 1200, 1)), { width: 1600, height: 1200 });
  assert.deepEqual(sizeFromBytes(jpeg(1600, 1200, 6)), { width: 1200, height: 1600 });  // shown turned a quarter
  assert.deepEqual(sizeFromBytes(jpeg(1600, 1200, 8)), { width: 1200, height: 1600 });
});

test('node: an image header that is unknown, cut short or says 0 pixels gives null (the page then decodes at full size)', async () => {
  assert.equal(sizeFromBytes(bytes('<svg xmlns="http://www.w3.org/2000/svg"/>')), null);
  assert.equal(sizeFromBytes(png(2000, 2500).subarray(0, 20)), null);
  assert.equal(sizeFromBytes(jpeg(1600, 1200).subarray(0, 30)), null);
  assert.equal(sizeFromBytes(png(0, 10)), null);
  assert.equal(sizeFromBytes(new Uint8Array(0)), null);
  assert.deepEqual(await imageSizeOf(new Blob([png(640, 400)])), { width: 640, height: 400 });
  assert.equal(await imageSizeOf(new Blob(['not an image'])), null);
});
