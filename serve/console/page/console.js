// lfd console (docs/console.md). Every action is a documented route of the service: Bridge's
// endpoints (docs/serve.md) where one exists, the console's own (/library, /playlists,
// /console/config, /seen_from) for the rest, so nothing the page does is closed to scripts. Live state comes
// over Bridge's event WebSocket; the page asks lfd_status again when an event arrives.
'use strict';

const state = {config: null, orchestration: '', library: [], playlists: [], autostart: null, status: null};
const $ = (id) => document.getElementById(id);

function say(text, isError) {
  const m = $('message');
  m.textContent = text;
  m.className = isError ? 'error' : '';
}

// --- the service's routes -----------------------------------------------------------------

async function getJson(path) {
  const r = await fetch(path, {credentials: 'same-origin'});
  const body = await r.json().catch(() => ({}));
  if (!r.ok) throw new Error(body.error || `${path}: HTTP ${r.status}`);
  return body;
}

async function postJson(path, body) {
  const r = await fetch(path, {method: 'POST', credentials: 'same-origin',
                               headers: {'Content-Type': 'application/json'}, body: JSON.stringify(body)});
  const reply = await r.json().catch(() => ({}));
  if (!r.ok) throw new Error(reply.error || `${path}: HTTP ${r.status}`);
  return reply;
}

// A Bridge call (PUT, as bridge.js), with the page's orchestration; entered again once when the
// service no longer knows it (restarted).
async function bridge(endpoint, fields = {}, retried = false) {
  if (!state.orchestration && endpoint !== 'enter_orchestration') await enterOrchestration();
  const r = await fetch('/' + endpoint, {method: 'PUT', credentials: 'same-origin',
                                         headers: {'Content-Type': 'application/json'},
                                         body: JSON.stringify({orchestration: state.orchestration, ...fields})});
  const reply = await r.json().catch(() => ({}));
  const status = reply.status && reply.status.value;
  if (status === 'UnknownOrchestration' && !retried) {
    state.orchestration = '';
    return bridge(endpoint, fields, true);
  }
  if (status !== 'Completion') {
    const why = reply.payload && reply.payload.value;
    throw new Error(`${endpoint}: ${typeof why === 'string' ? why : 'HTTP ' + r.status}`);
  }
  return reply.payload ? reply.payload.value : null;
}

async function enterOrchestration() {
  const r = await fetch('/enter_orchestration', {method: 'PUT', credentials: 'same-origin',
                                                 headers: {'Content-Type': 'application/json'},
                                                 body: JSON.stringify({name: 'lfd console'})});
  const reply = await r.json();
  state.orchestration = reply.payload.value;
}

// Runs an action, saying what went wrong in one line.
async function act(what, f) {
  try {
    const done = await f();
    if (typeof done === 'string') say(done, false);
  } catch (e) {
    say(`${what}: ${e.message}`, true);
  }
}

// --- views --------------------------------------------------------------------------------

function showView() {
  const id = (location.hash || '#display').slice(1);
  const known = ['display', 'content', 'playlists'].includes(id) ? id : 'display';
  for (const view of document.querySelectorAll('.view')) view.hidden = view.id !== known;
  for (const a of document.querySelectorAll('nav a')) {
    if (a.getAttribute('href') === '#' + known) a.setAttribute('aria-current', 'page');
    else a.removeAttribute('aria-current');
  }
}

function el(tag, attrs = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === 'text') e.textContent = v;
    else if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
    else if (v !== false && v !== null && v !== undefined) e.setAttribute(k, v === true ? '' : v);
  }
  for (const c of children) if (c) e.append(c);
  return e;
}

function fact(dl, term, value) {
  dl.append(el('dt', {text: term}), el('dd', {text: value}));
}

// --- display ------------------------------------------------------------------------------

async function loadDisplays() {
  const devices = await bridge('available_output_devices');
  const list = $('displays');
  list.replaceChildren();
  for (const d of Object.values(devices || {})) {
    const v = d.value;
    const cal = JSON.parse(v.calibration.value);
    const quilt = JSON.parse(v.defaultQuilt.value);
    const status = (state.status && state.status.displays || []).find((s) => s.index === v.index.value) || {};
    const item = el('li', {'aria-label': `Display ${v.index.value}: ${cal.serial || v.hwid.value}`});
    item.append(el('h3', {text: `Display ${v.index.value}`}));
    const dl = el('dl', {class: 'facts'});
    fact(dl, 'Model', v.hwid.value);
    fact(dl, 'Serial', cal.serial || 'unknown');
    fact(dl, 'Panel', `${cal.screenW.value} x ${cal.screenH.value} px`);
    fact(dl, 'Views', String(quilt.tileX * quilt.tileY));
    fact(dl, 'Quilt', `${quilt.tileX} x ${quilt.tileY} tiles, ${quilt.quiltX} x ${quilt.quiltY} px, aspect ${quilt.quiltAspect}`);
    fact(dl, 'View cone', `${cal.viewCone.value} degrees`);
    fact(dl, 'Calibration', `${v.calibrationSource.value}${status.calibration ? ': ' + status.calibration : ''}`);
    await reportFacts(dl, v.index.value);
    item.append(dl);
    list.append(item);
  }
}

// The position within the entry: lfd_status's, moved on by the page's own clock while playing
// (the service pushes an event at each change; between events the page counts, it does not poll).
function secondsText(t) {
  return `${Math.floor(t / 60)}:${(t % 60).toFixed(1).padStart(4, '0')}`;
}

function showPosition() {
  const s = state.status;
  if (!s || !(s.duration_s > 0)) {
    $('now-position').textContent = 'none';
    $('seek-box').hidden = true;
    return;
  }
  const elapsed = s.playing ? (performance.now() - state.statusAt) / 1000 : 0;
  const at = Math.min(s.position_s + elapsed, s.duration_s);
  $('now-position').textContent = `${secondsText(at)} of ${secondsText(s.duration_s)}${s.is_video ? ' (video)' : ''}`;
  const seek = $('seek');
  $('seek-box').hidden = !s.is_video;
  seek.max = String(s.duration_s);
  if (!state.seeking) {
    seek.value = String(at);
    seek.setAttribute('aria-valuetext', `${secondsText(at)} of ${secondsText(s.duration_s)}`);
  }
}

async function seekTo(seconds) {
  await bridge('lfd_seek', {seconds});
  await loadStatus();
  return `Moved to ${secondsText(seconds)}`;
}

// What lfd calibrate's report says of the calibration (GET /calibration_report): the gates'
// verdict, the fit, the warnings; nothing for a factory calibration.
async function reportFacts(dl, index) {
  let report = null;
  try {
    report = (await getJson(`/calibration_report?display=${index}`)).report;
  } catch (e) {
    return fact(dl, 'Calibration report', `unreadable: ${e.message}`);
  }
  if (!report) return;
  const fit = [`${report.positions} camera positions`];
  if (report.residual_rms_periods !== null) fit.push(`residual ${report.residual_rms_periods.toFixed(4)} lens periods RMS`);
  if (report.view_cone_deg !== null) fit.push(`view cone ${report.view_cone_deg.toFixed(2)} degrees`);
  fact(dl, 'Calibration report', `${report.accepted ? 'accepted' : 'refused'}: ${fit.join(', ')}`);
  if (report.gate_failures.length) fact(dl, 'Gates failed', report.gate_failures.join('; '));
  fact(dl, 'Warnings', report.warnings.length ? report.warnings.join('; ') : 'none');
  fact(dl, 'Report file', report.page || report.file);
}

async function loadStatus() {
  const s = await bridge('lfd_status');
  state.status = s;
  state.statusAt = performance.now();
  showPosition();
  $('now-showing').textContent = s.showing || 'nothing yet';
  $('now-playlist').textContent = s.playlist || 'none';
  $('now-entry').textContent = s.index >= 0 && s.entries ? `${s.index + 1} of ${s.entries}` : 'none';
  $('now-state').textContent = s.playing ? 'playing' : 'paused';
}

// --- seen from ----------------------------------------------------------------------------

// The slider runs over display 0's views, from the middle of the first (the cone's left edge) to
// the middle of the last, in half views; the service turns a view into the eye's angle and
// renders the picture (GET /seen_from, one at a time: busy means try again shortly).
const seen = {range: null, busy: false, again: false, url: ''};

function seenText(view, angle) {
  const side = Math.abs(angle) < 0.05 ? 'straight on' : `${Math.abs(angle).toFixed(1)} degrees ${angle < 0 ? 'left' : 'right'}`;
  return `${side}, view ${Number(view) + 1} of ${seen.range.views}`;
}

async function loadSeenFromRange() {
  seen.range = await getJson('/seen_from/range?display=0');
  const slider = $('seen-view');
  slider.max = String(seen.range.views - 1);
  slider.value = String((seen.range.views - 1) / 2);
}

async function renderSeenFrom() {
  if (!seen.range) return;
  if (seen.busy) { seen.again = true; return; }
  seen.busy = true;
  try {
    let busyTries = 0;
    do {
      seen.again = false;
      const view = $('seen-view').value;
      const r = await fetch(`/seen_from?display=0&view=${encodeURIComponent(view)}`, {credentials: 'same-origin'});
      if (r.status === 503 && ++busyTries < 5) {
        await new Promise((done) => setTimeout(done, 1000));
        seen.again = true;
        continue;
      }
      if (!r.ok) {
        const body = await r.json().catch(() => ({}));
        throw new Error(body.error || `HTTP ${r.status}`);
      }
      const angle = Number(r.headers.get('X-Seen-From-Angle'));
      const picture = $('seen-picture');
      if (seen.url) URL.revokeObjectURL(seen.url);
      seen.url = URL.createObjectURL(await r.blob());
      picture.src = seen.url;
      picture.alt = `Display 0 seen from ${seenText(view, angle)}`;
      picture.hidden = false;
      picture.dataset.view = view;
      $('seen-angle').textContent = seenText(view, angle);
      $('seen-view').setAttribute('aria-valuetext', seenText(view, angle));
    } while (seen.again);
  } finally {
    seen.busy = false;
  }
}

// --- content ------------------------------------------------------------------------------

function entryFields(item, durationMS = 0) {
  const fields = {uri: item.uri, durationMS};
  if (item.kind === 'rgbd photo') return {...fields, isRGBD: true};
  return {...fields, cols: item.cols, rows: item.rows, view_count: item.views, aspect: item.aspect};
}

async function playNow(item) {
  await bridge('instance_playlist', {name: 'Play now', loop: true});
  await bridge('insert_playlist_entry', {name: 'Play now', index: -1, ...entryFields(item)});
  await bridge('play_playlist', {name: 'Play now', head_index: 0});
  return `Playing ${item.name}`;
}

function renderLibrary() {
  const list = $('library');
  list.replaceChildren();
  if (!state.library.length) list.append(el('li', {text: 'The content folder is empty: upload a quilt.'}));
  for (const item of state.library) {
    const thumb = el('img', {alt: '', 'data-name': item.name, class: 'pending'});
    const layout = item.cols ? `${item.cols} x ${item.rows} views, aspect ${item.aspect}` : 'colour and depth';
    list.append(el('li', {'aria-label': item.name},
      thumb,
      el('span', {class: 'name', text: item.name}),
      el('span', {class: 'kind', text: `${item.kind}, ${item.width} x ${item.height} px, ${layout}`}),
      el('span', {class: 'actions'},
        el('button', {type: 'button', text: 'Play', onclick: () => act('Play', () => playNow(item))}),
        el('button', {type: 'button', text: 'Add', 'aria-label': `Add ${item.name} to the playlist`,
                      onclick: () => act('Add', () => addToPlaylist(item))}),
        el('button', {type: 'button', text: 'Rename', 'aria-label': `Rename ${item.name}`,
                      onclick: () => act('Rename', () => rename(item))}),
        el('button', {type: 'button', text: 'Delete', 'aria-label': `Delete ${item.name}`,
                      onclick: () => act('Delete', () => remove(item))}))));
  }
}

// The thumbnails the service makes (GET /library/thumbnail: a quilt's centre view made small),
// asked one after another: the service makes one at a time and answers busy meanwhile.
async function loadThumbnails() {
  if (state.thumbnailing) { state.thumbnailsAgain = true; return; }
  state.thumbnailing = true;
  try {
    do {
      state.thumbnailsAgain = false;
      for (const img of document.querySelectorAll('#library img.pending')) {
        for (let tries = 0; tries < 5; ++tries) {
          const r = await fetch('/library/thumbnail?name=' + encodeURIComponent(img.dataset.name), {credentials: 'same-origin'});
          if (r.status === 503) { await new Promise((done) => setTimeout(done, 500)); continue; }
          if (r.ok) img.src = URL.createObjectURL(await r.blob());
          break;
        }
        img.classList.remove('pending');
      }
    } while (state.thumbnailsAgain);
  } finally {
    state.thumbnailing = false;
  }
}

async function loadLibrary() {
  const items = (await getJson('/library')).items;
  const text = JSON.stringify(items);
  if (text === state.libraryText) return;
  state.libraryText = text;
  state.library = items;
  renderLibrary();
  act('Thumbnails', loadThumbnails);
}

async function upload(files) {
  for (const file of files) {
    if (state.config && file.size > state.config.upload_limit_bytes) {
      say(`Upload: ${file.name}: larger than the upload limit of ${state.config.upload_limit_bytes >> 20} MiB`, true);
      continue;
    }
    const r = await fetch('/library/upload', {method: 'POST', credentials: 'same-origin', body: file,
                                              headers: {'Content-Type': 'application/octet-stream',
                                                        'X-File-Name': encodeURIComponent(file.name)}});
    const reply = await r.json().catch(() => ({}));
    if (!r.ok) say(`Upload: ${reply.error || 'HTTP ' + r.status}`, true);
    else say(`Uploaded ${reply.name} (${reply.kind})`, false);
  }
  $('upload').value = '';
  await loadLibrary();
}

async function rename(item) {
  const name = prompt(`New name for ${item.name}`, item.name);
  if (!name || name === item.name) return null;
  const done = await postJson('/library/rename', {name: item.name, new_name: name});
  await loadLibrary();
  return `Renamed to ${done.name}`;
}

async function remove(item) {
  if (!confirm(`Delete ${item.name} from the content folder?`)) return null;
  await postJson('/library/delete', {name: item.name});
  await loadLibrary();
  return `Deleted ${item.name}`;
}

async function addToPlaylist(item) {
  const name = $('add-target').value;
  if (!name) throw new Error('make a playlist first (Playlists)');
  await bridge('insert_playlist_entry', {name, index: -1, ...entryFields(item, 5000)});
  await loadPlaylists();
  return `Added ${item.name} to ${name}`;
}

// --- playlists ----------------------------------------------------------------------------

// A playlist written again in the order and with the settings given: Bridge's instance_playlist
// (which replaces) and one insert_playlist_entry per entry.
async function writePlaylist(name, loop, entries) {
  await bridge('instance_playlist', {name, loop});
  for (const e of entries) {
    const fields = {uri: e.uri, durationMS: e.durationMS};
    if (e.isRGBD) fields.isRGBD = true;
    else Object.assign(fields, {cols: e.cols, rows: e.rows, view_count: e.views, aspect: e.aspect});
    await bridge('insert_playlist_entry', {name, index: -1, ...fields});
  }
  await loadPlaylists();
}

function moveEntry(p, from, to) {
  const entries = p.entries.slice();
  const [moved] = entries.splice(from, 1);
  entries.splice(to, 0, moved);
  return writePlaylist(p.name, p.loop, entries).then(() => `Moved ${moved.name} in ${p.name}`);
}

// Reordering by dragging an entry's handle (pointer events: mouse, pen and touch alike); the
// entry's Up and Down buttons do the same from the keyboard.
function dragToReorder(list, p) {
  let dragged = null;
  list.addEventListener('pointerdown', (ev) => {
    const handle = ev.target.closest('.handle');
    if (!handle) return;
    dragged = handle.closest('li');
    state.dragging = true;  // an event's re-render waits for the drop
    dragged.classList.add('dragging');
    handle.setPointerCapture(ev.pointerId);
    ev.preventDefault();
  });
  list.addEventListener('pointermove', (ev) => {
    if (!dragged) return;
    const over = document.elementFromPoint(ev.clientX, ev.clientY);
    const target = over && over.closest('li');
    if (!target || target === dragged || target.parentNode !== list) return;
    const box = target.getBoundingClientRect();
    list.insertBefore(dragged, ev.clientY < box.top + box.height / 2 ? target : target.nextSibling);
  });
  const drop = () => {
    if (!dragged) return;
    const from = Number(dragged.dataset.index);
    const to = [...list.children].indexOf(dragged);
    dragged.classList.remove('dragging');
    dragged = null;
    state.dragging = false;
    if (from !== to) act('Reorder', () => moveEntry(p, from, to));
    else renderPlaylists();
  };
  list.addEventListener('pointerup', drop);
  list.addEventListener('pointercancel', drop);
}

function renderPlaylists() {
  const list = $('playlist-list');
  list.replaceChildren();
  const target = $('add-target');
  const chosen = target.value;
  target.replaceChildren();
  const lists = state.playlists.filter((p) => p.name !== 'Play now');
  for (const p of lists) target.append(el('option', {value: p.name, text: p.name}));
  if (lists.some((p) => p.name === chosen)) target.value = chosen;
  if (!lists.length) list.append(el('li', {text: 'No playlists yet.'}));
  for (const p of lists) {
    const isAutostart = state.autostart && state.autostart.name === p.name;
    const entries = el('ol', {class: 'entries', 'aria-label': `Entries of ${p.name}`});
    p.entries.forEach((e, i) => {
      const durationId = `duration-${encodeURIComponent(p.name)}-${i}`;
      const duration = el('input', {id: durationId, type: 'number', min: '0', step: '0.5',
                                    value: String((e.durationMS || 0) / 1000)});
      duration.addEventListener('change', () => act('Duration', () => {
        const changed = p.entries.slice();
        changed[i] = {...e, durationMS: Math.round(Number(duration.value) * 1000)};
        return writePlaylist(p.name, p.loop, changed).then(() => `Duration of ${e.name} changed`);
      }));
      entries.append(el('li', {'data-index': String(i), 'aria-label': `${i + 1}. ${e.name}`},
        el('span', {class: 'handle', 'aria-hidden': 'true', title: 'drag to reorder', text: '\u2261'}),
        el('span', {class: 'file', text: e.name}),
        el('label', {for: durationId, text: 'Seconds'}), duration,
        el('button', {type: 'button', text: 'Up', 'aria-label': `Move ${e.name} up`, disabled: i === 0,
                      onclick: () => act('Reorder', () => moveEntry(p, i, i - 1))}),
        el('button', {type: 'button', text: 'Down', 'aria-label': `Move ${e.name} down`,
                      disabled: i === p.entries.length - 1, onclick: () => act('Reorder', () => moveEntry(p, i, i + 1))}),
        el('button', {type: 'button', text: 'Remove', 'aria-label': `Remove ${e.name} from ${p.name}`,
                      onclick: () => act('Remove', () => writePlaylist(p.name, p.loop, p.entries.filter((_, j) => j !== i))
                                                        .then(() => `Removed ${e.name}`))})));
    });
    dragToReorder(entries, p);
    const loopId = `loop-${encodeURIComponent(p.name)}`;
    const loop = el('input', {id: loopId, type: 'checkbox', checked: p.loop});
    loop.addEventListener('change', () => act('Loop', () => writePlaylist(p.name, loop.checked, p.entries)
                                                          .then(() => `${p.name}: loop ${loop.checked ? 'on' : 'off'}`)));
    list.append(el('li', {'aria-label': `Playlist ${p.name}`},
      el('h3', {text: p.name}),
      isAutostart ? el('p', {class: 'autostart', text: 'Plays when the service starts'}) : null,
      entries,
      el('div', {class: 'actions'},
        el('button', {type: 'button', text: 'Play', 'aria-label': `Play ${p.name}`,
                      onclick: () => act('Play', async () => {
                        await bridge('play_playlist', {name: p.name, head_index: 0});
                        return `Playing ${p.name}`;
                      })}),
        el('span', {}, loop, el('label', {for: loopId, text: ' Loop'})),
        el('button', {type: 'button', text: 'Autostart', 'aria-label': `Play ${p.name} when the service starts`,
                      'aria-pressed': isAutostart ? 'true' : 'false',
                      onclick: () => act('Autostart', async () => {
                        await bridge('set_named_autostart_playlist', {playlist_name: p.name, head_index: 0});
                        await loadPlaylists();
                        return `${p.name} plays when the service starts`;
                      })}),
        el('button', {type: 'button', text: 'Delete', 'aria-label': `Delete playlist ${p.name}`,
                      onclick: () => act('Delete', async () => {
                        if (!confirm(`Delete the playlist ${p.name}?`)) return null;
                        await bridge('delete_playlist', {name: p.name});
                        await loadPlaylists();
                        return `Deleted ${p.name}`;
                      })}))));
  }
}

async function loadPlaylists() {
  const reply = await getJson('/playlists');
  // Drawn again only when something changed: an event for another's change keeps focus here.
  const text = JSON.stringify(reply);
  if (text === state.playlistsText) return;
  state.playlistsText = text;
  state.playlists = reply.playlists;
  state.autostart = reply.autostart;
  if (!state.dragging) renderPlaylists();
}

// --- live state ---------------------------------------------------------------------------

function listen() {
  const url = `ws://${location.hostname}:${state.config.events_port}/event_source`;
  const socket = new WebSocket(url);
  socket.addEventListener('open', () => {
    $('connection').textContent = 'live';
    socket.send(JSON.stringify({subscribe_orchestration_events: state.orchestration}));
  });
  socket.addEventListener('message', (m) => {
    let event = '';
    try { event = JSON.parse(m.data).payload.value.event.value; } catch (e) { return; }
    act('Status', loadStatus);
    if (/^Playlist/.test(event)) act('Playlists', loadPlaylists);
    if (/(New Item Playing|Transport)/.test(event) && !$('display').hidden) act('Seen from', renderSeenFrom);
  });
  socket.addEventListener('close', () => {
    $('connection').textContent = 'reconnecting';
    setTimeout(listen, 2000);
  });
}

// --- start --------------------------------------------------------------------------------

function wire() {
  window.addEventListener('hashchange', showView);
  showView();
  $('upload-button').addEventListener('click', () => $('upload').click());
  $('upload').addEventListener('change', (e) => act('Upload', () => upload(e.target.files)));
  const drop = $('drop');
  drop.addEventListener('dragover', (e) => { e.preventDefault(); drop.classList.add('over'); });
  drop.addEventListener('dragleave', () => drop.classList.remove('over'));
  drop.addEventListener('drop', (e) => {
    e.preventDefault();
    drop.classList.remove('over');
    act('Upload', () => upload(e.dataTransfer.files));
  });
  $('new-playlist').addEventListener('submit', (e) => {
    e.preventDefault();
    const name = $('new-playlist-name').value.trim();
    act('Create', async () => {
      await bridge('instance_playlist', {name, loop: true});
      $('new-playlist-name').value = '';
      await loadPlaylists();
      $('add-target').value = name;
      return `Made the playlist ${name}`;
    });
  });
  $('seen-view').addEventListener('change', () => act('Seen from', renderSeenFrom));
  const seek = $('seek');
  seek.addEventListener('input', () => { state.seeking = true; });
  seek.addEventListener('change', () => act('Seek', () => seekTo(Number(seek.value)).finally(() => { state.seeking = false; })));
  setInterval(showPosition, 250);
  for (const verb of ['play', 'pause', 'next', 'previous'])
    $(verb).addEventListener('click', () => act(verb, () => bridge('transport_control_' + verb).then(loadStatus)));
}

async function start() {
  wire();
  await act('Start', async () => {
    state.config = await getJson('/console/config');
    await enterOrchestration();
    await loadStatus();
    await Promise.all([loadDisplays(), loadLibrary(), loadPlaylists(), loadSeenFromRange()]);
    listen();
    act('Seen from', renderSeenFrom);
    document.body.dataset.ready = 'true';
  });
}

start();
