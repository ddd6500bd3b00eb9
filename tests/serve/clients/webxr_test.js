// @lookingglass/webxr, unmodified, in Debian's headless Chromium against a running lfd serve: a
// page served from http://localhost (an allowed origin) imports the library's own bundle, which
// reads the calibration through holoplay-core; the page posts back what it received, and that
// must be lfd's calibration (docs/serve.md).
//   node webxr_test.js CALIBRATION_FILE
'use strict';
const http = require('http');
const fs = require('fs');
const path = require('path');
const {spawn} = require('child_process');
const {check, expectedCalibration} = require('./common.js');

const expected = expectedCalibration(process.argv[2]);
const bundle = path.join(__dirname, 'node_modules/@lookingglass/webxr/dist/bundle/webxr.js');
const page = `<!doctype html><html><body><script type="module">
import {LookingGlassWebXRPolyfill, LookingGlassConfig} from '/webxr.js';
new LookingGlassWebXRPolyfill({});
const report = () => fetch('/result', {method: 'POST', body: JSON.stringify(LookingGlassConfig.calibration)});
LookingGlassConfig.addEventListener('on-config-changed', report);
setTimeout(report, 15000);
</script></body></html>`;

let chromium = null;
const server = http.createServer((req, res) => {
  if (req.url === '/webxr.js') {
    res.writeHead(200, {'Content-Type': 'text/javascript'});
    return res.end(fs.readFileSync(bundle));
  }
  if (req.url === '/result') {
    let body = '';
    req.on('data', (d) => body += d).on('end', () => {
      res.end('ok');
      const cal = JSON.parse(body);
      if (cal.serial !== expected.serial) return;  // a default config, before lfd's arrived
      for (const key of ['pitch', 'slope', 'center', 'viewCone', 'DPI', 'screenW', 'screenH'])
        check(Math.abs(cal[key].value - expected[key].value) < 1e-9, `the page's calibration.${key} is lfd's (${cal[key].value})`);
      chromium.kill();
      process.exit(0);
    });
    return;
  }
  res.writeHead(200, {'Content-Type': 'text/html'});
  res.end(page);
});
server.listen(0, '127.0.0.1', () => {
  const url = `http://localhost:${server.address().port}/`;
  const profile = fs.mkdtempSync(path.join(process.env.LFD_SERVE_TMP || '/tmp', 'chromium-'));
  chromium = spawn('chromium', ['--headless=new', '--no-sandbox', '--disable-gpu', '--no-first-run',
                                `--user-data-dir=${profile}`, url], {stdio: 'ignore'});
  chromium.on('exit', (code) => check(false, `chromium exited (${code}) before the page reported`));
});
setTimeout(() => { if (chromium) chromium.kill(); check(false, 'no calibration from the page in 60 s'); }, 60000);
