// @lookingglass/bridge (bridge.js), unmodified, against a running lfd serve: connects, lists the
// display, casts a quilt, plays a playlist and controls playback (docs/serve.md). Node 20 has
// no `window` nor WebSocket, which bridge.js's event socket expects of a browser: the test gives
// it the `ws` package's (the library itself is not changed).
//   node bridge_test.js CALIBRATION_FILE QUILT_A QUILT_B COLS ROWS ASPECT
'use strict';
const path = require('path');
globalThis.window = globalThis;
globalThis.WebSocket = require(require.resolve('ws', {paths: [require.resolve('holoplay-core')]}));
const {BridgeClient, QuiltHologram} =
    require(path.join(__dirname, 'node_modules/@lookingglass/bridge/dist/looking-glass-bridge.js'));
const {check, lfdStatus, waitFor, expectedCalibration} = require('./common.js');

const [calibrationFile, quiltA, quiltB, cols, rows, aspect] = process.argv.slice(2);
const settings = {rows: Number(rows), columns: Number(cols), aspect: Number(aspect), viewCount: cols * rows};

(async () => {
  setTimeout(() => check(false, 'not done in 60 s'), 60000);
  const client = BridgeClient.getInstance();
  client.setVerbosity(0);
  const events = [];
  const connected = await client.connect();
  check(connected.success && connected.response.orchestration.length > 0, 'connect (an orchestration)');
  await client.addEventListener('All Events', (e) => events.push(e.payload.value.event.value));
  const displays = await client.getDisplays();
  check(displays.success && displays.response.length === 1, 'getDisplays lists the display');
  const expected = expectedCalibration(calibrationFile);
  check(Math.abs(displays.response[0].calibration.pitch - expected.pitch.value) < 1e-9, "the display's calibration is lfd's");

  const cast = await client.cast(new QuiltHologram({uri: 'file://' + quiltA, settings}));
  check(cast.success, 'cast a quilt');
  await waitFor('the cast quilt shows', async () => {
    const s = await lfdStatus();
    return s.playlist.startsWith('Cast_') && s.entries === 1 && s.index === 0;
  });

  const played = await client.playRemotePlaylist([new QuiltHologram({uri: 'file://' + quiltA, settings}),
                                                  new QuiltHologram({uri: 'file://' + quiltB, settings})]);
  check(played.success, 'play a playlist of two quilts');
  await waitFor('the playlist plays', async () => (await lfdStatus()).entries === 2);
  check((await client.pause()).success, 'pause');
  await waitFor('paused', async () => !(await lfdStatus()).playing);
  check((await client.next()).success, 'next');
  await waitFor('the second entry shows', async () => (await lfdStatus()).index === 1);
  check((await client.seek(0)).success, 'seek to entry 0');
  await waitFor('the first entry shows again', async () => (await lfdStatus()).index === 0);
  check((await client.play()).success, 'play');
  await waitFor('playing', async () => (await lfdStatus()).playing);
  check((await client.showWindow(false)).success, 'showWindow(false)');
  await waitFor('the window is hidden', async () => (await lfdStatus()).window_visible === false);
  check((await client.showWindow(true)).success, 'showWindow(true)');
  await waitFor('the window shows again', async () => (await lfdStatus()).window_visible === true);
  const aspected = await client.updateCurrentHologram({name: (await lfdStatus()).playlist, parameter: 'aspect', value: 0.8});
  check(aspected.success, "updateCurrentHologram sets the quilt's aspect");
  await waitFor('the quilt shown takes the aspect', async () => Math.abs((await lfdStatus()).quilt_aspect - 0.8) < 1e-9);
  const playing = (await lfdStatus()).playlist;
  const chosen = await client.setAutoStartPlaylist({playlistName: playing, playlistPath: ''});
  check(chosen.success, 'setAutoStartPlaylist names the playlist playing');
  const autostart = await client.getAutoStartPlaylist();
  check(autostart.success && autostart.response.payload.value.playlist_name.value === playing,
        'getAutoStartPlaylist gives it back');
  await waitFor('events arrive on the event socket', async () => events.includes('Transport Control Pause'));
  console.log('events seen: ' + [...new Set(events)].join(', '));
  await client.disconnect();
  process.exit(0);
})().catch((e) => check(false, 'exception: ' + (e.stack || e)));
