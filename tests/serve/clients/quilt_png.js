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

// An RGB PNG of w x h whose pixel (x, y) (row 0 at the top) is colour(x, y) = [r, g, b].
function rgbPng(w, h, colour) {
  const raw = Buffer.alloc((w * 3 + 1) * h);
  for (let y = 0; y < h; y++) {
    raw[y * (w * 3 + 1)] = 0;
    for (let x = 0; x < w; x++) raw.set(colour(x, y), y * (w * 3 + 1) + 1 + x * 3);
  }
  const ihdr = Buffer.alloc(13);
  ihdr.writeUInt32BE(w, 0);
  ihdr.writeUInt32BE(h, 4);
  ihdr[8] = 8; ihdr[9] = 2; ihdr[10] = 0; ihdr[11] = 0; ihdr[12] = 0;
  return Buffer.concat([Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]), chunk('IHDR', ihdr),
                        chunk('IDAT', zlib.deflateSync(raw)), chunk('IEND', Buffer.alloc(0))]);
}

// The view of quilt pixel (x, y) for cols x rows tiles of tileW x tileH; view 0 is the
// bottom-left tile.
function viewAt(x, y, cols, rows, tileW, tileH) {
  return (rows - 1 - Math.floor(y / tileH)) * cols + Math.floor(x / tileW);
}

function quiltPng(cols, rows, tileW, tileH) {
  const views = cols * rows;
  return rgbPng(cols * tileW, rows * tileH, (x, y) => {
    const view = viewAt(x, y, cols, rows, tileW, tileH);
    const u = (x % tileW) / tileW, v = (y % tileH) / tileH;
    if (Math.abs(u - view / views) < 0.06) return [255, 255, 255];  // the bar
    return [Math.round(255 * u), Math.round(255 * v), Math.round(255 * view / views)];
  });
}

// Each view one flat colour: red fading from view 0, blue rising to the last, green peaking at
// the middle views. What an eye sees near an edge of the cone is the edge views' red and blue
// (which of them dominates says which edge) with little green (docs/console.md, "Seen from").
function viewColour(view, views) {
  const t = view / (views - 1);
  return [Math.round(255 * (1 - t)), Math.round(255 * (1 - Math.abs(2 * t - 1))), Math.round(255 * t)];
}
function viewColourQuiltPng(cols, rows, tileW, tileH) {
  return rgbPng(cols * tileW, rows * tileH, (x, y) => viewColour(viewAt(x, y, cols, rows, tileW, tileH), cols * rows));
}

module.exports = {quiltPng, viewColourQuiltPng};
