// The worksheet in the page (issue 17, "lessons and worksheets in the
// page"): Debian's chromium, headless, driven by playwright-core.
//   node worksheet_test.mjs PROMYK NODE_MODULES LESSONS_DIR WORKDIR
// A pupil fills in the sphere lesson's worksheet for pixel (3, 4) with one
// right answer, one rounded the wrong way and one wrong, by the keyboard
// alone; "Check" marks them as `promyk lesson --answers` marks the file
// "Save answers" downloads (the CLI is run on that very file); the URL
// reopens the lesson at its pixel, step and mode; axe-core finds no serious
// or critical violation with a lesson in step mode and with a worksheet
// checked; every control on the walk shows its focus. Both languages.
// Leaves WORKDIR/worksheet_LANG.png and worksheet_print_LANG.png (print media) to look at.
import { execFileSync } from 'node:child_process';
import { mkdirSync, readFileSync, rmSync } from 'node:fs';
import { join } from 'node:path';
import assert from 'node:assert/strict';
import { startBrowser, runPromyk, exportPage } from './harness.mjs';

const [promyk, modules, , work] = process.argv.slice(2);
rmSync(work, { recursive: true, force: true });
mkdirSync(work, { recursive: true });

// bypassCSP: axe-core is injected as a script the page's CSP would refuse.
const { browser, failures, open } = await startBrowser(modules, work, { acceptDownloads: true, bypassCSP: true });
const axeSource = readFileSync(join(modules, 'axe-core', 'axe.min.js'), 'utf8');
async function axeViolations(page) {
  await page.addScriptTag({ content: axeSource });
  return page.evaluate(async () => (await window.axe.run(document, { resultTypes: ['violations'] })).violations
    .filter((v) => v.impact === 'serious' || v.impact === 'critical')
    .map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`));
}

// `promyk lesson ARGS`: its standard output and exit code (1: a wrong answer).
function lesson(args) {
  try {
    return { out: execFileSync(promyk, ['lesson', ...args], { cwd: work, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] }), code: 0 };
  } catch (error) {
    if (typeof error.status !== 'number' || error.status > 1) throw error;
    return { out: error.stdout, code: error.status };
  }
}
const squeezed = (text) => text.replace(/\s+/g, ' ').trim();

// Presses Tab until the element `selector` has the focus (at most 60 times);
// every element the walk reaches must show its focus (an outline).
async function tabTo(page, selector) {
  for (let k = 0; k < 60; ++k) {
    await page.keyboard.press('Tab');
    const at = await page.evaluate((s) => {
      const e = document.activeElement;
      const style = getComputedStyle(e);
      return { hit: e.matches(s), name: e.id || e.tagName, outline: style.outlineStyle, width: parseFloat(style.outlineWidth) };
    }, selector);
    if (at.name !== 'BODY') assert.ok(at.outline !== 'none' && at.width >= 2, `no visible focus on ${at.name}`);
    if (at.hit) return;
  }
  assert.fail(`Tab never reaches ${selector}`);
}

const visibleSteps = (page) =>
  page.$$eval('#lesson-body section.lesson-step', (s) => s.filter((x) => !x.hidden).map((x) => Number(x.dataset.step)));

const file = exportPage(promyk, work, 'article.html', ['--w', '8']);
const pixel = [3, 4];
for (const lang of ['en', 'pl']) {
  let page = await open(file, `#p=${pixel.join(',')}&lang=${lang}`);

  // --- the keyboard walk: the lesson list, "use this pixel", the mode, the steps ---
  await page.locator('#lesson-select').focus();
  const first = await page.evaluate(() => document.getElementById('lesson-body').dataset.lesson);
  await page.keyboard.press('ArrowDown');
  await page.waitForFunction((f) => document.getElementById('lesson-body').dataset.lesson !== f, first);
  await page.selectOption('#lesson-select', 'sphere');
  await page.waitForFunction(() => document.getElementById('lesson-body').dataset.lesson === 'sphere');
  await page.locator('#lesson-select').focus();
  await tabTo(page, '#lesson-use-pixel');
  await page.keyboard.press('Enter');
  await page.waitForFunction((p) => document.getElementById('lesson-body').dataset.pixels === JSON.stringify([p]), pixel);
  await tabTo(page, '#lesson-step-mode');
  await page.keyboard.press('Space');
  assert.deepEqual(await visibleSteps(page), [1], 'Space on the step mode');
  await tabTo(page, '#lesson-next');
  await page.keyboard.press('Enter');
  assert.deepEqual(await visibleSteps(page), [2], 'Enter on the next step');
  // The focus goes to the step's heading; the arrows walk the steps from there.
  await page.keyboard.press('ArrowRight');
  assert.deepEqual(await visibleSteps(page), [3]);
  await page.keyboard.press('ArrowLeft');
  assert.deepEqual(await visibleSteps(page), [2]);
  await page.keyboard.press('ArrowRight');
  assert.deepEqual(await visibleSteps(page), [3]);
  // axe-core on a lesson in step mode.
  assert.deepEqual(await axeViolations(page), [], `axe-core, a lesson in step mode (${lang})`);

  // The URL holds the lesson, its pixel, its step and the mode: a link reopens them.
  let hash = await page.evaluate(() => location.hash);
  assert.match(hash, /[#&]l=sphere(&|$)/);
  assert.match(hash, /[#&]lp=3,4(&|$)/);
  assert.match(hash, /[#&]ls=3(&|$)/);
  page = await open(file, hash);
  assert.equal(await page.evaluate(() => document.getElementById('lesson-body').dataset.lesson), 'sphere');
  assert.equal(await page.evaluate(() => document.getElementById('lesson-body').dataset.pixels), JSON.stringify([pixel]));
  assert.deepEqual(await visibleSteps(page), [3], `the link ${hash} reopens step 3`);
  assert.equal(await page.isChecked('#lesson-step-mode'), true);
  assert.equal(await page.isChecked('#lesson-mode-lesson'), true);

  // --- the worksheet: the mode is a radio group (arrows) ---
  await page.locator('#lesson-step-mode').focus();
  await page.keyboard.press('Space'); // step mode off: every blank at once
  await tabTo(page, '#lesson-mode-lesson');
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => document.getElementById('lesson-body').dataset.mode === 'worksheet');
  assert.equal(await page.isChecked('#lesson-mode-worksheet'), true);
  const blanks = await page.$$eval('#lesson-body input.blank-field', (inputs) =>
    inputs.map((i) => ({ n: Number(i.dataset.blank), key: i.dataset.key, kind: i.dataset.kind, id: i.id,
      label: i.labels.length === 1 ? i.labels[0].textContent : null })));
  // The page's worksheet is the CLI's: as many fields as `lesson --worksheet --format html` has.
  const cliHtml = lesson(['sphere', '--pixel', pixel.join(','), '--worksheet', '--format', 'html', '--lang', lang]).out;
  assert.equal(blanks.length, (cliHtml.match(/<input /g) || []).length, 'the fields of the CLI\'s HTML worksheet');
  assert.ok(blanks.length >= 5, 'few fields');
  // One field a blank, each labelled.
  assert.equal(new Set(blanks.map((b) => b.n)).size, blanks.length);
  for (const b of blanks) assert.ok(b.label && b.label.includes(`(${b.n})`), `blank ${b.n} has no label`);

  // The values from the CLI's answer key, at 12 significant digits.
  const key = lesson(['sphere', '--pixel', pixel.join(','), '--worksheet', '--key', '--format', 'markdown', '--lang', lang, '--digits', '12']).out;
  const values = new Map();
  for (const line of key.split('\n')) {
    const m = line.match(/^- \((\d+)\) .*? = (\S+)\s+\[(.+)\]$/);
    if (m) values.set(Number(m[1]), Number(m[2].replace('\u2212', '-').replace(',', '.')));
  }
  const usable = blanks.filter((b) => b.kind === 'scalar' && Number.isFinite(values.get(b.n)) &&
    Math.abs(values.get(b.n) * 1000 - Math.round(values.get(b.n) * 1000)) > 0.01);
  assert.ok(usable.length >= 3, 'three blanks to answer');
  const [right, way, wrong] = usable;
  const thousandths = (v) => Math.round(v * 1000);
  const text = (k, comma) => {
    const s = (k / 1000).toFixed(3);
    return comma ? s.replace('.', ',') : s;
  };
  const rounded = (v) => thousandths(v);
  const otherWay = (v) => (rounded(v) / 1000 < v ? rounded(v) + 1 : rounded(v) - 1);
  // A decimal comma in one, a point in another, whatever the language.
  const typed = new Map([
    [right.n, text(rounded(values.get(right.n)), true)],
    [way.n, text(otherWay(values.get(way.n)), false)],
    [wrong.n, text(rounded(values.get(wrong.n)) + 7, lang === 'pl')],
  ]);
  for (const b of [right, way, wrong].sort((a, c) => blanks.indexOf(a) - blanks.indexOf(c))) {
    await tabTo(page, `#${b.id}`);
    await page.keyboard.type(typed.get(b.n));
  }
  await tabTo(page, '#worksheet-check');
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => document.getElementById('worksheet-result').textContent !== '');
  const marks = await page.$$eval('#lesson-body .mark', (m) => m.map((x) => ({
    n: Number(x.id.replace('mark-', '')), verdict: x.dataset.verdict, text: x.textContent })));
  const verdictOf = (n) => (marks.find((m) => m.n === n) || {}).verdict;
  assert.equal(verdictOf(right.n), 'right', `${lang}: ${JSON.stringify(marks)}`);
  assert.equal(verdictOf(way.n), 'wrong_way');
  assert.equal(verdictOf(wrong.n), 'wrong');
  assert.equal(marks.filter((m) => m.verdict !== 'blank').length, 3);
  // The wrong answers are said to be wrong to a screen reader too.
  assert.equal(await page.getAttribute(`#blank-${way.n}`, 'aria-invalid'), 'true');
  assert.equal(await page.getAttribute(`#blank-${way.n}`, 'aria-describedby'), `mark-${way.n}`);
  const summary = await page.textContent('#worksheet-result');
  await page.locator('#lessons-panel').screenshot({ path: join(work, `worksheet_${lang}.png`) });
  assert.deepEqual(await axeViolations(page), [], `axe-core, a checked worksheet (${lang})`);
  // Printed, the worksheet keeps its fields (what was typed) without the page's buttons and marks.
  await page.emulateMedia({ media: 'print' });
  const printed = await page.evaluate(() => ({
    bar: getComputedStyle(document.getElementById('worksheet-bar')).display,
    controls: getComputedStyle(document.getElementById('lesson-controls')).display,
    fields: [...document.querySelectorAll('#lesson-body input.blank-field')].filter((i) => getComputedStyle(i).display !== 'none').length,
    marks: [...document.querySelectorAll('#lesson-body .mark')].filter((m) => getComputedStyle(m).display !== 'none').length,
  }));
  assert.deepEqual(printed, { bar: 'none', controls: 'none', fields: blanks.length, marks: 0 }, 'the printed worksheet');
  await page.screenshot({ path: join(work, `worksheet_print_${lang}.png`), fullPage: true });
  // The answer key shows only when the key is printed, with every blank's value.
  const keyShown = () => page.$eval('#lesson-body .worksheet-key', (k) => getComputedStyle(k).display !== 'none');
  assert.equal(await keyShown(), false, 'the printed worksheet shows its answer key');
  await page.evaluate(() => { document.body.dataset.printing = 'key'; });
  assert.equal(await keyShown(), true, 'the printed answer key lacks the key');
  assert.equal(await page.$$eval('#lesson-body .worksheet-key li', (l) => l.length), blanks.length);
  await page.evaluate(() => delete document.body.dataset.printing);
  await page.emulateMedia({ media: 'screen' });
  assert.equal(await keyShown(), false, 'the answer key shows on the screen');

  // "Save answers" (Space) downloads the file; the CLI checks it with the same marks.
  await tabTo(page, '#worksheet-save');
  const [download] = await Promise.all([page.waitForEvent('download'), page.keyboard.press('Space')]);
  const saved = join(work, `saved_${lang}.txt`);
  await download.saveAs(saved);
  assert.equal(download.suggestedFilename(), lang === 'pl' ? 'ODPOWIEDZI.txt' : 'ANSWERS.txt');
  const content = readFileSync(saved, 'utf8');
  for (const value of typed.values()) assert.ok(content.includes(` = ${value} `), `the file lacks ${value}: ${content}`);
  const cli = lesson(['sphere', '--pixel', pixel.join(','), '--lang', lang, '--answers', saved]);
  assert.equal(cli.code, 1, 'the CLI finds a wrong answer');
  const report = squeezed(cli.out);
  for (const m of marks) assert.ok(report.includes(squeezed(m.text)), `the CLI's report lacks the page's mark: ${m.text}\n${cli.out}`);
  const cliMarks = cli.out.split('\n').filter((line) => /^ {2}[✓✗·] /.test(line));
  assert.equal(cliMarks.length, marks.length, 'as many marks as the CLI');
  assert.ok(report.includes(squeezed(summary)), `the summary: ${summary}`);
  assert.ok((await page.textContent('#worksheet-result')).includes('--answers'), 'the saved note names the command');

  // Shown again (the lesson's mode and back), the worksheet keeps what was typed.
  await page.locator('#lesson-mode-lesson').check();
  await page.waitForFunction(() => document.getElementById('lesson-body').dataset.mode === 'lesson');
  await page.locator('#lesson-mode-worksheet').check();
  await page.waitForFunction(() => document.getElementById('lesson-body').dataset.mode === 'worksheet');
  for (const [n, value] of typed) assert.equal(await page.inputValue(`#blank-${n}`), value, `blank ${n} lost its answer`);

  // The worksheet mode is in the URL too.
  hash = await page.evaluate(() => location.hash);
  assert.match(hash, /[#&]lw=1(&|$)/);
  page = await open(file, hash);
  assert.equal(await page.evaluate(() => document.getElementById('lesson-body').dataset.mode), 'worksheet');
  assert.equal(await page.locator('#lesson-body input.blank-field').count(), blanks.length);
}

await browser.close();
if (failures.length) {
  console.error(failures.join('\n'));
  process.exit(1);
}
console.log('web.worksheet: marks equal promyk lesson --answers on the saved file; the URL reopens the lesson; axe-core clean');
