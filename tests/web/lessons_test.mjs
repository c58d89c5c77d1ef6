// The lessons section in a real browser (issue 17, "lessons and worksheets
// in the page"): Debian's chromium, headless, driven by playwright-core.
//   node lessons_test.mjs PROMYK NODE_MODULES LESSONS_DIR WORKDIR
// A lesson opened with a chosen pixel ("use this pixel" on a page showing
// the lesson's own scene) shows the numbers of `promyk lesson NAME --pixel
// I,J --format markdown` in the same language, number for number (both
// languages; lessons on the article's scene, shadows and Phong); a hostile
// scene name shows as text; step mode reveals one step at a time, answers
// open from the keyboard; the print stylesheet shows the lesson alone.
// Leaves WORKDIR/lessons.png (the section) and lessons_print.png (print
// media) to look at.
import { mkdirSync, rmSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import assert from 'node:assert/strict';
import { startBrowser, runPromyk, exportPage as exportTo } from './harness.mjs';

const [promyk, modules, lessons, work] = process.argv.slice(2);
rmSync(work, { recursive: true, force: true });
mkdirSync(work, { recursive: true });
const run = (args) => runPromyk(promyk, args, work);
const exportPage = (name, args) => exportTo(promyk, work, name, args);

// The numbers a reader sees, in order: formulas (TeX) and list markers left out.
const numbersOf = (text) => text.match(/[−-]?\d+(?:[.,]\d+)*(?:e[+−-]?\d+)?/g) || [];
const markdownNumbers = (markdown) =>
  numbersOf(markdown.replace(/\$[^$\n]+\$/g, ' ').replace(/(^|\n) *\d+\. /g, '$1'));

const { browser, failures, open } = await startBrowser(modules, work);

// The page's lesson text without its typeset formulas.
const pageNumbers = (page) =>
  page.evaluate(() => {
    const copy = document.getElementById('lesson-body').cloneNode(true);
    for (const math of copy.querySelectorAll('span.math')) math.replaceWith(' ');
    return copy.textContent;
  }).then(numbersOf);

// Opens lesson `name` and runs it for `pixel` by "use this pixel"; waits
// until the section shows that lesson for that pixel (no timing assumed).
async function openLesson(page, name, pixel) {
  await page.selectOption('#lesson-select', name);
  await page.waitForFunction((n) => document.getElementById('lesson-body').dataset.lesson === n, name);
  await page.locator('#lesson-use-pixel').click();
  await page.waitForFunction(([n, p]) => {
    const body = document.getElementById('lesson-body');
    return body.dataset.lesson === n && body.dataset.pixels === JSON.stringify([p]);
  }, [name, pixel]);
}

// Each lesson on a page that shows its own scene at its w (8).
const cases = [
  { name: 'sphere', scene: null, pixel: [3, 4] },
  { name: 'lambert', scene: null, pixel: [5, 1] },
  { name: 'shadows', scene: 'shadows.json', pixel: [7, 2] },
  { name: 'phong', scene: 'phong.json', pixel: [3, 5] },
];
const pages = new Map();
for (const c of cases) {
  const key = c.scene || 'article';
  if (!pages.has(key))
    pages.set(key, exportPage(`${key}.html`, [...(c.scene ? ['--scene', join(lessons, 'scenes', c.scene)] : []), '--w', '8']));
}
let page;
for (const lang of ['en', 'pl']) {
  for (const c of cases) {
    page = await open(pages.get(c.scene || 'article'), `#p=${c.pixel.join(',')}&lang=${lang}`);
    await openLesson(page, c.name, c.pixel);
    const shown = await pageNumbers(page);
    const markdown = run(['lesson', c.name, '--pixel', c.pixel.join(','), '--format', 'markdown', '--lang', lang]);
    const expected = markdownNumbers(markdown);
    assert.ok(expected.length > 20, `${c.name} ${lang}: few numbers in the markdown`);
    assert.deepEqual(shown, expected, `${c.name} ${lang} (${c.pixel}): the page's numbers are the CLI's`);
    // The page says it runs on the lesson's own scene for that pixel.
    const note = await page.textContent('#lesson-note');
    assert.ok(note.includes(`promyk lesson ${c.name} --pixel ${c.pixel.join(',')}`), `${c.name} ${lang}: ${note}`);
    // A Polish lesson writes the decimal comma; every formula is typeset.
    if (lang === 'pl') assert.ok(shown.some((n) => /\d,\d/.test(n)), `${c.name}: no decimal comma`);
    assert.equal(await page.locator('#lesson-body span.math:not(:has(.katex))').count(), 0, 'a formula not typeset');
  }
}

// "Use this pixel" on a page showing another scene than the lesson's: the
// lesson runs on the page's scene, as `promyk lesson NAME --scene FILE` does.
for (const lang of ['en', 'pl']) {
  page = await open(pages.get('article'), `#p=3,4&lang=${lang}`);
  await openLesson(page, 'shadows', [3, 4]);
  const markdown = run(['lesson', 'shadows', '--scene', join(lessons, 'scenes', 'article.json'), '--w', '8', '--pixel', '3,4',
    '--format', 'markdown', '--lang', lang]);
  assert.deepEqual(await pageNumbers(page), markdownNumbers(markdown), `shadows on the article's scene (${lang})`);
  const lacks = markdown.split('\n').find((line) => line.includes('shadows.json'));
  assert.ok(lacks && (await page.textContent('#lesson-body')).includes(lacks), `the scene-lacks line (${lang}): ${lacks}`);
  assert.ok((await page.textContent('#lesson-note')).includes('--scene'), 'the note names lesson --scene');
}

// The list follows the language switch: Polish titles, English after the switch.
page = await open(pages.get('article'), '#lang=pl');
const titles = async () => page.$$eval('#lesson-select option', (o) => o.map((x) => x.textContent));
const plTitles = await titles();
await page.locator('#lang-switch button[data-lang="en"]').click();
await page.waitForFunction(() => document.getElementById('lesson-body').lang === 'en');
const enTitles = await titles();
assert.equal(plTitles.length, enTitles.length);
assert.ok(plTitles.length >= 11);
assert.notDeepEqual(plTitles, enTitles);

// Step mode: one step at a time; next and previous; an answer behind a reveal opened by the keyboard.
await page.selectOption('#lesson-select', 'sphere');
await page.waitForFunction(() => document.getElementById('lesson-body').dataset.lesson === 'sphere');
await page.locator('#lesson-step-mode').check();
const visibleSteps = () => page.$$eval('#lesson-body section.lesson-step', (s) => s.filter((x) => !x.hidden).map((x) => x.dataset.step));
assert.deepEqual(await visibleSteps(), ['1']);
await page.locator('#lesson-next').click();
assert.deepEqual(await visibleSteps(), ['2']);
await page.locator('#lesson-prev').click();
assert.deepEqual(await visibleSteps(), ['1']);
// The arrows walk the lesson's steps while the focus is in the section.
await page.locator('#lesson-next').focus();
await page.keyboard.press('ArrowRight');
assert.deepEqual(await visibleSteps(), ['2']);
await page.keyboard.press('ArrowLeft');
assert.deepEqual(await visibleSteps(), ['1']);
const withAnswer = await page.$eval('#lesson-body details.answer', (d) => Number(d.dataset.step));
for (let k = 1; k < withAnswer; ++k) await page.locator('#lesson-next').click();
assert.deepEqual(await visibleSteps(), [String(withAnswer)]);
const reveal = page.locator(`#lesson-body details.answer[data-step="${withAnswer}"]`).first();
assert.equal(await reveal.evaluate((d) => d.open), false, 'an answer shows before its reveal');
await reveal.locator('summary').focus();
await page.keyboard.press('Enter');
assert.equal(await reveal.evaluate((d) => d.open), true, 'Enter on the reveal does not open the answer');
// Visible focus on the lesson's controls, reached by the keyboard.
await page.locator('#lesson-prev').focus();
await page.keyboard.press('Shift+Tab');
await page.keyboard.press('Tab');
const focused = await page.evaluate(() => ({ id: document.activeElement.id, outline: getComputedStyle(document.activeElement).outlineStyle }));
assert.equal(focused.id, 'lesson-prev');
assert.notEqual(focused.outline, 'none', 'no visible focus');
await page.locator('#lesson-step-mode').uncheck();
await page.locator('#lessons-panel').screenshot({ path: join(work, 'lessons.png') });

// Print media: the lesson alone, every step, no interface around it.
await page.emulateMedia({ media: 'print' });
const printed = await page.evaluate(() => ({
  header: getComputedStyle(document.querySelector('body > header')).display,
  title: getComputedStyle(document.querySelector('#lesson-body h1')).display,
  image: getComputedStyle(document.getElementById('image-panel')).display,
  controls: getComputedStyle(document.getElementById('lesson-controls')).display,
  steps: [...document.querySelectorAll('#lesson-body section.lesson-step')].filter((s) => getComputedStyle(s).display !== 'none').length,
  all: document.querySelectorAll('#lesson-body section.lesson-step').length,
  answers: [...document.querySelectorAll('#lesson-body details.answer')].filter((d) => getComputedStyle(d).display !== 'none').length,
}));
assert.equal(printed.header, 'none');
assert.equal(printed.title, 'block', "the printed lesson lacks its title");
assert.equal(printed.image, 'none');
assert.equal(printed.controls, 'none');
assert.equal(printed.steps, printed.all);
assert.equal(printed.answers, 0, 'a printed lesson shows its answers');
// About A4's width at 96 dpi (210 mm), as the printer lays it out.
await page.setViewportSize({ width: 794, height: 1123 });
await page.screenshot({ path: join(work, 'lessons_print.png'), fullPage: true });
// The answer key: the same with every answer shown.
const key = await page.evaluate(() => {
  document.body.dataset.printing = 'key';
  for (const d of document.querySelectorAll('#lesson-body details.answer')) d.open = true;
  return [...document.querySelectorAll('#lesson-body details.answer')].filter((d) => getComputedStyle(d).display !== 'none').length;
});
assert.ok(key > 0, 'the answer key shows no answer');
await page.screenshot({ path: join(work, 'lessons_key.png'), fullPage: true });
await page.evaluate(() => delete document.body.dataset.printing);
await page.emulateMedia({ media: 'screen' });
await page.setViewportSize({ width: 1600, height: 1000 });

// A hostile scene name shows as text, not markup, in the lesson.
const hostileName = `<img src=x onerror="window.pwned=1">&amp; "q" <script>window.pwned=2</script>`;
const hostile = join(work, 'hostile.json');
writeFileSync(hostile, JSON.stringify({ name: hostileName, z_E: 2, spheres: [{ S: [0, 0, 3.2], r: 1.1 }], lights: [{ L: [1.5, 1, 1], I: 1 }] }));
page = await open(exportPage('hostile.html', ['--scene', hostile, '--w', '8']), '#p=3,4&lang=en');
await openLesson(page, 'sphere', [3, 4]);
const hostileShown = await page.evaluate(() => ({
  img: document.querySelectorAll('#lesson-body img, #lesson-body script').length,
  text: document.getElementById('lesson-body').textContent,
  pwned: window.pwned,
}));
assert.equal(hostileShown.img, 0, 'the scene name became markup');
assert.equal(hostileShown.pwned, undefined);
assert.ok(hostileShown.text.includes(hostileName), 'the scene name is not shown as written');

await browser.close();
if (failures.length) {
  console.error(failures.join('\n'));
  process.exit(1);
}
console.log(`web.lessons: ${cases.length} lessons × 2 languages equal to promyk lesson --format markdown`);
