// A test quilt as PNG bytes, from Node's own zlib: every tile a different gradient with a bright
// bar whose position says the view, so a wrong view or a wrong tile shows (docs/serve.md).
'use strict';
const zlib = require('zlib');

const CRC_TABLE = Array.from({length: 256}, (_, n) => {
  let c = n;
  for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
  return c >>> 0;
});
function crc32(buf) {
  let c = 0xffffffff;
  for (const b of buf) c = CRC_TABLE[(c ^ b) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}
function chunk(type, data) {
  const out = Buffer.alloc(12 + data.length);
  out.writeUInt32BE(data.length, 0);
  out.write(type, 4, 'ascii');
  data.copy(out, 8);
  out.writeUInt32BE(crc32(out.subarray(4, 8 + data.length)), 8 + data.length);
  return out;
}

// cols x rows tiles of tileW x tileH; view 0 is the bottom-left tile.
function quiltPng(cols, rows, tileW, tileH) {
  const w = cols * tileW, h = rows * tileH;
  const raw = Buffer.alloc((w * 3 + 1) * h);
  for (let y = 0; y < h; y++) {
    raw[y * (w * 3 + 1)] = 0;
    for (let x = 0; x < w; x++) {
      const col = Math.floor(x / tileW), rowFromBottom = rows - 1 - Math.floor(y / tileH);
      const view = rowFromBottom * cols + col, views = cols * rows;
      const u = (x % tileW) / tileW, v = (y % tileH) / tileH;
      const bar = Math.abs(u - view / views) < 0.06;
      const o = y * (w * 3 + 1) + 1 + x * 3;
      raw[o] = bar ? 255 : Math.round(255 * u);
      raw[o + 1] = bar ? 255 : Math.round(255 * v);
      raw[o + 2] = bar ? 255 : Math.round(255 * view / views);
    }
  }
  const ihdr = Buffer.alloc(13);
  ihdr.writeUInt32BE(w, 0);
  ihdr.writeUInt32BE(h, 4);
  ihdr[8] = 8; ihdr[9] = 2; ihdr[10] = 0; ihdr[11] = 0; ihdr[12] = 0;
  return Buffer.concat([Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]), chunk('IHDR', ihdr),
                        chunk('IDAT', zlib.deflateSync(raw)), chunk('IEND', Buffer.alloc(0))]);
}

module.exports = {quiltPng};
