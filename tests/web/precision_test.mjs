// The precision lab in a real browser (issue 17): Debian's chromium,
// headless, driven by playwright-core.
//   node precision_test.mjs PROMYK NODE_MODULES LESSONS_DIR WORKDIR BENCH_JSON
// The bench plot of `export --bench` has one mark per row of the embedded
// JSON and a hovered or focused mark says that row's numbers; the error and
// digits-lost overlays are `promyk render --map` of the same scene and
// settings byte for byte (the exported one, and the ones the page's workers
// compute after a change of settings), with the CLI's range and legend
// words; "fix the range" keeps the scale (as --range LO,HI); the far sphere
// vanishes in float with the article's formula and comes back with the
// geometric one; axe-core finds no serious or critical violation with the
// lab open. Leaves WORKDIR/lab_overlay.png and lab_plot.png to look at.
import { spawnSync } from 'node:child_process';
import { mkdirSync, rmSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import assert from 'node:assert/strict';
import { startBrowser, runPromyk, exportPage as exportTo, readNetpbm } from './harness.mjs';

const [promyk, modules, lessons, work, benchJson] = process.argv.slice(2);

rmSync(work, { recursive: true, force: true });
mkdirSync(work, { recursive: true });
const run = (args) => runPromyk(promyk, args, work);
const exportPage = (name, args) => exportTo(promyk, work, name, args);


// `promyk render --map KIND` of the scene: its RGB bytes.
function cliMap(kind, { scene = null, w, real = 'double', formula = 'article', range = null }) {
  const args = ['render', '--w', String(w), '--real', real, '--formula', formula, '--map', kind, '-o', 'map.ppm'];
  if (scene) args.push('--scene', scene);
  if (range) args.push('--range', `${range[0]},${range[1]}`);
  run(args);
  return { rgb: readNetpbm(join(work, 'map.ppm')).bytes };
}

const axeSource = readFileSync(join(modules, 'axe-core', 'axe.min.js'), 'utf8');
async function axeViolations(page) {
  await page.addScriptTag({ content: axeSource });
  return page.evaluate(async () => (await window.axe.run(document, { resultTypes: ['violations'] })).violations
    .filter((v) => v.impact === 'serious' || v.impact === 'critical')
    .map((v) => `${v.id} (${v.impact}): ${v.help}: ${v.nodes.slice(0, 4).map((n) => n.target.join(' ')).join('; ')}`));
}

const { browser, failures, open } = await startBrowser(modules, work, { bypassCSP: true });

// The overlay shown once it is the one wanted: {kind, source, w, rgb (Buffer), range, range_text}.
async function overlay(page, kind, source) {
  await page.waitForFunction(([k, s]) => {
    const o = window.promykLab.overlay();
    return o && o.kind === k && (!s || o.source === s);
  }, [kind, source], { timeout: 300000 });
  const o = await page.evaluate(() => window.promykLab.overlay());
  return { ...o, rgb: Buffer.from(o.rgb, 'base64') };
}

// Waits for the image of the settings asked to be shown.
async function rendered(page, change) {
  const before = await page.evaluate(() => Number(document.body.dataset.renders || 0));
  await change();
  await page.waitForFunction((n) => Number(document.body.dataset.renders || 0) > n, before, { timeout: 120000 });
  await page.waitForFunction(() => !/…/.test(document.getElementById('render-status').textContent), null, { timeout: 120000 });
}

// Hovers pixel (i, j) of the image; the hover line's text.
async function hoverPixel(page, i, j, w) {
  const image = page.locator('#image');
  await image.scrollIntoViewIfNeeded();
  const box = await image.boundingBox();
  await image.hover({ position: { x: ((j + 0.5) * box.width) / w, y: ((i + 0.5) * box.height) / w } });
  return page.textContent('#hover');
}

// The number in a text as the project writes it (U+2212 minus, 1.23e−7).
const numberIn = (text) => Number(text.replace(/\u2212/g, '-').replace(',', '.'));

try {
  // --- the bench plot: one mark per row, each saying its numbers ---
  const bench = JSON.parse(readFileSync(benchJson, 'utf8'));
  // A row without a time (as a bench that could not time it writes) and one
  // with an exact error still get their marks, in the strips beyond the axes.
  bench.results[1].ratio = null;
  bench.results[1].untimed = 'could not be timed (test)';
  bench.timeable = false;
  writeFileSync(join(work, 'bench.json'), JSON.stringify(bench, null, 1));
  assert.ok(bench.results.some((r) => r.max_error === 0), 'the bench has an exact row (quad, geometric)');
  const w = 32;
  const file = exportPage('lab.html', ['--w', String(w), '--bench', 'bench.json']);
  let page = await open(file);
  const embedded = JSON.parse(await page.textContent('#promyk-data'));
  assert.deepEqual(embedded.bench, bench, 'the page embeds the bench file');
  const rows = await page.$$eval('.lab-mark', (marks) => marks.map((m) => Number(m.dataset.row)));
  assert.deepEqual([...rows].sort((a, b) => a - b), bench.results.map((_, k) => k), 'one mark per row of the embedded JSON');
  // Each scene's plot holds its own rows.
  for (const scene of bench.scenes) {
    const own = await page.$$eval(`.lab-plot[aria-label^="Scene ${scene.name} "] .lab-mark`, (marks) => marks.length);
    assert.equal(own, bench.results.filter((r) => r.scene === scene.name).length, `the marks of ${scene.name}`);
  }
  const says = (row) => [`${row.scene}: ${row.real}, ${row.formula}, spp ${row.spp}`, `branch differs: ${row.branch_differs}`, `non-finite: ${row.non_finite}`];
  for (const k of [0, 1, 7, bench.results.findIndex((r) => r.max_error === 0), bench.results.length - 1]) {
    const row = bench.results[k];
    await page.hover(`.lab-mark[data-row="${k}"]`);
    const text = await page.textContent('#lab-bench-readout');
    for (const part of says(row)) assert.ok(text.includes(part), `mark ${k}: "${part}" in "${text}"`);
    const ratio = /time × ([^ ]+)/.exec(text)[1];
    if (row.ratio === null) assert.equal(ratio, 'not');
    else assert.ok(Math.abs(numberIn(ratio) / row.ratio - 1) < 5e-3, `mark ${k}: ratio ${ratio} for ${row.ratio}`);
    const max = /largest error ([^,]+),/.exec(text)[1];
    if (row.max_error === 0) assert.equal(max, 'exact');
    else assert.ok(Math.abs(numberIn(max) / row.max_error - 1) < 5e-3, `mark ${k}: error ${max} for ${row.max_error}`);
  }
  assert.ok((await page.textContent('#lab-bench-readout')).length > 0);
  // The keyboard: a mark takes the focus and says its numbers.
  await page.focus('.lab-mark[data-row="5"]');
  assert.ok((await page.textContent('#lab-bench-readout')).includes(says(bench.results[5])[0]), 'a focused mark says its numbers');
  assert.equal(bench.results[6].scene, bench.results[5].scene);
  await page.keyboard.press('Tab'); // the next mark
  assert.ok((await page.textContent('#lab-bench-readout')).includes(says(bench.results[6])[0]), 'Tab walks the marks');
  await page.locator('#lab-panel').screenshot({ path: join(work, 'lab_plot.png') });

  // --- the error overlay of the exported image: render --map error's pixels ---
  await page.selectOption('#lab-overlay', 'error');
  const exported = await overlay(page, 'error', 'export');
  const cli = cliMap('error', { w });
  assert.ok(exported.rgb.equals(cli.rgb), 'the exported error overlay is render --map error, byte for byte');
  // Its range is the run's own, as render --map error --stats says it.
  const statsErr = spawnSync(promyk,
    ['render', '--w', String(w), '--map', 'error', '--stats', '-o', 'map.ppm'], { cwd: work, encoding: 'utf8', env: { ...process.env, LANG: 'C' } }).stderr;
  const scale = /scale: (\S+) … (\S+)/.exec(statsErr);
  assert.ok(scale, statsErr);
  assert.deepEqual(exported.range_text, [scale[1], scale[2]], 'the range render --map error --stats gives');
  assert.ok((await page.textContent('#lab-range')).includes(`${scale[1]} … ${scale[2]}`));
  // The legend's words: render --legend's (lessons/messages_maps.json).
  assert.equal(await page.textContent('#lab-legend-title'), 'error |I − I_ref|');
  assert.deepEqual(await page.$$eval('#lab-swatches li', (items) => items.map((li) => li.textContent.trim())), ['exact', 'branch differs', 'non-finite']);
  const ticks = await page.$$eval('.lab-tick', (spans) => spans.map((s) => s.textContent));
  assert.equal(ticks[0], scale[1]);
  assert.equal(ticks[ticks.length - 1], scale[2]);
  // Hovering says the value in words: the corner misses (exact), a sphere pixel has an error.
  assert.match(await hoverPixel(page, 0, 0, w), / · error map: exact$/);
  const values = new Float64Array(new Uint8Array(Buffer.from(embedded.maps.error, 'base64')).buffer);
  const lit = [...values.keys()].find((p) => values[p] > 0);
  const hovered = await hoverPixel(page, Math.floor(lit / w), lit % w, w);
  const shownValue = / · error map: (\S+)$/.exec(hovered);
  assert.ok(shownValue, hovered);
  assert.ok(Math.abs(numberIn(shownValue[1]) / values[lit] - 1) < 5e-3, `${hovered} for ${values[lit]}`);
  await page.locator('#image-panel').screenshot({ path: join(work, 'lab_overlay.png') });

  // --- another type: recomputed in the page by the workers, as the CLI draws it ---
  await rendered(page, () => page.selectOption('#real', 'float'));
  const inFloat = await overlay(page, 'error', 'page');
  assert.ok(inFloat.rgb.equals(cliMap('error', { w, real: 'float' }).rgb), 'the page\'s float error overlay is render --map error --real float');
  assert.ok(!inFloat.rgb.equals(exported.rgb));

  // --- fix the range: double's range kept for float (as --range LO,HI) ---
  await rendered(page, () => page.selectOption('#real', 'double'));
  const again = await overlay(page, 'error', 'export');
  await page.check('#lab-fix-range');
  const fixedRange = again.range;
  await rendered(page, () => page.selectOption('#real', 'float'));
  const fixed = await overlay(page, 'error', 'page');
  assert.deepEqual(fixed.range, fixedRange, 'the fixed range stays');
  assert.ok(fixed.rgb.equals(cliMap('error', { w, real: 'float', range: fixedRange }).rgb), 'the fixed range colours as --range');
  assert.ok((await page.textContent('#lab-range')).includes('fixed in the page'));
  await page.uncheck('#lab-fix-range');
  const own = await overlay(page, 'error', 'page');
  assert.ok(own.rgb.equals(inFloat.rgb), 'the run\'s own range again');

  // --- the digits-lost map, in float: computed in the page ---
  await page.selectOption('#lab-overlay', 'digits-lost');
  const digits = await overlay(page, 'digits-lost', 'page');
  assert.ok(digits.rgb.equals(cliMap('digits-lost', { w, real: 'float' }).rgb), 'the digits-lost overlay is render --map digits-lost');
  assert.equal(await page.textContent('#lab-legend-title'), 'digits lost');
  const digitsHover = / · digits-lost map: (.+)$/.exec(await hoverPixel(page, Math.floor(lit / w), lit % w, w));
  assert.ok(digitsHover && (digitsHover[1] === 'none lost' || numberIn(digitsHover[1]) > 0), 'hovering says the digits lost');

  // axe-core with the lab open (an overlay, its legend, the plot).
  assert.deepEqual(await axeViolations(page), [], 'axe-core: serious or critical violations');

  // The legend in Polish: the same words as render --legend --lang pl.
  await page.click('#lang-switch button[data-lang="pl"]');
  await page.waitForFunction(() => document.getElementById('lab-legend-title').textContent === 'stracone cyfry');
  await page.click('#lang-switch button[data-lang="en"]');

  // --- a pane the page does not recompute: the note says why and gives the command ---
  const large = exportPage('large.html', ['--w', '300']);
  page = await open(large);
  await page.selectOption('#lab-overlay', 'error');
  await page.waitForFunction(() => document.getElementById('lab-status').textContent.includes('does not compute this map again'));
  const note = await page.textContent('#lab-status');
  assert.ok(note.includes('w = 300 at spp 1 is 90000 samples') && note.includes('--w 300') && note.includes('--map error'), note);
  assert.equal(await page.evaluate(() => window.promykLab.overlay()), null);
  assert.equal(await page.isVisible('#lab-legend'), false);

  // --- the far sphere: float with the article's formula loses it, geometric brings it back ---
  const far = join(lessons, 'scenes', 'far_sphere.json');
  const farPage = exportPage('far.html', ['--scene', far, '--w', '32']);
  page = await open(farPage);
  assert.equal(await page.isVisible('#lab-far'), true, 'the far sphere\'s hint');
  const image = async () => Buffer.from((await page.evaluate(() => window.promykPage.image())).base64, 'base64');
  const cliImage = (real, formula) => {
    run(['render', '--scene', far, '--w', '32', '--real', real, '--formula', formula, '-o', 'far.pgm']);
    return readNetpbm(join(work, 'far.pgm')).bytes;
  };
  const background = (bytes) => bytes.every((v) => v === bytes[0]);
  const inDouble = await image();
  assert.ok(!background(inDouble), 'double, article: the sphere is there');
  // With the settings' own controls, as the lesson says it...
  await rendered(page, () => page.selectOption('#real', 'float'));
  const lost = await image();
  assert.ok(lost.equals(cliImage('float', 'article')), 'float, article: as promyk render');
  assert.ok(background(lost), 'float, article: the sphere vanishes');
  assert.equal(await page.inputValue('#real'), 'float');
  assert.equal(await page.inputValue('#formula'), 'article');
  // ... and with the lab's buttons, which set the same controls.
  await rendered(page, () => page.click('#lab-far button[data-real="float"][data-formula="geometric"]'));
  assert.equal(await page.inputValue('#formula'), 'geometric');
  const back = await image();
  assert.ok(back.equals(cliImage('float', 'geometric')), 'float, geometric: as promyk render');
  assert.ok(!background(back), 'float, geometric: the sphere is back');

  assert.deepEqual(failures, []);
  console.log(`screenshots: ${join(work, 'lab_overlay.png')}, ${join(work, 'lab_plot.png')}`);
} finally {
  await browser.close();
}
