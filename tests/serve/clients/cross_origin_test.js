// A web page from another site reaches none of lfd serve's endpoints and changes nothing; nor
// does a request whose Host header names a foreign site (DNS rebinding) (docs/serve.md).
//   node cross_origin_test.js QUILT_PNG
'use strict';
const fs = require('fs');
const hp = require('holoplay-core');
const {check, lfdStatus, waitFor} = require('./common.js');
const {holoplayRaw, put, eventSocket} = require('./raw_clients.js');

const EVIL = 'https://evil.example';
const CBOR = require('cbor-js');
const cbor = (obj) => Buffer.from(CBOR.encode(obj));

(async () => {
  setTimeout(() => check(false, 'not done in 60 s'), 60000);
  // A loopback page shows a quilt first: the refused requests below must leave it shown.
  const png = fs.readFileSync(process.argv[2]);
  const shown = await holoplayRaw(cbor({cmd: {show: {source: 'bindata', quilt: {type: 'image',
      settings: {vx: 4, vy: 3, aspect: 0.75}}}}, bin: new Uint8Array(png)}), {origin: 'http://localhost:8080'});
  check(shown.reply && CBOR.decode(new Uint8Array(shown.reply).buffer).error === 0, 'a loopback page may show a quilt');
  await waitFor('it shows', async () => (await lfdStatus()).showing.includes('HoloPlay'));
  const before = await lfdStatus();

  const wipe = await holoplayRaw(cbor({cmd: {wipe: {}}, bin: null}), {origin: EVIL});
  check(!wipe.reply, 'HoloPlay: a foreign origin gets no reply (its connection is closed)');
  const info = await holoplayRaw(cbor({cmd: {info: {}}, bin: null}), {origin: EVIL});
  check(!info.reply, 'HoloPlay: a foreign origin cannot read the calibration either');

  const enter = await put('enter_orchestration', {}, {Origin: EVIL});
  check(enter.status === 403, 'Bridge: enter_orchestration from a foreign origin is 403');
  const token = JSON.parse((await put('enter_orchestration', {})).body).payload.value;
  for (const [endpoint, body] of [['transport_control_pause', {orchestration: token}],
                                  ['instance_playlist', {orchestration: token, name: 'evil'}],
                                  ['available_output_devices', {orchestration: token}]]) {
    const r = await put(endpoint, body, {Origin: EVIL});
    check(r.status === 403, `Bridge: ${endpoint} from a foreign origin is 403`);
  }
  const rebound = await put('transport_control_pause', {orchestration: token}, {Host: 'evil.example:33334'});
  check(rebound.status === 403, 'Bridge: a foreign Host header (DNS rebinding) is 403');
  check(await eventSocket({origin: EVIL}) !== 'open', 'events: a foreign origin is disconnected');
  check(await eventSocket({origin: 'http://127.0.0.1:3000'}) === 'open', 'events: a loopback page stays connected');

  const after = await lfdStatus();
  check(after.showing === before.showing && after.playing === before.playing && after.playlist === before.playlist,
        'nothing changed: ' + after.showing);
  process.exit(0);
})().catch((e) => check(false, 'exception: ' + (e.stack || e)));
