// Raw clients for the refusal tests (docs/serve.md): a HoloPlay request over WebSocket with the
// SP framing done here (4-byte big-endian request id, high bit set, then the payload), an HTTP
// PUT with chosen headers, an event socket. Each resolves to what happened, never hangs.
'use strict';
const http = require('http');
const WebSocket = require(require.resolve('ws', {paths: [require.resolve('holoplay-core')]}));

// Resolves {reply: Buffer} or {closed: true} or {timeout: true}.
// `host`: another address than loopback (the --listen test); `headers`: e.g. the token's.
function holoplayRaw(payload, {origin, timeoutMs = 3000, rawFrame = false, host = 'localhost', headers = {}} = {}) {
  return new Promise((resolve) => {
    const ws = new WebSocket(`ws://${host}:11222/driver`, ['rep.sp.nanomsg.org'], origin ? {origin, headers} : {headers});
    const timer = setTimeout(() => { ws.terminate(); resolve({timeout: true}); }, timeoutMs);
    ws.on('open', () => {
      if (rawFrame) return ws.send(payload);
      const frame = Buffer.alloc(4 + payload.length);
      frame.writeUInt32BE(0x80000000 + 12345, 0);
      Buffer.from(payload).copy(frame, 4);
      ws.send(frame);
    });
    ws.on('message', (data) => { clearTimeout(timer); ws.close(); resolve({reply: Buffer.from(data).subarray(4)}); });
    ws.on('close', () => { clearTimeout(timer); resolve({closed: true}); });
    ws.on('error', () => { clearTimeout(timer); resolve({closed: true}); });
  });
}

// Resolves {status, body} or {error}.
function put(endpoint, body, headers = {}) {
  return new Promise((resolve) => {
    const data = Buffer.from(typeof body === 'string' ? body : JSON.stringify(body));
    const req = http.request({host: '127.0.0.1', port: 33334, path: '/' + endpoint, method: 'PUT',
                              headers: {'Content-Type': 'application/json', 'Content-Length': data.length, ...headers}},
                             (res) => {
                               let text = '';
                               res.on('data', (d) => text += d).on('end', () => resolve({status: res.statusCode, body: text}));
                             });
    req.on('error', (e) => resolve({error: e.message}));
    req.setTimeout(10000, () => { req.destroy(); resolve({error: 'timeout'}); });
    req.end(data);
  });
}

// Resolves 'open' (stayed open for holdMs), 'closed', or 'refused'.
function eventSocket({origin, send, holdMs = 1000} = {}) {
  return new Promise((resolve) => {
    const ws = new WebSocket('ws://localhost:9724/event_source', origin ? {origin} : {});
    let opened = false;
    ws.on('open', () => {
      opened = true;
      if (send) ws.send(send);
      setTimeout(() => { ws.terminate(); resolve('open'); }, holdMs);
    });
    ws.on('close', () => resolve(opened ? 'closed' : 'refused'));
    ws.on('error', () => resolve('refused'));
  });
}

module.exports = {holoplayRaw, put, eventSocket};
