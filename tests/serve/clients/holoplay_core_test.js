// holoplay-core, unmodified, against a running lfd serve: reads lfd's calibration through
// `info` and shows a quilt sent as bytes (docs/serve.md).
//   node holoplay_core_test.js CALIBRATION_FILE QUILT_PNG COLS ROWS ASPECT
'use strict';
const fs = require('fs');
const hp = require('holoplay-core');
const {check, lfdStatus, waitFor, expectedCalibration} = require('./common.js');

const [calibrationFile, quiltFile, cols, rows, aspect] = process.argv.slice(2);
const expected = expectedCalibration(calibrationFile);

const client = new hp.Client(async (info) => {
  check(info.error === 0 && info.devices.length >= 1, 'info lists a display');
  const cal = info.devices[0].calibration;
  for (const key of ['pitch', 'slope', 'center', 'viewCone', 'DPI', 'screenW', 'screenH'])
    check(Math.abs(cal[key].value - expected[key].value) < 1e-9, `calibration.${key} is lfd's (${cal[key].value})`);
  check(info.devices[0].defaultQuilt.tileX >= 1, 'a default quilt');
  const png = new Uint8Array(fs.readFileSync(quiltFile));
  const shown = await client.sendMessage(
      new hp.ShowMessage({vx: Number(cols), vy: Number(rows), aspect: Number(aspect)}, png));
  check(shown.error === 0, 'show of a quilt sent as bytes');
  await waitFor('the display shows it', async () => (await lfdStatus()).showing.includes('HoloPlay'));
  let refused = null;
  await client.sendMessage(new hp.CheckMessage('no-such-quilt')).catch((e) => { refused = e; });
  check(refused && refused.error !== 0, 'check of an absent quilt is an error reply');
  client.disconnect();
  process.exit(0);
}, (e) => check(false, 'connect: ' + (e.message || e)));
setTimeout(() => check(false, 'no answer in 30 s'), 30000);
