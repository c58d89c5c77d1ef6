// The exported page in a real browser (issue 16): Debian's chromium, headless,
// driven by playwright-core.
//   node page_test.mjs PROMYK NODE_MODULES LESSONS_DIR WORKDIR
// Opens pages made by `promyk export` from file://, fails on any console
// error and on any request but the page itself, and checks what the page
// shows against the CLI: every branch's pixels, real types, formulas, a trace
// file, keys, languages, the URL state, the 3D canvas, hostile strings.
// Leaves WORKDIR/page.png (a lit pixel at step D) to look at, and prints the
// page's size, first paint and the time to trace one pixel (figures only).
import { execFileSync } from 'node:child_process';
import { mkdirSync, rmSync, readFileSync, writeFileSync, statSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import assert from 'node:assert/strict';

const [promyk, modules, lessons, work] = process.argv.slice(2);
const require = createRequire(join(modules, 'noop.js'));
const { chromium } = require('playwright-core');

rmSync(work, { recursive: true, force: true });
mkdirSync(work, { recursive: true });
const everything = join(lessons, 'scenes', 'everything.json');

function run(args) {
  return execFileSync(promyk, args, { encoding: 'utf8', env: { ...process.env, LANG: 'C' }, stdio: ['ignore', 'pipe', 'pipe'] });
}

function exportPage(name, args) {
  const file = join(work, name);
  run(['export', '--lang', 'en', ...args, '-o', file]);
  return file;
}

// The CLI's trace of a pixel, its steps flattened in the trace's order.
function cliSteps(traceText) {
  const trace = JSON.parse(traceText);
  const steps = [];
  const walk = (list) => {
    for (const item of list) {
      if (item.steps) walk(item.steps);
      else steps.push(item);
    }
  };
  walk(trace.steps);
  return { trace, steps };
}

function cliTrace(i, j, w, { scene, real = 'double', formula = 'article', spp = 1 } = {}) {
  const args = ['trace', '--format', 'json', '--pixel', `${i},${j}`, '--w', String(w), '--real', real, '--formula', formula, '--spp', String(spp)];
  if (scene) args.push('--scene', scene);
  return cliSteps(run(args));
}

// A shown full-digit text (English: "−0.125", "(0.1, 0.2, 3)") as its parts.
const parts = (text) => text.replace(/\u2212/g, '-').replace(/^[([]|[)\]]$/g, '').split(', ');

// The page's steps (key, full text) must equal the CLI's values: a double
// number for number, another real type text for text (its real_text).
function assertSameValues(pageSteps, cli, what) {
  const numeric = cli.steps.filter((s) => typeof s.value !== 'string');
  const shown = pageSteps.filter((s) => s.kind !== 'word');
  assert.equal(shown.length, numeric.length, `${what}: ${shown.length} numeric steps shown, the CLI has ${numeric.length}`);
  numeric.forEach((step, k) => {
    const page = shown[k];
    assert.equal(page.key, step.key, `${what}: step ${k + 1}`);
    const values = Array.isArray(step.value) ? step.value : [step.value];
    const texts = step.real_text === undefined ? null : Array.isArray(step.real_text) ? step.real_text : [step.real_text];
    const got = parts(page.full);
    assert.equal(got.length, values.length, `${what}: ${step.key} has ${values.length} components, shown ${page.full}`);
    values.forEach((value, c) => {
      if (value === null) return; // non-finite: the text beside it is checked by the CLI's own tests
      // float and quad: the shortest text in their own type (real_text);
      // double: the number itself (the JSON's double).
      if (texts) assert.equal(got[c], texts[c], `${what}: ${step.key}[${c}] shown ${got[c]}, the CLI's real text ${texts[c]}`);
      else assert.equal(Number(got[c]), value, `${what}: ${step.key}[${c}] shown ${got[c]}, the CLI has ${value}`);
    });
  });
}

const browser = await chromium.launchPersistentContext(join(work, 'profile'), {
  executablePath: '/usr/bin/chromium',
  headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--enable-unsafe-swiftshader', '--disable-background-networking',
    '--disable-component-update', '--disable-sync', '--no-first-run'],
  viewport: { width: 1600, height: 1000 },
});
const failures = [];
let currentUrl = '';
browser.on('request', (request) => {
  const url = request.url();
  // data: URLs (KaTeX's fonts) are read from the page itself, not requested.
  if (url.split('#')[0] !== currentUrl && !url.startsWith('data:') && !url.startsWith('blob:')) failures.push(`request: ${url}`);
});

async function open(file, fragment = '') {
  const page = browser.pages()[0] || (await browser.newPage());
  currentUrl = pathToFileURL(file).href;
  page.removeAllListeners('console');
  page.removeAllListeners('pageerror');
  page.on('console', (message) => {
    if (message.type() === 'error') failures.push(`console: ${message.text()}`);
  });
  page.on('pageerror', (error) => failures.push(`page error: ${error.message}`));
  await page.goto(currentUrl + fragment);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 60000 });
  return page;
}

// The derivation as the page shows it: per step its key, kind and full text.
async function shownSteps(page) {
  return page.$$eval('#steps .step', (rows) => rows.map((row) => {
    const value = row.querySelector('.v');
    return { key: row.dataset.key, full: value.title, kind: row.dataset.kind };
  }));
}

async function selectPixel(page, i, j) {
  await page.evaluate(([i, j]) => {
    const canvas = document.getElementById('image');
    const box = canvas.getBoundingClientRect();
    const w = JSON.parse(document.getElementById('promyk-data').textContent).w;
    const x = box.left + ((j + 0.5) / w) * box.width;
    const y = box.top + ((i + 0.5) / w) * box.height;
    canvas.dispatchEvent(new MouseEvent('click', { clientX: x, clientY: y, bubbles: true }));
  }, [i, j]);
}

// The page's step keys work when no input, the image or the 3D view has focus.
const blur = (page) => page.evaluate(() => document.activeElement && document.activeElement.blur());

// Reading a picked file is asynchronous: wait until the page says something.
async function pickFile(page, file, where) {
  await page.evaluate((where) => { document.getElementById(where).textContent = ''; }, where);
  await page.setInputFiles('#traces-input', file);
  await page.waitForFunction((where) => document.getElementById(where).textContent !== '', where);
}

async function selected(page) {
  const fragment = new URLSearchParams((await page.evaluate(() => location.hash)).slice(1));
  return fragment.get('p').split(',').map(Number);
}

// A hash of the 3D canvas's pixels and how many differ from the background.
async function canvasPixels(page) {
  return page.evaluate(() => {
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

try {
  // --- the article's scene: every branch, values as the CLI's ---
  const articleW = 8;
  const article = exportPage('article.html', ['--w', String(articleW)]);
  let page = await open(article);
  await page.check('#atlas-toggle');
  const kinds = await page.$$eval('#legend-list button:not([disabled])', (buttons) => buttons.map((b) => b.dataset.category));
  assert.ok(kinds.includes('miss') && kinds.includes('dark') && kinds.includes('lit'), `article kinds: ${kinds}`);
  for (const kind of kinds) {
    await page.click(`#legend-list button[data-category="${kind}"]`);
    const [i, j] = await selected(page);
    assertSameValues(await shownSteps(page), cliTrace(i, j, articleW), `article (${i}, ${j}) ${kind}`);
  }
  // float and quad, each formula, on a lit pixel
  await selectPixel(page, 3, 4);
  for (const real of ['float', 'quad', 'double']) {
    for (const formula of ['article', 'stable', 'fma', 'geometric']) {
      await page.selectOption('#real', real);
      await page.selectOption('#formula', formula);
      assertSameValues(await shownSteps(page), cliTrace(3, 4, articleW, { real, formula }), `article (3, 4) ${real} ${formula}`);
    }
  }
  await page.selectOption('#formula', 'article');
  // "compare": two settings side by side, the agreeing digits marked
  await page.selectOption('#compare', 'quad,geometric');
  const compared = await page.$$eval('#comparison tr', (rows) => rows.length);
  assert.ok(compared > 10 && (await page.$$eval('#comparison mark', (marks) => marks.length)) > 0, 'compare marks no digits');
  await page.selectOption('#compare', '');
  assert.equal(await page.$$eval('#comparison tr', (rows) => rows.length), 0);
  // "full digits": every value with all its digits, 4 significant ones otherwise
  await page.check('#full-digits');
  assert.equal(await page.textContent('#steps .step[data-key="t"] .v'), `= ${await page.getAttribute('#steps .step[data-key="t"] .v', 'title')}`);
  await page.uncheck('#full-digits');
  assert.match(await page.textContent('#steps .step[data-key="t"] .v'), /^= 1\.058$/);

  // --- keys: step through the derivation ---
  await blur(page);
  const steps = (await shownSteps(page)).length;
  await page.keyboard.press('End');
  assert.equal(await page.textContent('#step-counter'), `step ${steps} of ${steps}`);
  await page.keyboard.press('Home');
  assert.equal(await page.textContent('#step-counter'), `step 1 of ${steps}`);
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('ArrowRight');
  assert.equal(await page.textContent('#step-counter'), `step 3 of ${steps}`);
  assert.equal(await page.getAttribute('#steps .step.current', 'data-index'), '2');
  // the arrow keys on the focused image move the selection
  await page.focus('#image');
  await page.keyboard.press('ArrowDown');
  assert.deepEqual(await selected(page), [4, 4]);
  await page.keyboard.press('ArrowUp');

  // --- the 3D canvas is drawn and follows the selection ---
  const before = await canvasPixels(page);
  assert.ok(before.drawn > before.total / 50, `3D canvas nearly blank: ${before.drawn} of ${before.total} pixels drawn`);
  await selectPixel(page, 5, 1);
  const after = await canvasPixels(page);
  assert.notEqual(after.hash, before.hash, 'the 3D view did not change with the selection');

  // --- language: Polish words and numbers, remembered, and the URL state ---
  await selectPixel(page, 3, 4);
  await blur(page);
  await page.keyboard.press('End');
  await page.click('#lang-switch button[data-lang="pl"]');
  assert.match(await page.textContent('#derivation-heading'), /Wyprowadzenie piksela \(3, 4\)/);
  assert.match(await page.textContent('#step-counter'), /^krok \d+ z \d+$/);
  assert.match(await page.textContent('#outcome .result'), /0,\d/);
  const hash = await page.evaluate(() => location.hash);
  await page.reload();
  await page.waitForSelector('body[data-ready="true"]');
  assert.equal(await page.evaluate(() => location.hash), hash);
  assert.match(await page.textContent('#step-counter'), new RegExp(`^krok ${steps} z ${steps}$`));
  page = await open(article, '#p=5,1&s=4&lang=en&real=quad&full=1');
  assert.deepEqual(await selected(page), [5, 1]);
  assert.equal(await page.textContent('#step-counter'), `step 5 of ${(await shownSteps(page)).length}`);
  assert.equal(await page.inputValue('#real'), 'quad');
  assert.ok(await page.isChecked('#full-digits'));
  // without a fragment the language chosen last is remembered
  await page.click('#lang-switch button[data-lang="pl"]');
  page = await open(article);
  assert.equal(await page.evaluate(() => document.documentElement.lang), 'pl');
  await page.click('#lang-switch button[data-lang="en"]');

  // --- the screenshot: a lit pixel of the article's scene at step D ---
  const shot = exportPage('article64.html', ['--w', '64']);
  page = await open(shot);
  const firstPaint = await page.evaluate(() => [...performance.getEntriesByType('paint').map((e) => `${e.name} ${e.startTime.toFixed(0)} ms`),
    `tracer ready ${Number(document.body.dataset.readyMs).toFixed(0)} ms`].join(', '));
  const traceTime = await page.evaluate(() => {
    const canvas = document.getElementById('image');
    const box = canvas.getBoundingClientRect();
    const start = performance.now();
    canvas.dispatchEvent(new MouseEvent('click', { clientX: box.left + box.width * 0.45, clientY: box.top + box.height * 0.4, bubbles: true }));
    return performance.now() - start;
  });
  const dIndex = await page.$$eval('#steps .step', (rows) => rows.findIndex((row) => row.dataset.key === 'D'));
  assert.ok(dIndex >= 0, 'the lit pixel has a step D');
  await blur(page);
  await page.keyboard.press('Home');
  for (let k = 0; k < dIndex; ++k) await page.keyboard.press('ArrowRight');
  assert.equal(await page.getAttribute('#steps .step.current', 'data-key'), 'D');
  await page.screenshot({ path: join(work, 'page.png'), fullPage: false });

  // --- a scene with planes, shadows, Phong and colour ---
  const everythingW = 24;
  const rich = exportPage('everything.html', ['--scene', everything, '--w', String(everythingW)]);
  page = await open(rich);
  await page.check('#atlas-toggle');
  const richKinds = await page.$$eval('#legend-list button:not([disabled])', (buttons) => buttons.map((b) => b.dataset.category));
  assert.ok(richKinds.includes('shadowed') && richKinds.includes('lit'), `everything kinds: ${richKinds}`);
  for (const kind of richKinds) {
    await page.click(`#legend-list button[data-category="${kind}"]`);
    const [i, j] = await selected(page);
    assertSameValues(await shownSteps(page), cliTrace(i, j, everythingW, { scene: everything }), `everything (${i}, ${j}) ${kind}`);
  }
  await page.selectOption('#spp', '4');
  await page.selectOption('#real', 'quad');
  const [ri, rj] = await selected(page);
  assertSameValues(await shownSteps(page), cliTrace(ri, rj, everythingW, { scene: everything, real: 'quad', spp: 4 }), 'everything quad spp 4');
  await page.selectOption('#spp', '1');
  await page.selectOption('#real', 'double');

  // --- a trace file made by render --traces (samples, float): the file's values ---
  const traces = join(work, 'traces.jsonl');
  run(['render', '--scene', everything, '--w', String(everythingW), '--real', 'float', '--spp', '4', '--traces', traces,
    '--trace-region', '10,10,12,12', '-o', join(work, 'traces.png')]);
  const lines = readFileSync(traces, 'utf8').trim().split('\n');
  await pickFile(page, traces, 'traces-status');
  assert.match(await page.textContent('#traces-status'), /9 traced pixels \(float, article, samples per pixel: 4\)/);
  await selectPixel(page, 11, 12);
  assert.match(await page.textContent('#source-note'), /not recomputed/);
  assertSameValues(await shownSteps(page), cliSteps(lines[5]), 'trace file line (11, 12)');
  // the same file embedded by export
  page = await open(exportPage('embedded.html', ['--scene', everything, '--w', String(everythingW), '--traces', traces]));
  await selectPixel(page, 10, 10);
  assertSameValues(await shownSteps(page), cliSteps(lines[0]), 'embedded trace file line (10, 10)');
  // a trace file of another w is refused, with a message
  const other = join(work, 'other.jsonl');
  run(['render', '--w', '8', '--traces', other, '--trace-pixel', '3,4', '-o', join(work, 'other.png')]);
  await pickFile(page, other, 'status');
  assert.match(await page.textContent('#status'), /w = 8/);

  // --- hostile strings are shown as text and run nothing ---
  const hostileName = '<img src=x onerror="window.__pwned=1"><script>window.__pwned=2</script>&amp;';
  const sceneText = JSON.parse(readFileSync(join(lessons, 'scenes', 'article.json'), 'utf8'));
  sceneText.name = hostileName;
  const hostileScene = join(work, 'hostile <b>scene&amp;.json');
  writeFileSync(hostileScene, JSON.stringify(sceneText));
  const hostileTraces = join(work, 'hostile.jsonl');
  run(['render', '--scene', hostileScene, '--w', '8', '--traces', hostileTraces, '--trace-pixel', '3,4', '-o', join(work, 'hostile.png')]);
  page = await open(exportPage('hostile.html', ['--scene', hostileScene, '--w', '8', '--traces', hostileTraces]));
  await selectPixel(page, 3, 4);
  assert.ok((await page.textContent('#scene-line')).includes(hostileName), 'the scene name is shown as text');
  assert.equal(await page.evaluate(() => window.__pwned), undefined, 'a hostile string ran');
  assert.equal(await page.$$eval('body img, main script, #steps script', (found) => found.length), 0);

  const size = statSync(shot).size;
  console.log(`page (article, w = 64): ${size} bytes; first paint: ${firstPaint}; one pixel traced and shown: ${traceTime.toFixed(1)} ms`);
  console.log(`screenshot: ${join(work, 'page.png')}`);
} catch (error) {
  failures.push(error.stack || String(error));
} finally {
  await browser.close();
}
if (failures.length) {
  console.error(failures.join('\n'));
  process.exit(1);
}
console.log('web page tests: ok');
