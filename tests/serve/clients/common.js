// Shared by the client tests (docs/serve.md, "Tests with the real clients"): assertions that
// exit non-zero with a message, lfd serve's own status endpoint, waiting for a condition.
'use strict';
const fs = require('fs');

function check(ok, what) {
  if (!ok) {
    console.error('FAIL: ' + what);
    process.exit(1);
  }
  console.log('ok: ' + what);
}

async function lfdStatus() {
  const r = await fetch('http://127.0.0.1:33334/lfd_status', {method: 'PUT', body: '{}'});
  return (await r.json()).payload.value;
}

async function waitFor(what, predicate, timeoutMs = 10000) {
  const start = Date.now();
  for (;;) {
    const value = await predicate();
    if (value) return value;
    if (Date.now() - start > timeoutMs) check(false, what + ' (timed out)');
    await new Promise((r) => setTimeout(r, 100));
  }
}

// The visual.json fields lfd was started with (a plain visual.json or lfd's calibration.json).
function expectedCalibration(file) {
  const root = JSON.parse(fs.readFileSync(file, 'utf8'));
  return root.format === 'lfd-calibration' ? root.display : root;
}

module.exports = {check, lfdStatus, waitFor, expectedCalibration};
