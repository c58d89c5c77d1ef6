// The exported page in a real browser (issue 16): Debian's chromium, headless,
// driven by playwright-core.
//   node page_test.mjs PROMYK NODE_MODULES LESSONS_DIR WORKDIR
// Opens pages made by `promyk export` from file://, fails on any console
// error and on any request but the page itself, and checks what the page
// shows against the CLI: every branch's pixels, real types, formulas, a trace
// file, keys, languages, the URL state, the 3D canvas, hostile strings.
// Leaves WORKDIR/page.png (a lit pixel at step D) to look at, and prints the
// page's size, first paint and the time to trace one pixel (figures only).
import { mkdirSync, rmSync, readFileSync, writeFileSync, statSync } from 'node:fs';
import { startBrowser, runPromyk, exportPage as exportTo, canvasPixels } from './harness.mjs';
import { join } from 'node:path';
import assert from 'node:assert/strict';

const [promyk, modules, lessons, work] = process.argv.slice(2);

rmSync(work, { recursive: true, force: true });
mkdirSync(work, { recursive: true });
const everything = join(lessons, 'scenes', 'everything.json');

const run = (args) => runPromyk(promyk, args);

const exportPage = (name, args) => exportTo(promyk, work, name, args);

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

const { browser, failures, open } = await startBrowser(modules, work);

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


// The image canvas at each zoom the page offers, smallest first: calls
// `check(zoom)` at every one (the zoom buttons are disabled at the ends).
async function everyZoom(page, check) {
  while (!(await page.isDisabled('#zoom-out'))) await page.click('#zoom-out');
  const seen = [];
  for (;;) {
    const zoom = await page.textContent('#zoom-label');
    seen.push(zoom);
    await check(zoom);
    if (await page.isDisabled('#zoom-in')) break;
    await page.click('#zoom-in');
  }
  return seen;
}

// The image fits its box: no scrolling, the canvas inside the frame, the
// frame inside its panel, and no strip of frame beside the canvas.
async function assertImageFits(page, what) {
  const box = await page.evaluate(() => {
    const rect = (id) => document.getElementById(id).getBoundingClientRect().toJSON();
    const frame = document.getElementById('image-frame');
    return { frame: rect('image-frame'), canvas: rect('image'), panel: rect('image-panel'),
      scroll: [frame.scrollWidth, frame.clientWidth, frame.scrollHeight, frame.clientHeight], page: [document.documentElement.scrollWidth, window.innerWidth],
      // what reaches past the window's right edge (the first few), to say why
      wide: [...document.querySelectorAll('body *')].filter((e) => e.getBoundingClientRect().right > window.innerWidth + 0.5)
        .slice(0, 4).map((e) => `${e.tagName.toLowerCase()}#${e.id}.${e.className} ${e.getBoundingClientRect().right.toFixed(0)}`) };
  });
  const at = `${what}: ${JSON.stringify(box)}`;
  assert.ok(box.scroll[0] <= box.scroll[1] && box.scroll[2] <= box.scroll[3], `the image frame scrolls: ${at}`);
  assert.ok(box.canvas.left >= box.frame.left - 0.5 && box.canvas.right <= box.frame.right + 0.5, `the image is wider than its frame: ${at}`);
  assert.ok(box.frame.right <= box.panel.right + 0.5, `the frame is wider than its panel: ${at}`);
  assert.ok(box.frame.width - box.canvas.width <= 2.5, `a strip of frame beside the image: ${at}`);
  assert.ok(box.page[0] <= box.page[1], `the page scrolls sideways: ${at}`);
  // and the zoom shown is the zoom drawn: whole screen pixels per pixel
  const zoom = Number((await page.textContent('#zoom-label')).match(/(\d+)×/)[1]);
  const w = await page.evaluate(() => JSON.parse(document.getElementById('promyk-data').textContent).w);
  assert.equal(box.canvas.width, w * zoom, `the image is not drawn at its zoom ${zoom}: ${at}`);
}

// The atlas's patterns as drawn on the image canvas: per branch category,
// how much of its area is ink (not its colour) and a signature of the
// pattern's shape (how often an ink pixel's neighbour right, below, and
// on each diagonal is ink too).
async function atlasInk(page) {
  return page.evaluate(() => {
    const data = JSON.parse(document.getElementById('promyk-data').textContent);
    const map = Uint8Array.from(atob(data.branch_map), (c) => c.charCodeAt(0));
    const canvas = document.getElementById('image');
    const side = canvas.width;
    const z = side / data.w;
    const pixels = canvas.getContext('2d').getImageData(0, 0, side, side).data;
    const colours = {};
    for (const li of document.querySelectorAll('#legend-list li')) colours[li.dataset.index] = li.dataset.rgb.split(',').map(Number);
    const category = (x, y) => map[Math.floor(y / z) * data.w + Math.floor(x / z)];
    const ink = (x, y) => {
      const c = colours[category(x, y)];
      const k = 4 * (y * side + x);
      return pixels[k] !== c[0] || pixels[k + 1] !== c[1] || pixels[k + 2] !== c[2];
    };
    const out = {};
    const offsets = [[1, 0], [0, 1], [1, 1], [1, -1]];
    for (let y = 1; y < side - 1; ++y)
      for (let x = 0; x < side - 1; ++x) {
        const c = category(x, y);
        const o = (out[c] ||= { area: 0, ink: 0, pairs: [0, 0, 0, 0], next: [0, 0, 0, 0] });
        ++o.area;
        if (!ink(x, y)) continue;
        ++o.ink;
        offsets.forEach(([dx, dy], n) => {
          if (category(x + dx, y + dy) !== c) return;
          ++o.pairs[n];
          if (ink(x + dx, y + dy)) ++o.next[n];
        });
      }
    for (const o of Object.values(out)) {
      o.fraction = o.ink / o.area;
      o.signature = o.pairs.map((p, n) => (p ? o.next[n] / p : 0));
    }
    return out;
  });
}

// The 3D view's list of what it draws: per item its kind, light, data.
const drawnItems = (page) => page.$$eval('#view-list li', (items) => items.map((li) => ({ ...li.dataset, text: li.textContent })));
const point = (text) => text.split(',').map(Number);
const near = (a, b, tolerance = 1e-9) => a.length === b.length && a.every((x, k) => Math.abs(x - b[k]) <= tolerance * Math.max(1, Math.abs(b[k])));
const unit = (v) => { const n = Math.hypot(...v); return v.map((x) => x / n); };
const minus = (a, b) => a.map((x, k) => x - b[k]);

// A trace's light groups: per light its K, the blocker and where the shadow
// ray meets the blocker (the least s of its test in 0 < s < 1).
function lightsOf(trace) {
  const lights = [];
  const walk = (list, light) => {
    for (const item of list) {
      if (item.steps) {
        if (item.group === 'light') {
          lights[item.index] = { K: null, blocker: null, tests: [] };
          walk(item.steps, item.index);
        } else if (light !== undefined && (item.group === 'sphere' || item.group === 'plane')) {
          for (const step of item.steps)
            if (['s_1', 's_2', 's'].includes(step.key) && step.value > 0 && step.value < 1)
              lights[light].tests.push({ object: `${item.group} ${item.index}`, key: step.key, s: step.value });
        } else walk(item.steps, light);
      } else if (light !== undefined) {
        if (step_is(item, 'K')) lights[light].K = item.value;
        if (step_is(item, 'blocker')) lights[light].blocker = item.value;
      }
    }
  };
  const step_is = (item, key) => item.key === key;
  walk(trace.steps);
  return lights;
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
  // a click on the image (a real one, and one made by a script) gives it the
  // arrow keys; Home and End still walk the steps there
  const pixelBox = await page.evaluate(() => document.getElementById('image').getBoundingClientRect().toJSON());
  await blur(page);
  await page.mouse.click(pixelBox.left + (4.5 / articleW) * pixelBox.width, pixelBox.top + (3.5 / articleW) * pixelBox.height);
  assert.deepEqual(await selected(page), [3, 4]);
  await page.keyboard.press('ArrowRight');
  assert.deepEqual(await selected(page), [3, 5], 'ArrowRight after a click on the image');
  await page.keyboard.press('ArrowDown');
  assert.deepEqual(await selected(page), [4, 5], 'ArrowDown after a click on the image');
  await page.keyboard.press('End');
  assert.match(await page.textContent('#step-counter'), /^step (\d+) of \1$/, 'End after a click on the image');
  await page.keyboard.press('Home');
  assert.match(await page.textContent('#step-counter'), /^step 1 of/, 'Home after a click on the image');
  await page.click('#real'); // a select has the keys: the arrows are its own
  await page.keyboard.press('Escape');
  await selectPixel(page, 3, 4);
  await page.keyboard.press('ArrowLeft');
  assert.deepEqual(await selected(page), [3, 3], 'ArrowLeft after a click made by a script');
  await selectPixel(page, 3, 4);
  await blur(page);
  await page.keyboard.press('ArrowRight');
  assert.deepEqual(await selected(page), [3, 4]);
  assert.match(await page.textContent('#step-counter'), /^step 2 of/, 'ArrowRight with nothing focused walks the steps');
  // each formula with its numbers put in (by the C++ view): C = x_E x_S + …
  const cNumbers = await page.textContent('#steps .step[data-key="C"] .numbers');
  assert.ok(cNumbers.includes('0.125') && cNumbers.includes('3.2'), `C's numbers: ${cNumbers}`);

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
  assert.ok((await page.textContent('#steps .step[data-key="C"] .numbers')).includes('0,125'), 'Polish numbers in the formulas');
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

  // --- the image fits its box at every zoom; the atlas's patterns read at every zoom ---
  const zoomPage = exportPage('zoom.html', ['--scene', everything, '--w', '100']);
  page = await open(zoomPage);
  await page.check('#atlas-toggle');
  const patternNames = await page.$$eval('#legend-list .pattern-name', (names) => names.map((n) => n.textContent));
  assert.equal(new Set(patternNames).size, patternNames.length, `pattern names in the legend: ${patternNames}`);
  const zooms = await everyZoom(page, async (zoom) => {
    await assertImageFits(page, zoom);
    const ink = await atlasInk(page);
    const drawn = Object.entries(ink).filter(([, o]) => o.area >= 400);
    const patterned = drawn.filter(([c]) => c !== '0'); // 0: miss, plain
    assert.ok(patterned.length >= 2, `${zoom}: categories drawn ${JSON.stringify(ink)}`);
    if (ink[0]) assert.equal(ink[0].ink, 0, `${zoom}: the miss category is plain`);
    for (const [c, o] of patterned)
      assert.ok(o.fraction > 0.05 && o.fraction < 0.6, `${zoom}: category ${c} is ${(100 * o.fraction).toFixed(1)} % ink`);
    for (const [a, oa] of patterned)
      for (const [b, ob] of patterned)
        if (a < b) {
          const apart = Math.max(...oa.signature.map((x, n) => Math.abs(x - ob.signature[n])));
          assert.ok(apart > 0.3, `${zoom}: the patterns of categories ${a} and ${b} look alike (${oa.signature}; ${ob.signature})`);
        }
  });
  assert.ok(zooms.length >= 3, `zooms offered: ${zooms}`);
  // a narrower window: the zoom shrinks to fit
  await page.setViewportSize({ width: 900, height: 900 });
  await page.waitForTimeout(200);
  await assertImageFits(page, 'a window 900 wide');
  // a window narrowed for a moment (or a full-page screenshot, which broke
  // web.edit in CI) must not lose the reader's zoom: back to full width,
  // the zoom shown is the one chosen before
  const zoomLabel = () => page.textContent('#zoom-label');
  const chosenZoom = await zoomLabel();
  for (const width of [420, 300, 1600]) {
    await page.setViewportSize({ width, height: 1000 });
    await page.waitForTimeout(200);
    await assertImageFits(page, `a window ${width} wide`);
  }
  assert.equal(await zoomLabel(), chosenZoom, 'the zoom after the window narrowed and widened again');

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
  // shadow rays on their own: per light P + sK, blocked (where) or free
  const allTraces = join(work, 'everything_all.jsonl');
  run(['render', '--scene', everything, '--w', String(everythingW), '--traces', allTraces, '-o', join(work, 'everything_all.png')]);
  const everyTrace = readFileSync(allTraces, 'utf8').trim().split('\n').map((line) => JSON.parse(line));
  for (const trace of everyTrace) Object.assign(trace, trace.pixel);
  const lightsL = JSON.parse(readFileSync(everything, 'utf8')).lights.map((l) => l.L);
  const shadowCase = (trace) => lightsOf(trace).filter((l) => l && l.blocker !== null);
  const mixed = everyTrace.find((trace) => { const l = shadowCase(trace); return l.length === 2 && l.some((x) => x.blocker === 'none') && l.some((x) => x.blocker !== 'none'); });
  const shadowed = everyTrace.find((trace) => trace.branch === 'shadowed' && shadowCase(trace).length > 0);
  for (const trace of [mixed, shadowed]) {
    assert.ok(trace, 'no pixel with the shadow case wanted');
    await selectPixel(page, trace.i, trace.j);
    const items = await drawnItems(page);
    const P = cliSteps(JSON.stringify(trace)).steps.find((s) => s.key === 'P').value;
    const what = `shadow rays of (${trace.i}, ${trace.j})`;
    const lights = shadowCase(trace);
    const rays = items.filter((item) => item.kind === 'shadow');
    assert.equal(rays.length, lights.length, `${what}: ${JSON.stringify(items)}`);
    lightsOf(trace).forEach((light, l) => {
      if (!light || light.blocker === null) return;
      const ray = rays.find((item) => Number(item.light) === l);
      assert.ok(ray, `${what}: light ${l} has no shadow ray drawn`);
      assert.ok(near(point(ray.from), P) && near(point(ray.to), lightsL[l]), `${what}: light ${l} drawn from ${ray.from} to ${ray.to}`);
      if (light.blocker === 'none') {
        assert.equal(ray.result, 'free', `${what}: light ${l}`);
        return;
      }
      const test = light.tests.filter((x) => x.object === light.blocker).sort((a, b) => a.s - b.s)[0];
      assert.equal(ray.result, 'blocked', `${what}: light ${l}`);
      assert.equal(ray.blocker, light.blocker);
      assert.equal(Number(ray.s), test.s, `${what}: light ${l} s`);
      assert.ok(near(point(ray.hit), P.map((p, k) => p + test.s * light.K[k])), `${what}: light ${l} meets ${ray.blocker} at ${ray.hit}`);
      assert.ok(ray.text.includes(test.key === 's' ? 's =' : test.key === 's_1' ? 's₁ =' : 's₂ ='), `${what}: ${ray.text}`);
    });
  }
  // the blocker's step draws its shadow ray bold, labelled where it meets it
  const blockerIndex = await page.$$eval('#steps .step', (rows) => rows.findIndex((row) => row.dataset.key === 'blocker'));
  await page.evaluate((hash) => { location.hash = hash; }, `#p=${shadowed.i},${shadowed.j}&s=${blockerIndex}&lang=en&atlas=1`);
  await page.waitForFunction((k) => document.querySelector('#steps .step.current')?.dataset.index === String(k), blockerIndex);
  assert.equal(await page.getAttribute('#steps .step.current', 'data-key'), 'blocker');
  await page.evaluate(() => window.promykPage.view3d()); // the drawing asked for, done now
  assert.match(await page.textContent('#view-labels .label.current'), /^P \+ s/);
  // R and V where Phong runs, pointing as the trace's R̂ and V̂
  const phong = everyTrace.find((trace) => trace.branch === 'lit' && cliSteps(JSON.stringify(trace)).steps.some((s) => s.key === 'R_hat'));
  await selectPixel(page, phong.i, phong.j);
  const phongItems = await drawnItems(page);
  const phongSteps = cliSteps(JSON.stringify(phong)).steps;
  const Vhat = phongSteps.find((s) => s.key === 'V_hat').value;
  const drawnV = phongItems.find((item) => item.kind === 'V');
  assert.ok(drawnV && near(unit(minus(point(drawnV.to), point(drawnV.from))), unit(Vhat)), `V drawn ${JSON.stringify(drawnV)}, the trace's ${Vhat}`);
  const Rs = phongSteps.filter((s) => s.key === 'R_hat').map((s) => s.value);
  const drawnR = phongItems.filter((item) => item.kind === 'R');
  assert.equal(drawnR.length, Rs.length, `R drawn ${drawnR.length} times, the trace has ${Rs.length}`);
  drawnR.forEach((item, k) => assert.ok(near(unit(minus(point(item.to), point(item.from))), unit(Rs[k])), `R drawn ${JSON.stringify(item)}, the trace's ${Rs[k]}`));

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
  assert.match(await page.textContent('#traces-status'), /traced pixels: 9 \(float, article, samples per pixel: 4\)/);
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

  // --- hostile strings are shown as text and run nothing: the scene's name,
  // the scene file's name (scene_file in the page's data and in every trace
  // line), the trace file's name ---
  const hostileName = '<img src=x onerror="window.__pwned=1"><script>window.__pwned=2</script>&amp;';
  const sceneText = JSON.parse(readFileSync(join(lessons, 'scenes', 'article.json'), 'utf8'));
  sceneText.name = hostileName;
  const hostileFile = 'hostile <img src=x onerror=window.__pwned=3> {scene} &amp;.json';
  const hostileScene = join(work, hostileFile);
  writeFileSync(hostileScene, JSON.stringify(sceneText));
  const hostileTraces = join(work, 'hostile <svg onload=window.__pwned=4>.jsonl');
  run(['render', '--scene', hostileScene, '--w', '8', '--traces', hostileTraces, '--trace-pixel', '3,4', '-o', join(work, 'hostile.png')]);
  assert.equal(JSON.parse(readFileSync(hostileTraces, 'utf8').split('\n')[0]).scene_file, hostileScene);
  page = await open(exportPage('hostile.html', ['--scene', hostileScene, '--w', '8', '--traces', hostileTraces]));
  await selectPixel(page, 3, 4);
  const sceneLine = await page.textContent('#scene-line');
  assert.ok(sceneLine.includes(hostileName), `the scene name is shown as text: ${sceneLine}`);
  assert.ok(sceneLine.includes(hostileScene), `the scene file is shown as text: ${sceneLine}`);
  const tracesLine = await page.textContent('#traces-status');
  assert.ok(tracesLine.includes(hostileName) && tracesLine.includes(hostileScene) && tracesLine.includes(hostileTraces),
    `the trace file's scene, scene_file and name are shown as text: ${tracesLine}`);
  const sourceNote = await page.textContent('#source-note');
  assert.ok(sourceNote.includes(hostileScene) && /not recomputed/.test(sourceNote), `the traced pixel's scene_file: ${sourceNote}`);
  assert.equal(await page.evaluate(() => window.__pwned), undefined, 'a hostile string ran');
  assert.equal(await page.$$eval('body img, body svg:not(.katex *), main script, #steps script', (found) => found.length), 0,
    'a hostile string made an element');

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
