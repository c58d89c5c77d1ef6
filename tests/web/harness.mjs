// What the browser tests share (page_test.mjs, edit_test.mjs): Debian's
// chromium, headless, driven by playwright-core from the build's
// node_modules; every console error, page error and request for anything
// but the page itself recorded as a failure; promyk run as the CLI user
// would, in English.
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

// The browser with its failure list and open(file, fragment), which loads
// an exported page from file:// and waits until it says it is ready.
// `options` adds to the context's options (acceptDownloads, bypassCSP).
export async function startBrowser(modules, work, options = {}) {
  const require = createRequire(join(modules, 'noop.js'));
  const { chromium } = require('playwright-core');
  const browser = await chromium.launchPersistentContext(join(work, 'profile'), {
    executablePath: '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--enable-unsafe-swiftshader', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', '--no-first-run'],
    viewport: { width: 1600, height: 1000 },
    ...options,
  });
  const failures = [];
  let currentUrl = '';
  browser.on('request', (request) => {
    const url = request.url();
    // data: URLs (KaTeX's fonts) and blob: URLs (the render workers) are the page's own.
    if (url.split('#')[0] !== currentUrl && !url.startsWith('data:') && !url.startsWith('blob:')) failures.push(`request: ${url}`);
  });

  // From about:blank first, so that a page opened again with only another
  // fragment loads anew rather than only changing its hash.
  async function open(file, fragment = '') {
    const page = browser.pages()[0] || (await browser.newPage());
    currentUrl = pathToFileURL(file).href;
    page.removeAllListeners('console');
    page.removeAllListeners('pageerror');
    page.on('console', (message) => {
      if (message.type() === 'error') failures.push(`console: ${message.text()}`);
    });
    page.on('pageerror', (error) => failures.push(`page error: ${error.message}`));
    await page.goto('about:blank');
    await page.goto(currentUrl + fragment);
    await page.waitForSelector('body[data-ready="true"]', { timeout: 60000 });
    return page;
  }
  return { browser, failures, open };
}

// promyk's standard output for `args`, run in `cwd` (LANG=C: English).
export function runPromyk(promyk, args, cwd) {
  return execFileSync(promyk, args, { cwd, encoding: 'utf8', env: { ...process.env, LANG: 'C' }, stdio: ['ignore', 'pipe', 'pipe'] });
}

// `promyk export --lang en ARGS -o WORK/NAME`; the page's path.
export function exportPage(promyk, work, name, args) {
  const file = join(work, name);
  runPromyk(promyk, ['export', '--lang', 'en', ...args, '-o', file], work);
  return file;
}

// A binary PGM (P5) or PPM (P6) as {w, channels, bytes}.
export function readNetpbm(file) {
  const data = readFileSync(file);
  const header = [];
  let at = 0;
  while (header.length < 4) {
    while (/\s/.test(String.fromCharCode(data[at]))) ++at;
    let token = '';
    while (!/\s/.test(String.fromCharCode(data[at]))) token += String.fromCharCode(data[at++]);
    header.push(token);
  }
  ++at; // the one whitespace after maxval
  const channels = header[0] === 'P6' ? 3 : 1;
  return { w: Number(header[1]), channels, bytes: data.subarray(at) };
}

// A hash of the 3D canvas's pixels and how many differ from the background.
export async function canvasPixels(page) {
  return page.evaluate(() => {
    window.promykPage.view3d(); // the drawing asked for (at most one a frame) done now
    const gl = document.getElementById('view3d');
    const copy = document.createElement('canvas');
    copy.width = gl.width;
    copy.height = gl.height;
    const ctx = copy.getContext('2d');
    ctx.drawImage(gl, 0, 0);
    const data = ctx.getImageData(0, 0, copy.width, copy.height).data;
    let drawn = 0;
    let hash = 0;
    for (let k = 0; k < data.length; k += 4) {
      if (data[k] !== data[0] || data[k + 1] !== data[1] || data[k + 2] !== data[2]) ++drawn;
      hash = (hash * 31 + data[k] + 7 * data[k + 1] + 13 * data[k + 2]) | 0;
    }
    return { drawn, hash, total: data.length / 4 };
  });
}
