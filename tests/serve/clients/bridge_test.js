// @lookingglass/bridge (bridge.js), unmodified, against a running lfd serve: connects, lists the
// display, casts a quilt and an RGB-D image, plays a playlist and a Looking Glass Studio playlist
// and controls playback (docs/serve.md). Node 20 has
// no `window` nor WebSocket, which bridge.js's event socket expects of a browser: the test gives
// it the `ws` package's (the library itself is not changed).
//   node bridge_test.js CALIBRATION_FILE QUILT_A QUILT_B COLS ROWS ASPECT
'use strict';
const fs = require('fs');
const os = require('os');
const path = require('path');
globalThis.window = globalThis;
globalThis.WebSocket = require(require.resolve('ws', {paths: [require.resolve('holoplay-core')]}));
const {BridgeClient, QuiltHologram, RGBDHologram} =
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

  // An RGB-D image (any picture: its halves are colour and depth) and update_current_entry's
  // depth_cutoff, as bridge.js 0.0.8-alpha.4 sends it (0 or 1).
  const rgbd = new RGBDHologram({uri: 'file://' + quiltA, settings: {depthiness: 1.5, focus: 0, aspect: 1,
    chroma_depth: 0, depth_inversion: 0, depth_loc: 2, zoom: 1}});
  check((await client.cast(rgbd)).success, 'cast an RGB-D image');
  await waitFor('the RGB-D image shows', async () => {
    const s = await lfdStatus();
    return s.playlist.startsWith('Cast_') && s.rgbd !== null && s.rgbd.depth_cutoff === 0;
  });
  const cutoff = await client.updateCurrentHologram({name: (await lfdStatus()).playlist, parameter: 'depth_cutoff', value: 1});
  check(cutoff.success && cutoff.response.status.value === 'Completion', 'updateCurrentHologram sets depth_cutoff');
  await waitFor('the RGB-D views take the cutoff', async () => (await lfdStatus()).rgbd.depth_cutoff === 1);

  // A Looking Glass Studio playlist folder: playlist.json and each file's sidecar settings.
  const studio = fs.mkdtempSync(path.join(os.tmpdir(), 'lfd-studio-'));
  const items = [];
  for (const [i, quilt] of [quiltA, quiltB].entries()) {
    const name = `hologram${i}` + path.extname(quilt);
    fs.copyFileSync(quilt, path.join(studio, name));
    fs.writeFileSync(path.join(studio, name + '.json'), JSON.stringify({movie: false, mediaType: 'quilt',
      quilt_settings: {viewX: Number(cols), viewY: Number(rows), viewTotal: cols * rows, aspect: Number(aspect),
                       invertViews: false}, focus: 0, zoom: 1, duration: 10}));
    items.push({filename: name, last_updated: '2024-05-01T12:00:00', needs_sync: false});
  }
  const studioPlaylist = path.join(studio, 'playlist.json');
  fs.writeFileSync(studioPlaylist, JSON.stringify(items));
  const studioPlayed = await client.playStudioPlaylist(studioPlaylist);
  check(studioPlayed.success && studioPlayed.response.status.value === 'Completion', 'playStudioPlaylist');
  await waitFor('the Studio playlist plays', async () => {
    const s = await lfdStatus();
    return s.playlist === 'Studio Playlist' && s.entries === 2 && s.rgbd === null;
  });
  const fromStudio = await client.setAutoStartPlaylist({playlistName: 'Studio autostart', playlistPath: studioPlaylist});
  check(fromStudio.success && fromStudio.response.status.value === 'Completion', 'setAutoStartPlaylist of a Studio playlist.json');
  check((await client.getAutoStartPlaylist()).response.payload.value.playlist_name.value === 'Studio autostart',
        'getAutoStartPlaylist gives the Studio playlist back');

  const playing = (await lfdStatus()).playlist;
  const chosen = await client.setAutoStartPlaylist({playlistName: playing, playlistPath: ''});
  check(chosen.success, 'setAutoStartPlaylist names the playlist playing');
  const autostart = await client.getAutoStartPlaylist();
  check(autostart.success && autostart.response.payload.value.playlist_name.value === playing,
        'getAutoStartPlaylist gives it back');
  // sync_overwrite_playlist, which bridge.js has no call for: plain HTTP, the vendor Toolkit's
  // request (LKG-Toolkit TrySyncPlaylist).
  const synced = await (await fetch('http://localhost:33334/sync_overwrite_playlist', {method: 'PUT',
    headers: {'Content-Type': 'application/json'},
    body: JSON.stringify({orchestration: client.orchestration, name: 'Studio Playlist', head_index: -1, crf: 20,
                          pixel_format: 'yuv420p', encoder: 'h265'})})).json();
  check(synced.status.value === 'Completion', 'sync_overwrite_playlist (plain HTTP)');
  check((await client.getAutoStartPlaylist()).response.payload.value.playlist_name.value === 'Studio Playlist',
        'the synced playlist is the one played at start');
  await waitFor('sync events arrive', async () => events.includes('Sync/Play Playlist Complete'));
  await waitFor('events arrive on the event socket', async () => events.includes('Transport Control Pause'));
  console.log('events seen: ' + [...new Set(events)].join(', '));
  check((await client.stopStudioPlaylist()).success, 'stopStudioPlaylist');
  await waitFor('the Studio playlist is gone and the window hidden', async () => {
    const s = await lfdStatus();
    return s.playlist !== 'Studio Playlist' && s.window_visible === false;
  });
  fs.rmSync(studio, {recursive: true});
  await client.disconnect();
  process.exit(0);
})().catch((e) => check(false, 'exception: ' + (e.stack || e)));
