// lfd serve's console (docs/console.md) in Debian's headless Chromium, driven by the pinned
// puppeteer-core, against a real `lfd serve` on Xvfb with the test display's calibration. The
// harness starts (and restarts) the service itself: the autostart case needs a restart, the
// --listen case another address.
//   LFD_EXE=... CALIBRATION=... node console_test.js display|upload-play|playlist|refusals|foreign-origin|listen
// LFD_CONSOLE_SHOTS=DIR keeps the screenshots (docs/console.md's come from here).
'use strict';
const fs = require('fs');
const os = require('os');
const path = require('path');
const http = require('http');
const {spawn, execFileSync} = require('child_process');
const puppeteer = require('puppeteer-core');
const {check, waitFor, expectedCalibration} = require('./common.js');
const {quiltPng} = require('./quilt_png.js');

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

async function shot(page, name) {
  if (!SHOTS) return;
  fs.mkdirSync(SHOTS, {recursive: true});
  await page.screenshot({path: path.join(SHOTS, name + '.png')});
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
