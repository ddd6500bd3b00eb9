// Garbage never stops lfd serve: malformed CBOR and JSON, wrong shapes, unknown commands,
// lying sizes, oversized bodies and messages get an error reply or a closed connection, and the
// service answers the next real client (docs/serve.md).
'use strict';
const {check} = require('./common.js');
const {holoplayRaw, put, eventSocket} = require('./raw_clients.js');
const CBOR = require('cbor-js');
const cbor = (obj) => Buffer.from(CBOR.encode(obj));
const errorOf = (r) => r.reply ? CBOR.decode(new Uint8Array(r.reply).buffer).error : undefined;

(async () => {
  setTimeout(() => check(false, 'not done in 120 s'), 120000);
  const cases = [
    ['random bytes', Buffer.from([0xff, 0x13, 0x37, 0x00, 0x42])],
    ['a CBOR number', cbor(42)],
    ['no cmd', cbor({bin: null})],
    ['an unknown command', cbor({cmd: {launch: {}}, bin: null})],
    ['show without an image', cbor({cmd: {show: {source: 'bindata', quilt: {settings: {vx: 5, vy: 9, aspect: 1}}}}, bin: null})],
    ['show of bytes that are no image', cbor({cmd: {show: {quilt: {settings: {vx: 5, vy: 9, aspect: 1}}}}, bin: new Uint8Array(1000)})],
    ['NaN aspect', cbor({cmd: {show: {quilt: {settings: {vx: 5, vy: 9, aspect: NaN}}}}, bin: new Uint8Array(8)})],
    ['an array claiming 2^40 items', Buffer.from([0x9b, 0, 0, 1, 0, 0, 0, 0, 0])],
    ['nesting 100000 deep', Buffer.alloc(100000, 0x81)],
  ];
  for (const [what, payload] of cases) {
    const r = await holoplayRaw(payload);
    check(errorOf(r) > 0, `HoloPlay: ${what} gets an error reply (${errorOf(r)})`);
  }
  const tooBig = await holoplayRaw(Buffer.alloc(100 * 1024 * 1024, 0x41), {timeoutMs: 20000});
  check(!tooBig.reply, 'HoloPlay: a message over the size limit closes the connection');
  const noHeader = await holoplayRaw(Buffer.from([1, 2]), {rawFrame: true});
  check(!noHeader.reply, 'HoloPlay: a frame without the SP header closes the connection');

  for (const [what, body, status] of [['not JSON', '{"orchestration":', 400], ['a JSON array', '[1,2,3]', 400],
                                      ['deep nesting', '['.repeat(50000), 400],
                                      ['a body over 1 MiB', ' '.repeat(2 * 1024 * 1024), 413]]) {
    const r = await put('instance_playlist', body);
    check(r.status === status, `Bridge: ${what} is ${status} (${r.status || r.error})`);
  }
  check((await put('no_such_endpoint', {})).status === 404, 'Bridge: an unknown endpoint is 404');
  const token = JSON.parse((await put('enter_orchestration', {})).body).payload.value;
  const wrong = await put('insert_playlist_entry', {orchestration: token, name: 'x', uri: 'file:///etc', rows: 'many'});
  check(wrong.status === 400, 'Bridge: wrong field types are 400');
  check(await eventSocket({send: 'x'.repeat(100000)}) === 'closed', 'events: an oversized message closes the socket');

  const info = await holoplayRaw(cbor({cmd: {info: {}}, bin: null}));
  check(errorOf(info) === 0, 'after all that, info still answers');
  process.exit(0);
})().catch((e) => check(false, 'exception: ' + (e.stack || e)));
