// lfd serve's console (docs/console.md) in Debian's headless Chromium, driven by the pinned
// puppeteer-core, against a real `lfd serve` on Xvfb with the test display's calibration. The
// harness starts (and restarts) the service itself: the autostart case needs a restart, the
// --listen case another address.
//   LFD_EXE=... CALIBRATION=... node console_test.js display|upload-play|playlist|refusals|foreign-origin|listen|seen-from|seek
// LFD_CONSOLE_SHOTS=DIR keeps the screenshots (docs/console.md's come from here).
'use strict';
const fs = require('fs');
const os = require('os');
const path = require('path');
const http = require('http');
const {spawn, execFileSync} = require('child_process');
const puppeteer = require('puppeteer-core');
const {check, waitFor, expectedCalibration} = require('./common.js');
const {quiltPng, viewColourQuiltPng} = require('./quilt_png.js');

const LFD = process.env.LFD_EXE;
const CALIBRATION = process.env.CALIBRATION;
const SHOTS = process.env.LFD_CONSOLE_SHOTS || '';
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'lfd-console-'));
const content = path.join(tmp, 'content');
const stateFile = path.join(tmp, 'state', 'playlists.json');
const A = path.join(tmp, 'a_qs4x3a0.75.png');
const B = path.join(tmp, 'b_qs4x3a0.75.png');
fs.writeFileSync(A, quiltPng(4, 3, 192, 256));
fs.writeFileSync(B, quiltPng(4, 3, 96, 128));

let xvfb = null, serve = null, browser = null, display = '';
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

function cleanup() {
  for (const p of [serve, xvfb]) if (p && p.exitCode === null) p.kill('SIGTERM');
  fs.rmSync(tmp, {recursive: true, force: true});
}
process.on('exit', cleanup);

async function startXvfb() {
  const cal = expectedCalibration(CALIBRATION);
  fs.mkdirSync(path.join(tmp, 'fb'));
  xvfb = spawn('Xvfb', ['-displayfd', '3', '-screen', '0', `${cal.screenW.value}x${cal.screenH.value}x24`,
                        '-fbdir', path.join(tmp, 'fb'), '-nolisten', 'tcp'], {stdio: ['ignore', 'ignore', 'ignore', 'pipe']});
  display = await new Promise((resolve) => xvfb.stdio[3].once('data', (d) => resolve(':' + String(d).trim())));
}

async function startServe(args = [], base = 'http://127.0.0.1:33334') {
  const log = fs.openSync(path.join(tmp, 'serve.log'), 'a');
  serve = spawn(LFD, ['serve', '--calibration', CALIBRATION, '--state-file', stateFile, '--content', content, ...args],
                {env: {...process.env, DISPLAY: display}, stdio: ['ignore', log, log]});
  await waitFor('lfd serve answers', async () => {
    if (serve.exitCode !== null) check(false, 'lfd serve exited at start: ' + fs.readFileSync(path.join(tmp, 'serve.log'), 'utf8'));
    return fetch(base + '/').then(() => true, () => false);
  }, 30000);
  // The service answering is the one just started, not another on the fixed ports.
  if (base === 'http://127.0.0.1:33334') check((await status()).pid === serve.pid, 'the lfd serve answering is the one this test started');
}

async function stopServe() {
  const exited = new Promise((r) => serve.once('exit', r));
  serve.kill('SIGTERM');
  await exited;
}

async function launch() {
  browser = await puppeteer.launch({executablePath: '/usr/bin/chromium', headless: true,
                                    args: ['--no-sandbox', '--disable-gpu', '--host-resolver-rules=MAP evil.example 127.0.0.1']});
  return browser;
}

async function openConsole(base = 'http://localhost:33334', view = '#display', viewport = {width: 1024, height: 900}) {
  const page = await browser.newPage();
  await page.setViewport(viewport);
  await page.setBypassCSP(true);  // axe-core is injected into the page
  page.on('pageerror', (e) => check(false, 'the page threw: ' + e.message));
  page.on('dialog', (d) => d.accept(d.type() === 'prompt' ? page.promptAnswer || '' : undefined));
  await page.goto(base + '/' + view);
  await page.waitForSelector('body[data-ready]', {timeout: 20000});
  return page;
}

async function show(page, view) {
  await page.evaluate((v) => { location.hash = v; }, view);
  await page.waitForFunction((v) => !document.getElementById(v.slice(1)).hidden, {}, view);
}

// `selector`: only that element (scrolled into view), else the viewport.
async function shot(page, name, selector = '') {
  if (!SHOTS) return;
  fs.mkdirSync(SHOTS, {recursive: true});
  const target = selector ? await page.$(selector) : page;
  // The fixed transport bar would cover part of an element shown alone.
  const hideFooter = selector && selector !== 'footer';
  if (hideFooter) await page.$eval('footer', (f) => { f.style.visibility = 'hidden'; });
  await target.screenshot({path: path.join(SHOTS, name + '.png')});
  if (hideFooter) await page.$eval('footer', (f) => { f.style.visibility = ''; });
}

async function bridge(endpoint, body = {}) {
  const r = await fetch('http://127.0.0.1:33334/' + endpoint, {method: 'PUT', body: JSON.stringify(body)});
  return r.json();
}
async function status() { return (await bridge('lfd_status')).payload.value; }
async function playlists() { return (await fetch('http://127.0.0.1:33334/playlists')).json(); }
const folder = () => fs.readdirSync(content).sort();

// axe-core (pinned) on what the page shows now: no WCAG 2.x A/AA violation.
async function axe(page, view) {
  await page.addScriptTag({path: require.resolve('axe-core/axe.min.js')});
  const result = await page.evaluate(() => axe.run(document, {runOnly: {type: 'tag', values: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa']}}));
  const lines = result.violations.map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`);
  check(result.violations.length === 0, `axe-core finds no WCAG A/AA violation on ${view}${lines.length ? ': ' + lines.join('; ') : ''}`);
}

// A click on what `selector` names, again when an event re-drew the list under it.
async function click(page, selector) {
  for (let attempt = 0; ; ++attempt) {
    try {
      const element = await page.waitForSelector(selector, {timeout: 10000});
      return await element.click();
    } catch (e) {
      if (attempt >= 5 || !/detached|not clickable|no node/i.test(e.message)) throw e;
      await sleep(200);
    }
  }
}

async function uploadThroughPicker(page, files) {
  await show(page, '#content');
  const [chooser] = await Promise.all([page.waitForFileChooser(), page.click('aria/Upload[role="button"]')]);
  await chooser.accept(files);
  for (const f of files) await page.waitForSelector(`aria/${path.basename(f)}[role="listitem"]`, {timeout: 20000});
}

// A transport button, by its accessible name, in the region named "Transport".
async function transport(page, name) {
  const region = await page.$('aria/Transport[role="region"]');
  const button = region && await region.$(`aria/${name}[role="button"]`);
  check(button !== null, `the transport has a button named "${name}"`);
  await button.click();
}

async function libraryItem(page, name) {
  const item = await page.$(`aria/${name}[role="listitem"]`);
  check(item !== null, `the library lists ${name} as a list item named by its file name`);
  return item;
}

// Files dropped on the page's drop zone (the page's own upload code), and the one-line message.
async function dropFiles(page, files) {
  await show(page, '#content');
  await page.evaluate(() => { document.getElementById('message').textContent = ''; });
  await page.evaluate((files) => {
    const dt = new DataTransfer();
    for (const f of files) dt.items.add(new File([Uint8Array.from(atob(f.base64), (c) => c.charCodeAt(0))], f.name));
    document.getElementById('drop').dispatchEvent(new DragEvent('drop', {dataTransfer: dt, bubbles: true, cancelable: true}));
  }, files.map((f) => ({name: f.name, base64: f.bytes.toString('base64')})));
  await page.waitForFunction(() => document.getElementById('message').textContent !== '', {timeout: 20000});
  return page.$eval('#message', (m) => m.textContent);
}

function screenPsnr(quilt) {
  const screen = path.join(tmp, 'screen.png'), panel = path.join(tmp, 'panel.png');
  execFileSync('python3', [path.join(__dirname, '../../../scripts/xwd-to-png.py'), path.join(tmp, 'fb', 'Xvfb_screen0'), screen]);
  execFileSync(LFD, ['interlace', '--calibration', CALIBRATION, '--quilt', quilt, '--out', panel], {stdio: 'ignore'});
  const r = JSON.parse(execFileSync(LFD, ['compare', screen, panel, '--json']));
  return r.identical ? Infinity : r.psnr_db;
}

// --- the cases ----------------------------------------------------------------------------

const cases = {};

cases.display = async () => {
  const cal = expectedCalibration(CALIBRATION);
  const o = (await bridge('enter_orchestration')).payload.value;
  const device = (await bridge('available_output_devices', {orchestration: o})).payload.value['0'].value;
  const quilt = JSON.parse(device.defaultQuilt.value);
  const page = await openConsole();
  const card = await page.$(`aria/Display 0: ${cal.serial}[role="listitem"]`);
  check(card !== null, `the page lists display 0 named by its serial ${cal.serial}`);
  const text = await card.evaluate((e) => e.innerText);
  check(text.includes(`Serial\n${cal.serial}`) || text.includes(`Serial\t${cal.serial}`), 'the display shows its serial');
  const views = quilt.tileX * quilt.tileY;
  check(new RegExp(`Views\\s+${views}\\b`).test(text), `the display shows its ${views} views`);
  check(new RegExp(`View cone\\s+${cal.viewCone.value} degrees`).test(text), 'the display shows its view cone');
  check(/factory visual\.json/.test(text), 'the display shows its calibration source');
  await shot(page, 'console-display');
  await page.setViewport({width: 390, height: 844});
  await shot(page, 'console-display-phone');
};

cases['upload-play'] = async () => {
  const page = await openConsole();
  await uploadThroughPicker(page, [A]);
  check(JSON.stringify(folder()) === JSON.stringify(['a_qs4x3a0.75.png']), 'the upload is stored in the content folder');
  const item = await libraryItem(page, 'a_qs4x3a0.75.png');
  // Its thumbnail is the service's: the centre view (view 6 of 4x3 tiles of 192x256) made small.
  await page.waitForFunction(() => {
    const img = document.querySelector('#library img');
    return img && !img.classList.contains('pending') && img.complete && img.naturalWidth > 0;
  }, {timeout: 20000});
  const size = await page.$eval('#library img', (img) => [img.naturalWidth, img.naturalHeight]);
  check(size[0] === 120 && size[1] === 160, `the library shows the service's thumbnail, the centre view made small (${size.join('x')})`);
  const play = await item.$('aria/Play[role="button"]');
  check(play !== null, 'the library item holds a "Play" button');
  await play.click();
  await waitFor('the service plays the uploaded quilt', async () => {
    const s = await status();
    return s.playlist === 'Play now' && /a_qs4x3a0\.75/.test(s.showing);
  }, 20000);
  await shot(page, 'console-content');
  await sleep(2000);  // the frame on the Xvfb screen
  const psnr = screenPsnr(A);
  check(psnr >= 40, `the Xvfb screen equals lfd interlace of the quilt played from the library (PSNR ${psnr} dB >= 40)`);
  // Transport: Pause and Play from the page.
  await transport(page, 'Pause');
  await waitFor('Pause pauses', async () => !(await status()).playing);
  await transport(page, 'Play');
  await waitFor('Play plays again', async () => (await status()).playing);
  check(true, 'the transport buttons "Pause" and "Play" drive the display');
};

async function dragBefore(page, list, from, to) {
  await sleep(1000);  // the events of the inserts have re-drawn the list
  const handles = await page.$$(`${list} li .handle`);
  const target = await (await page.$$(`${list} li`))[to].boundingBox();
  const box = await handles[from].boundingBox();
  check(box !== null && target !== null, 'the entries are on screen to be dragged');
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(target.x + 20, target.y + 3, {steps: 8});
  await page.mouse.up();
}

cases.playlist = async () => {
  const page = await openConsole();
  await uploadThroughPicker(page, [A, B]);
  await show(page, '#playlists');
  await page.type('aria/New playlist', 'Tour');
  await click(page, 'aria/Create');
  await waitFor('the playlist Tour is made', async () => (await playlists()).playlists.some((p) => p.name === 'Tour'));
  await show(page, '#content');
  await page.waitForFunction(() => document.getElementById('add-target').value === 'Tour');
  for (const name of ['a_qs4x3a0.75.png', 'b_qs4x3a0.75.png']) {
    await click(page, `aria/Add ${name} to the playlist`);
    await waitFor(`${name} added`, async () => (await playlists()).playlists.find((p) => p.name === 'Tour').entries.some((e) => e.name === name));
  }
  await show(page, '#playlists');
  await page.waitForFunction(() => document.querySelectorAll('#playlist-list .entries li').length === 2);
  await shot(page, 'console-playlists-before');
  // Dragged: b above a.
  await dragBefore(page, '#playlist-list .entries', 1, 0);
  await waitFor('the dragged order is kept', async () => {
    const tour = (await playlists()).playlists.find((p) => p.name === 'Tour');
    return tour.entries.map((e) => e.name).join(',') === 'b_qs4x3a0.75.png,a_qs4x3a0.75.png';
  });
  check(true, 'dragging b above a reorders the playlist (the service keeps b, a)');
  await page.waitForFunction(() => /b_qs/.test(document.querySelector('#playlist-list .entries li').textContent));
  await click(page, 'aria/Play Tour');
  await waitFor('Tour plays b first', async () => {
    const s = await status();
    return s.playlist === 'Tour' && s.index === 0 && /b_qs4x3a0\.75/.test(s.showing);
  }, 20000);
  await transport(page, 'Next');
  await waitFor('Next shows a', async () => {
    const s = await status();
    return s.playlist === 'Tour' && s.index === 1 && /a_qs4x3a0\.75/.test(s.showing);
  }, 20000);
  check(true, 'the reordered playlist plays in the new order (b, then a)');
  await click(page, 'aria/Play Tour when the service starts');
  await waitFor('Tour is the autostart playlist', async () => ((await playlists()).autostart || {}).name === 'Tour');
  await page.waitForSelector('.autostart');
  await shot(page, 'console-playlists');
  for (const view of ['#display', '#content', '#playlists']) {
    await show(page, view);
    await axe(page, view);
  }
  await page.setViewport({width: 390, height: 844});
  await show(page, '#content');
  await shot(page, 'console-content-phone');
  await axe(page, '#content at phone size');
  await page.close();
  // The autostart playlist after a restart.
  await stopServe();
  await startServe();
  await waitFor('the service plays Tour after a restart', async () => {
    const s = await status();
    return s.playlist === 'Tour' && s.playing;
  }, 20000);
  check(true, 'the autostart playlist set in the page plays after the service restarts');
};

cases.refusals = async () => {
  await stopServe();
  await startServe(['--max-upload', '1']);  // A (1.1 MB) is over it
  const page = await openConsole();
  const before = folder();
  const messages = [
    [{name: 'notes_qs4x3a0.75.png', bytes: Buffer.from('not an image at all\n'.repeat(100))}, /not a quilt image/],
    [{name: '../evil_qs4x3a0.75.png', bytes: fs.readFileSync(B)}, /not a plain file name/],
    [{name: 'big_qs4x3a0.75.png', bytes: fs.readFileSync(A)}, /larger than the upload limit of 1 MiB/],
  ];
  for (const [file, expected] of messages) {
    const message = await dropFiles(page, [file]);
    check(expected.test(message) && !message.includes('\n'), `${file.name}: the page says why in one line ("${message}")`);
    check(JSON.stringify(folder()) === JSON.stringify(before), `${file.name}: the content folder is unchanged`);
  }
  await shot(page, 'console-refused');
  // The service's own refusal of an oversized body (the page checks first; a script does not).
  const r = await fetch('http://127.0.0.1:33334/library/upload', {method: 'POST', headers: {'X-File-Name': 'big.png'}, body: fs.readFileSync(A)});
  const body = await r.json();
  check(r.status === 413 && /upload limit/.test(body.error), `an oversized upload from a script: 413 "${body.error}"`);
  check(JSON.stringify(folder()) === JSON.stringify(before), 'the content folder is unchanged');
};

cases['foreign-origin'] = async () => {
  // A quilt in the library and shown, paused: what a foreign page would change.
  const up = await fetch('http://127.0.0.1:33334/library/upload', {method: 'POST', headers: {'X-File-Name': 'a_qs4x3a0.75.png'}, body: fs.readFileSync(A)});
  check(up.ok, 'a script (no Origin) uploads');
  const o = (await bridge('enter_orchestration')).payload.value;
  await bridge('instance_playlist', {orchestration: o, name: 'Kept', loop: true});
  await bridge('insert_playlist_entry', {orchestration: o, name: 'Kept', uri: path.join(content, 'a_qs4x3a0.75.png'), cols: 4, rows: 3, aspect: 0.75});
  await bridge('play_playlist', {orchestration: o, name: 'Kept'});
  await bridge('transport_control_pause', {orchestration: o});
  await waitFor('paused', async () => !(await status()).playing);
  const evil = http.createServer((req, res) => {
    res.writeHead(200, {'Content-Type': 'text/html'});
    res.end(`<!doctype html><title>evil</title><script>
      const base = 'http://localhost:33334';
      const tries = [
        fetch(base + '/transport_control_play', {method: 'PUT', body: JSON.stringify({orchestration: '${o}'})}),
        fetch(base + '/transport_control_play', {method: 'POST', mode: 'no-cors', body: JSON.stringify({orchestration: '${o}'})}),
        fetch(base + '/library/delete', {method: 'POST', mode: 'no-cors', body: JSON.stringify({name: 'a_qs4x3a0.75.png'})}),
        fetch(base + '/library/upload', {method: 'POST', mode: 'no-cors', body: new Blob(['x'])}),
        fetch(base + '/library/upload', {method: 'POST', headers: {'X-File-Name': 'b_qs4x3a0.75.png'}, body: new Blob(['x'])}),
        fetch(base + '/library'),
      ].map((p) => p.then((r) => r.type + ' ' + r.status, (e) => 'refused'));
      Promise.all(tries).then((r) => { document.title = 'done ' + r.join(','); });
    </script>`);
  });
  await new Promise((r) => evil.listen(0, '127.0.0.1', r));
  const page = await browser.newPage();
  await page.goto(`http://evil.example:${evil.address().port}/`);
  await page.waitForFunction(() => document.title.startsWith('done'), {timeout: 20000});
  const results = await page.title();
  evil.close();
  console.log('the foreign page saw: ' + results);
  check(!/basic 200|cors 200/.test(results), 'the foreign page got no answer it may read');
  await sleep(500);
  const s = await status();
  check(!s.playing, 'a page from another origin cannot play');
  check(JSON.stringify(folder()) === JSON.stringify(['a_qs4x3a0.75.png']), 'a page from another origin cannot delete or upload');
  const log = fs.readFileSync(path.join(tmp, 'serve.log'), 'utf8');
  check(/refused .*origin http:\/\/evil\.example/.test(log), 'the service logs the refusals (403)');
};

// The mean colour of the central 1/part (each way) of a PNG, read in the page's canvas.
async function centralMean(page, pngBytes, part = 10) {
  return page.evaluate(async (b64, part) => {
    const img = new Image();
    img.src = 'data:image/png;base64,' + b64;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.naturalWidth;
    c.height = img.naturalHeight;
    const g = c.getContext('2d');
    g.drawImage(img, 0, 0);
    const w = Math.max(1, Math.round(c.width / part)), h = Math.max(1, Math.round(c.height / part));
    const d = g.getImageData(Math.round((c.width - w) / 2), Math.round((c.height - h) / 2), w, h).data;
    const sum = [0, 0, 0];
    for (let i = 0; i < d.length; i += 4) for (let ch = 0; ch < 3; ++ch) sum[ch] += d[i + ch];
    return sum.map((v) => v / (d.length / 4));
  }, Buffer.from(pngBytes).toString('base64'), part);
}

// A colour of viewColourQuiltPng's views: the blue share of red and blue (0: view 0's side, 1:
// the last view's), and the green share of all (the middle views').
const blueShare = (rgb) => rgb[2] / Math.max(1, rgb[0] + rgb[2]);
const greenShare = (rgb) => rgb[1] / Math.max(1, rgb[0] + rgb[1] + rgb[2]);

cases['seen-from'] = async () => {
  const o = (await bridge('enter_orchestration')).payload.value;
  const quilt = JSON.parse((await bridge('available_output_devices', {orchestration: o})).payload.value['0'].value.defaultQuilt.value);
  const views = quilt.tileX * quilt.tileY;
  // A quilt of the display's views, each one flat colour, played from the library.
  const name = `views_qs${quilt.tileX}x${quilt.tileY}a0.75.png`;
  const file = path.join(tmp, name);
  fs.writeFileSync(file, viewColourQuiltPng(quilt.tileX, quilt.tileY, 48, 64));
  const page = await openConsole();
  await uploadThroughPicker(page, [file]);
  await (await (await libraryItem(page, name)).$('aria/Play[role="button"]')).click();
  await waitFor('the view-colour quilt plays', async () => new RegExp(name.replace('.', '\\.')).test((await status()).showing), 20000);
  await sleep(1000);
  const panel = path.join(tmp, 'views-panel.png');
  execFileSync(LFD, ['interlace', '--calibration', CALIBRATION, '--quilt', file, '--out', panel], {stdio: 'ignore'});
  await show(page, '#display');
  const range = await (await fetch('http://127.0.0.1:33334/seen_from/range?display=0')).json();
  check(range.views === views && range.first_view_deg < 0 && range.last_view_deg > 0,
        `the slider spans the ${views} views, ${range.first_view_deg.toFixed(2)} to ${range.last_view_deg.toFixed(2)} degrees`);
  const slider = await page.$('aria/Seen from[role="slider"]');
  check(slider !== null, 'the "Seen from" slider has its accessible name');
  for (const [key, view, angle] of [['Home', 0, range.first_view_deg], ['End', views - 1, range.last_view_deg]]) {
    await slider.focus();
    await page.keyboard.press(key);
    await page.waitForFunction((v) => {
      const img = document.getElementById('seen-picture');
      return img.dataset.view === String(v) && img.complete && img.naturalWidth > 0;
    }, {timeout: 30000}, view);
    const shown = await page.$eval('#seen-picture', async (img) => {
      const c = document.createElement('canvas');
      c.width = img.naturalWidth;
      c.height = img.naturalHeight;
      c.getContext('2d').drawImage(img, 0, 0);
      return new Promise((r) => c.toBlob((b) => b.arrayBuffer().then((a) => r(Array.from(new Uint8Array(a)))), 'image/png'));
    });
    const seen = await centralMean(page, Buffer.from(shown));
    const side = view ? 'right' : 'left';
    console.log(`seen from the ${side} end (${angle.toFixed(2)} degrees): mean colour [${seen.map(Math.round)}]`);
    // At the cone's edge a lens sends its edge view and, through the width of a subpixel, the
    // other edge's across the wrap (docs/display-model.md): the edge view dominates, the middle
    // views are absent.
    check((view ? blueShare(seen) > 0.6 : blueShare(seen) < 0.4) && greenShare(seen) < 0.15,
          `seen from the cone's ${side} edge the page shows the ${side} edge view's content (blue share ${blueShare(seen).toFixed(2)}, green share ${greenShare(seen).toFixed(2)})`);
    // lfd simulate of the same panel picture: a camera at the same eye looking at the panel centre
    // whose picture spans the same central tenth of the panel (across its width, foreshortened).
    const rad = angle * Math.PI / 180;
    const capture = path.join(tmp, `simulate-${view}.png`);
    const fov = 2 * Math.atan(range.panel_width_m / 20 * Math.cos(rad) / range.distance_m) * 180 / Math.PI;
    const across = 48, down = Math.round(48 * range.panel_height_m / range.panel_width_m);
    execFileSync(LFD, ['simulate', '--calibration', CALIBRATION, '--panel', panel, '--out', capture, '--camera-pos',
                       `${(range.distance_m * Math.sin(rad)).toFixed(6)},0,${(range.distance_m * Math.cos(rad)).toFixed(6)}`,
                       '--fov', fov.toFixed(4), '--size', `${across}x${down}`, '--exposure', String(1 / 3)], {stdio: 'ignore'});
    // Its camera pixels cover two panel pixels: a lens shows a channel fully (up to 3 times the
    // panel's mean light) or not at all, which a camera pixel of 8 bits would clip; a third of
    // the exposure keeps it all, and the mean is scaled back.
    const simulated = (await centralMean(page, fs.readFileSync(capture), 1)).map((v) => 3 * v);
    const colourGap = Math.max(...seen.map((v, ch) => Math.abs(v - simulated[ch])));
    check(Math.abs(blueShare(seen) - blueShare(simulated)) <= 0.05 && colourGap <= 20,
          `and lfd simulate of the same panel sees the same there (colours [${seen.map(Math.round)}] and [${simulated.map(Math.round)}], blue shares ${blueShare(seen).toFixed(2)} and ${blueShare(simulated).toFixed(2)})`);
    await shot(page, view ? 'console-seen-from-right' : 'console-seen-from-left', '#display .seen');
  }
  // Bounded: a bad angle is refused in one line, and the route says busy (503) rather than queueing.
  const bad = await fetch('http://127.0.0.1:33334/seen_from?display=0&angle=95');
  check(bad.status === 400 && /angle/.test((await bad.json()).error), 'an angle outside the limits is refused (400)');
  await axe(page, '#display with "Seen from"');
  await page.close();  // its own pictures (asked at each new entry) would make the burst's busy
  await waitFor('a picture the page asked is done', async () =>
    (await fetch('http://127.0.0.1:33334/seen_from?display=0&angle=0&height=16')).status === 200);
  const burst = await Promise.all(Array.from({length: 4}, () => fetch('http://127.0.0.1:33334/seen_from?display=0&angle=0&height=512')));
  const codes = burst.map((r) => r.status);
  check(codes.every((c) => c === 200 || c === 503) && codes.includes(200),
        `four at once: each rendered or answered busy, none queued past its turn (${codes.join(',')})`);
};

cases.seek = async () => {
  // A quilt video of 6 s (60 frames of 2x2 views) made by lfd record of the repository's demo scene.
  execFileSync(LFD, ['record', '--scene', path.join(__dirname, '../../../data/scenes/demo.ply'), '--views', '4', '--cols', '2',
                     '--rows', '2', '--size', '48x32', '--chunks', '8', '--path', 'turntable', '--seconds', '6', '--fps', '10',
                     '--out', path.join(tmp, 'clip.mp4')], {env: {...process.env, DISPLAY: display}, stdio: 'ignore'});
  const made = fs.readdirSync(tmp).find((f) => /^clip_qs.*\.mp4$/.test(f));
  check(made !== undefined, `lfd record made a quilt video (${made})`);
  const page = await openConsole();
  await uploadThroughPicker(page, [path.join(tmp, made)]);
  await (await (await libraryItem(page, made)).$('aria/Play[role="button"]')).click();
  await waitFor('the video plays', async () => {
    const s = await status();
    return s.is_video && s.duration_s > 5 && s.playing;
  }, 20000);
  await transport(page, 'Pause');
  await waitFor('paused', async () => !(await status()).playing);
  const seek = await page.waitForSelector('aria/Seek[role="slider"]', {visible: true, timeout: 10000});
  check(seek !== null, 'a video shows the transport\'s slider named "Seek"');
  // The slider moved to 4 s (what a drag ends with: input events, then change).
  await page.$eval('#seek', (e) => {
    e.value = '4';
    e.dispatchEvent(new Event('input'));
    e.dispatchEvent(new Event('change'));
  });
  await waitFor('the service is at 4 s', async () => Math.abs((await status()).position_s - 4) < 0.15, 10000);
  check(true, 'the page\'s "Seek" moves the video to 4 s (lfd_status position_s)');
  await show(page, '#display');
  // The page's position as seconds ("0:04.0 of 0:06.0 (video)").
  const shownAt = () => page.$eval('#now-position', (e) => {
    const m = /^(\d+):(\d+\.\d)/.exec(e.textContent);
    return m ? 60 * Number(m[1]) + Number(m[2]) : NaN;
  });
  await waitFor('the page shows 4 s', async () => Math.abs(await shownAt() - 4) <= 0.2, 10000);
  check(true, `the page's live state shows the position while paused (${await page.$eval('#now-position', (e) => e.textContent)})`);
  await transport(page, 'Play');
  await waitFor('playing again from 4 s', async () => {
    const s = await status();
    return s.playing && s.position_s > 4.3;
  }, 10000);
  await waitFor('the page counts on', async () => (await shownAt()) > 4.3, 10000);
  check(true, 'played on from there: the service and the page count on from 4 s');
  await shot(page, 'console-seek', 'footer');
  await axe(page, '#display with the "Seek" slider');
};

cases.listen = async () => {
  const address = Object.values(os.networkInterfaces()).flat().find((a) => a && a.family === 'IPv4' && !a.internal);
  if (!address) {
    console.log('SKIP: this machine has no address beyond loopback');
    process.exit(77);
  }
  await stopServe();
  const base = `http://${address.address}:33334`;
  await startServe(['--listen', address.address], base);
  const token = execFileSync(LFD, ['serve', '--print-token', '--state-file', stateFile]).toString().trim();
  check(/^[0-9a-f]{64}$/.test(token), 'lfd serve --print-token prints the token');
  const tokenFile = path.join(path.dirname(stateFile), 'serve-token');
  check((fs.statSync(tokenFile).mode & 0o077) === 0, 'the token file is the user\'s alone (0600)');
  const page = await fetch(base + '/', {headers: {Accept: 'text/html'}});
  const html = await page.text();
  check(page.status === 401 && /name="token"/.test(html) && !/console\.js/.test(html), 'without the token, GET / is only the login form');
  for (const [method, route] of [['GET', '/library'], ['GET', '/console/console.js'], ['GET', '/playlists'], ['PUT', '/lfd_status'],
                                 ['PUT', '/transport_control_play'], ['POST', '/library/upload'], ['GET', '/console/config']]) {
    const r = await fetch(base + route, {method, body: method === 'GET' ? undefined : '{}'});
    check(r.status === 401, `without the token: ${method} ${route} is refused (${r.status})`);
  }
  const wrong = await fetch(base + '/lfd_status', {method: 'PUT', body: '{}', headers: {Authorization: 'Bearer ' + '0'.repeat(64)}});
  check(wrong.status === 401, 'a wrong token is refused');
  const right = await fetch(base + '/lfd_status', {method: 'PUT', body: '{}', headers: {Authorization: 'Bearer ' + token}});
  check(right.status === 200, 'a script with the token (Authorization: Bearer) is answered');
  // The event socket from off the machine: closed without the token, kept with it.
  const WebSocket = require('ws');
  const socketStays = (headers) => new Promise((resolve) => {
    const ws = new WebSocket(`ws://${address.address}:9724/event_source`, {headers});
    const timer = setTimeout(() => { ws.close(); resolve(true); }, 1500);
    ws.on('close', () => { clearTimeout(timer); resolve(false); });
    ws.on('error', () => { clearTimeout(timer); resolve(false); });
  });
  check(!(await socketStays({})), 'without the token the event socket is closed');
  check(await socketStays({Cookie: 'lfd_token=' + token}), 'with the token\'s cookie the event socket stays open');
  // The HoloPlay listener from off the machine: holoplay-core's info request over its WebSocket.
  const {holoplayRaw} = require('./raw_clients.js');
  const CBOR = require('cbor-js');
  const info = Buffer.from(CBOR.encode({cmd: {info: {}}, bin: null}));
  const infoReply = (r) => r.reply ? CBOR.decode(new Uint8Array(r.reply).buffer) : null;
  for (const [what, headers] of [['no token', {}], ['a wrong token', {Authorization: 'Bearer ' + '0'.repeat(64)}],
                                 ['a wrong cookie', {Cookie: 'lfd_token=' + 'f'.repeat(64)}]]) {
    const r = await holoplayRaw(info, {host: address.address, headers});
    check(!r.reply, `HoloPlay beyond loopback with ${what}: no answer, the connection ${r.closed ? 'closed' : 'timed out'}`);
  }
  for (const [what, headers] of [['Bearer', {Authorization: 'Bearer ' + token}], ['cookie', {Cookie: 'lfd_token=' + token}]]) {
    const reply = infoReply(await holoplayRaw(info, {host: address.address, headers}));
    check(reply && reply.error === 0 && reply.devices && reply.devices.length === 1,
          `HoloPlay beyond loopback with the token (${what}): info answers the display`);
  }
  // The browser: the login form, a wrong token, the right one, then the console.
  const tab = await browser.newPage();
  await tab.setBypassCSP(true);
  await tab.goto(base + '/');
  await tab.waitForSelector('aria/Access token');
  await shot(tab, 'console-login');
  await axe(tab, 'the login form');
  await tab.type('aria/Access token', 'f'.repeat(64));
  await Promise.all([tab.waitForNavigation(), tab.click('aria/Sign in')]);
  check(/not the token/.test(await tab.$eval('main', (m) => m.textContent)), 'a wrong token: the login form says so');
  check(!tab.url().includes(token), 'the token is in no URL');
  await tab.waitForSelector('aria/Access token');
  await tab.$eval('#token', (e) => { e.value = ''; });
  await tab.type('aria/Access token', token);
  await Promise.all([tab.waitForNavigation(), tab.click('aria/Sign in')]);
  await tab.waitForSelector('body[data-ready]', {timeout: 20000});
  check(!tab.url().includes(token), 'signed in: the token is in no URL');
  check(await tab.$('aria/Display 0: ' + expectedCalibration(CALIBRATION).serial + '[role="listitem"]') !== null,
        'signed in, the console lists the display');
  await tab.waitForFunction(() => document.getElementById('connection').textContent === 'live', {timeout: 10000});
  check(true, 'the page\'s event socket is let in with the login cookie');
};

(async () => {
  const name = process.argv[2];
  if (!cases[name]) check(false, 'unknown case ' + name);
  await startXvfb();
  await startServe();
  await launch();
  await cases[name]();
  await browser.close();
  await stopServe();
  console.log(`ok: console case ${name}`);
  process.exit(0);
})().catch((e) => {
  console.error('FAIL: ' + (e.stack || e));
  if (fs.existsSync(path.join(tmp, 'serve.log'))) console.error(fs.readFileSync(path.join(tmp, 'serve.log'), 'utf8').slice(-3000));
  if (browser) browser.close();
  process.exit(1);
});
