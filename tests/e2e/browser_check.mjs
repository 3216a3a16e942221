// Opens ncverify's pictures in a real browser (Debian's headless chromium, driven over the
// DevTools protocol) and checks what a person would see. Used by test_html_report.sh.
//
//   node browser_check.mjs report REPORT.html SCREENSHOT.png
//     The page loads with no JavaScript error and no request beyond its own file; the first
//     3D view draws the part in the tolerance map's colours (pixels of the canvas, not
//     blank); its region table lists every region; hovering reads the error out; choosing a
//     region row moves the camera there. Writes a screenshot of the page's top.
//     Environment: EXPECT_REGIONS (the first direction's), EXPECT_VIEWS, EXPECT_VERDICT,
//     EXPECT_EXCESS and EXPECT_GOUGE (1: that colour must show).
//   node browser_check.mjs svg FILE.svg...
//     No text of the picture leaves it or overlaps another text.
//
// Prints one line per failed check and a summary; exit status 0 when every check passed.
import { spawn } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync, existsSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import CDP from 'chrome-remote-interface';
import { PNG } from 'pngjs';

const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';
const WIDTH = 1300;
const HEIGHT = 1700;

let failed = 0;
let passed = 0;
function check(ok, what) {
  if (ok) {
    ++passed;
  } else {
    ++failed;
    console.log(`FAIL: ${what}`);
  }
}

const sleep = (ms) => new Promise((done) => setTimeout(done, ms));

// Starts chromium on a fresh profile with a DevTools port of its own choosing (read back
// from the profile), with no network services, and WebGL on SwiftShader: the headless
// machine has no GPU, and chromium no longer falls back to software WebGL unasked.
async function startBrowser() {
  const profile = mkdtempSync(join(tmpdir(), 'ncverify-chromium-'));
  const args = [
    '--headless', '--no-sandbox', '--disable-gpu', '--use-angle=swiftshader',
    '--enable-unsafe-swiftshader', '--disable-quic', '--no-first-run',
    '--disable-background-networking', '--disable-component-update', '--disable-sync',
    '--disable-extensions', '--disable-default-apps', '--mute-audio',
    `--user-data-dir=${profile}`, '--remote-debugging-port=0', `--window-size=${WIDTH},${HEIGHT}`,
    'about:blank',
  ];
  // Its own process group, so that stopping it stops its renderer and GPU processes too.
  const browser = spawn(CHROMIUM, args, { stdio: ['ignore', 'ignore', 'pipe'], detached: true });
  let log = '';
  browser.stderr.on('data', (chunk) => { log += chunk; });
  const portFile = join(profile, 'DevToolsActivePort');
  for (let waited = 0; !existsSync(portFile); waited += 100) {
    if (waited > 60000 || browser.exitCode !== null) {
      throw new Error(`chromium did not start: ${log.slice(-500)}`);
    }
    await sleep(100);
  }
  await sleep(100);
  const port = Number(readFileSync(portFile, 'utf8').split('\n')[0]);
  const stop = async () => {
    if (browser.exitCode === null) {
      const exited = new Promise((done) => browser.once('exit', done));
      try {
        process.kill(-browser.pid, 'SIGKILL');
      } catch {
        browser.kill('SIGKILL');
      }
      await exited;
    }
    // A child still closing may write into the profile for a moment: retry, and never fail
    // the check over a temporary folder.
    try {
      rmSync(profile, { recursive: true, force: true, maxRetries: 20, retryDelay: 250 });
    } catch (error) {
      console.error(`note: the browser profile ${profile} stays: ${error.message}`);
    }
  };
  return { port, stop };
}

async function openPage(port, url) {
  const client = await CDP({ port, target: (targets) => targets.find((t) => t.type === 'page') });
  const { Page, Runtime, Log, Network, Emulation } = client;
  const problems = [];
  Runtime.consoleAPICalled(({ type, args }) => {
    if (type === 'error' || type === 'assert') {
      problems.push(`console.${type}: ${args.map((a) => a.value ?? a.description).join(' ')}`);
    }
  });
  Runtime.exceptionThrown(({ exceptionDetails }) => {
    problems.push(`exception: ${exceptionDetails.exception?.description ?? exceptionDetails.text}`);
  });
  Log.entryAdded(({ entry }) => {
    if (entry.level === 'error') problems.push(`log error: ${entry.text} (${entry.url ?? ''})`);
  });
  Network.requestWillBeSent(({ request }) => {
    if (request.url !== url && !/^(data|blob):/.test(request.url)) {
      problems.push(`request to ${request.url}`);
    }
  });
  await Promise.all([Page.enable(), Runtime.enable(), Log.enable(), Network.enable()]);
  await Emulation.setDeviceMetricsOverride({ width: WIDTH, height: HEIGHT, deviceScaleFactor: 1, mobile: false });
  const loaded = Page.loadEventFired();
  await Page.navigate({ url });
  await loaded;
  const evaluate = async (expression) => {
    const { result, exceptionDetails } = await Runtime.evaluate({ expression, returnByValue: true, awaitPromise: true });
    if (exceptionDetails) throw new Error(`${expression}: ${exceptionDetails.exception?.description}`);
    return result.value;
  };
  return { client, problems, evaluate };
}

async function waitFor(evaluate, expression, what, ms = 60000) {
  for (let waited = 0; waited < ms; waited += 200) {
    if (await evaluate(expression)) return true;
    await sleep(200);
  }
  check(false, `${what} within ${ms / 1000} s`);
  return false;
}

function decode(base64) {
  return PNG.sync.read(Buffer.from(base64, 'base64'));
}

// Shares of the canvas's pixels in each colour class of the tolerance map.
function colourShares(png) {
  const counts = { background: 0, green: 0, excess: 0, gouge: 0, marker: 0, other: 0 };
  const d = png.data;
  for (let i = 0; i < d.length; i += 4) {
    const [r, g, b] = [d[i], d[i + 1], d[i + 2]];
    if (Math.abs(r - 0xee) < 6 && Math.abs(g - 0xf1) < 6 && Math.abs(b - 0xf4) < 6) counts.background++;
    else if (g > r + 40 && g > b + 40) counts.green++;
    else if (r > g + 60 && r > b + 60) counts.excess++;
    else if (b > r + 60 && b > g + 30) counts.gouge++;
    else if (r > 200 && g > 200 && b < 80) counts.marker++;
    else counts.other++;
  }
  const total = png.width * png.height;
  return Object.fromEntries(Object.entries(counts).map(([k, v]) => [k, v / total]));
}

function differingPixels(a, b) {
  let differing = 0;
  for (let i = 0; i < a.data.length; i += 4) {
    if (Math.abs(a.data[i] - b.data[i]) + Math.abs(a.data[i + 1] - b.data[i + 1]) +
        Math.abs(a.data[i + 2] - b.data[i + 2]) > 30) differing++;
  }
  return differing / (a.width * a.height);
}

async function canvasShot(client, evaluate) {
  const rect = await evaluate(`(() => { const r = window.ncvReport.views[0].canvas.getBoundingClientRect();
    return { x: r.left + scrollX, y: r.top + scrollY, width: r.width, height: r.height }; })()`);
  const { data } = await client.Page.captureScreenshot({ format: 'png', clip: { ...rect, scale: 1 }, captureBeyondViewport: true });
  return decode(data);
}

async function checkReport(port, htmlPath, screenshotPath) {
  const url = pathToFileURL(resolve(htmlPath)).href;
  const { client, problems, evaluate } = await openPage(port, url);
  try {
    if (!(await waitFor(evaluate, 'window.ncvReport && window.ncvReport.ready', 'the report reports ready'))) return;
    await sleep(500);
    const page = await evaluate(`({
      rows: document.querySelector('section.ncv-direction').querySelectorAll('tr[data-region]').length,
      views: window.ncvReport.views.length,
      regions: window.ncvReport.views[0].regions,
      triangles: window.ncvReport.views[0].triangles,
      verdict: document.getElementById('ncv-verdict').textContent,
      webgl: !!window.ncvReport.views[0].canvas.getContext('webgl2'),
    })`);
    const expected = Number(process.env.EXPECT_REGIONS ?? page.regions);
    check(page.regions === expected, `the view marks ${expected} regions (it marks ${page.regions})`);
    check(page.rows === expected, `the region table lists ${expected} regions (it lists ${page.rows})`);
    check(page.triangles > 0, 'the view has triangles');
    if (process.env.EXPECT_VIEWS) {
      check(page.views === Number(process.env.EXPECT_VIEWS), `the page shows ${process.env.EXPECT_VIEWS} views (it shows ${page.views})`);
    }
    if (process.env.EXPECT_VERDICT) {
      check(page.verdict.includes(process.env.EXPECT_VERDICT), `the banner says ${process.env.EXPECT_VERDICT}: ${page.verdict}`);
    }

    const first = await canvasShot(client, evaluate);
    const shares = colourShares(first);
    console.log(`canvas ${first.width}x${first.height}: ${JSON.stringify(Object.fromEntries(Object.entries(shares).map(([k, v]) => [k, +(100 * v).toFixed(2)])))} %`);
    check(shares.background < 0.9, `the part covers the view (background ${(100 * shares.background).toFixed(1)} %)`);
    check(shares.green > 0.1, `the part is drawn green where within tolerance (${(100 * shares.green).toFixed(1)} %)`);
    if (process.env.EXPECT_EXCESS) check(shares.excess > 1e-4, `excess is drawn red (${(100 * shares.excess).toFixed(3)} %)`);
    if (process.env.EXPECT_GOUGE) check(shares.gouge > 1e-5, `gouge is drawn blue (${(100 * shares.gouge).toFixed(3)} %)`);

    const full = await client.Page.captureScreenshot({ format: 'png', clip: { x: 0, y: 0, width: WIDTH, height: HEIGHT, scale: 1 }, captureBeyondViewport: true });
    writeFileSync(screenshotPath, Buffer.from(full.data, 'base64'));

    // The error under the pointer, at the view's centre (the part is there).
    const centre = await evaluate(`(() => { const r = window.ncvReport.views[0].canvas.getBoundingClientRect();
      window.scrollTo(0, r.top + scrollY - 40); const s = window.ncvReport.views[0].canvas.getBoundingClientRect();
      return { x: s.left + s.width / 2, y: s.top + s.height / 2 }; })()`);
    await client.Input.dispatchMouseEvent({ type: 'mouseMoved', x: centre.x, y: centre.y });
    await sleep(300);
    const readout = await evaluate(`document.querySelector('.ncv-readout').textContent`);
    check(/^error -?[0-9.]+ mm at \(/.test(readout), `hovering reads the error out: "${readout}"`);

    if (page.rows > 0) {
      await evaluate(`document.querySelector('tr[data-region="1"]').click()`);
      await sleep(500);
      const moved = await canvasShot(client, evaluate);
      const changed = differingPixels(first, moved);
      check(changed > 0.05, `choosing region 1 moves the camera (${(100 * changed).toFixed(1)} % of the pixels changed)`);
      const said = await evaluate(`document.querySelector('.ncv-readout').textContent`);
      check(said.startsWith('region 1 ('), `the readout names the chosen region: "${said}"`);
      const chosen = await evaluate(`document.querySelector('tr.ncv-chosen')?.dataset.region`);
      check(chosen === '1', 'the chosen row is highlighted');
    }
    check(problems.length === 0, `no console error, exception or request: ${problems.join('; ')}`);
  } finally {
    await client.close();
  }
}

// Text boxes of an SVG document in its own coordinates.
const TEXT_BOXES = `(() => {
  const svg = document.documentElement;
  const view = svg.viewBox.baseVal;
  const boxes = [...document.querySelectorAll('text')].map((t) => {
    const b = t.getBBox();
    const m = t.getCTM();
    const corners = [[b.x, b.y], [b.x + b.width, b.y], [b.x, b.y + b.height], [b.x + b.width, b.y + b.height]]
      .map(([x, y]) => [m.a * x + m.c * y + m.e, m.b * x + m.d * y + m.f]);
    const xs = corners.map((c) => c[0]), ys = corners.map((c) => c[1]);
    return { text: t.textContent, left: Math.min(...xs), right: Math.max(...xs), top: Math.min(...ys), bottom: Math.max(...ys) };
  });
  return { width: view.width, height: view.height, boxes };
})()`;

async function checkSvg(port, svgPath) {
  const url = pathToFileURL(resolve(svgPath)).href;
  const { client, problems, evaluate } = await openPage(port, url);
  try {
    const { width, height, boxes } = await evaluate(TEXT_BOXES);
    check(boxes.length > 0, `${svgPath} has text`);
    for (const b of boxes) {
      check(b.left >= 0 && b.top >= 0 && b.right <= width && b.bottom <= height,
        `${svgPath}: "${b.text}" lies inside the picture (${b.left.toFixed(1)}..${b.right.toFixed(1)} x ${b.top.toFixed(1)}..${b.bottom.toFixed(1)})`);
    }
    // Glyph boxes include the line's ascent and descent: overlaps of a pixel or two between
    // stacked lines are not collisions.
    const slack = 2;
    for (let i = 0; i < boxes.length; ++i) {
      for (let j = i + 1; j < boxes.length; ++j) {
        const a = boxes[i], b = boxes[j];
        const apart = a.right - slack <= b.left || b.right - slack <= a.left ||
          a.bottom - slack <= b.top || b.bottom - slack <= a.top;
        check(apart, `${svgPath}: "${a.text}" and "${b.text}" do not overlap`);
      }
    }
    check(problems.length === 0, `${svgPath}: no console error or request: ${problems.join('; ')}`);
  } finally {
    await client.close();
  }
}

async function main() {
  const [mode, ...paths] = process.argv.slice(2);
  const { port, stop } = await startBrowser();
  try {
    if (mode === 'report') await checkReport(port, paths[0], paths[1]);
    else if (mode === 'svg') for (const path of paths) await checkSvg(port, path);
    else throw new Error(`unknown mode ${mode}: use report or svg`);
  } finally {
    await stop();
  }
  console.log(`browser: ${passed} passed, ${failed} failed`);
  process.exit(failed === 0 ? 0 : 1);
}

main().catch((error) => {
  console.log(`FAIL: ${error.message}`);
  process.exit(1);
});
