// Headless Chromium driven through its DevTools protocol over a pipe (--remote-debugging-pipe:
// no port, no network, and Node 18 and 20 need no WebSocket for it): fd 3 to Chromium, fd 4
// from it, each message ending in \0. Shared by the browser tests (drag.js) and the panel's
// speed script (scripts/browser-speed.js).
//   const cdp = require('./cdp.js').start(CHROMIUM, WORK, [extra flags]);
//   const page = await cdp.openPage(url);  await page.eval('1 + 1');  await cdp.answered(page, 0);
//   cdp.close();
'use strict';
const fs = require('fs');
const path = require('path');
const {spawn} = require('child_process');

function start(chromium, work, flags = []) {
  const browser = spawn(chromium, ['--headless', '--no-sandbox', '--disable-gpu', '--hide-scrollbars', '--remote-debugging-pipe',
                                   '--user-data-dir=' + fs.mkdtempSync(path.join(work, 'profile.'))].concat(flags, ['about:blank']),
                        {stdio: ['ignore', 'ignore', fs.openSync(path.join(work, 'chromium.log'), 'w'), 'pipe', 'pipe']});
  const toBrowser = browser.stdio[3], fromBrowser = browser.stdio[4];
  let nextId = 1, buffer = '';
  const waiting = new Map();
  fromBrowser.on('data', chunk => {
    buffer += chunk.toString('utf8');
    let end;
    while ((end = buffer.indexOf('\0')) >= 0) {
      const message = JSON.parse(buffer.slice(0, end));
      buffer = buffer.slice(end + 1);
      if (message.id && waiting.has(message.id)) {
        const {resolve, reject, method} = waiting.get(message.id);
        waiting.delete(message.id);
        if (message.error) reject(new Error(method + ': ' + message.error.message));
        else resolve(message.result);
      }
    }
  });
  function send(method, params = {}, sessionId) {
    const id = nextId++;
    toBrowser.write(JSON.stringify(sessionId ? {id, method, params, sessionId} : {id, method, params}) + '\0');
    return new Promise((resolve, reject) => waiting.set(id, {resolve, reject, method}));
  }
  const sleep = ms => new Promise(r => setTimeout(r, ms));

  async function openPage(url, size = {width: 1100, height: 1400}) {
    const {targetId} = await send('Target.createTarget', {url: 'about:blank'});
    const {sessionId} = await send('Target.attachToTarget', {targetId, flatten: true});
    const page = (method, params) => send(method, params, sessionId);
    await page('Emulation.setDeviceMetricsOverride', {width: size.width, height: size.height, deviceScaleFactor: 1, mobile: false});
    await page('Page.navigate', {url});
    page.eval = async expression => {
      const r = await page('Runtime.evaluate', {expression, returnByValue: true, awaitPromise: true});
      if (r.exceptionDetails) throw new Error(expression + ': ' + JSON.stringify(r.exceptionDetails));
      return r.result.value;
    };
    page.close = () => send('Target.closeTarget', {targetId});
    return page;
  }
  // Waits until the Try-it panel's engine has given more than `after` answers; returns the count.
  async function answered(page, after) {
    for (let k = 0; k < 600; ++k) {
      const n = await page.eval(`(function () { var p = document.getElementById('try-it');
        return p && p.dataset.answers ? Number(p.dataset.answers) : 0; })()`).catch(() => 0);
      if (n > after) {
        await sleep(100);  // answers still queued by the last moves
        return page.eval(`Number(document.getElementById('try-it').dataset.answers)`);
      }
      await sleep(50);
    }
    throw new Error('the engine did not answer');
  }
  return {send, openPage, answered, sleep, close: () => browser.kill()};
}

module.exports = {start};
