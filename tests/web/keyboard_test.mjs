// Every control of the page from the keyboard alone (issue 17, "Quality"):
// Debian's chromium, headless, driven by playwright-core.
//   node keyboard_test.mjs PROMYK NODE_MODULES LESSONS_DIR WORKDIR
// Tab walks the whole page, with a lesson open: every control a reader can
// see (button, field, list, check box, slider, link, summary, the image and
// the 3D view) is reached, in an order that runs down the page, and each
// shows a focus ring while it has focus (an outline or a shadow that it does
// not have without focus). Then the controls' own keys: Enter and Space press
// a button, Space ticks a check box, the arrows step a list, the image moves
// its pixel, a slider moves. Leaves WORKDIR/focus.png (a focused control).
import { mkdirSync, rmSync } from 'node:fs';
import { join } from 'node:path';
import assert from 'node:assert/strict';
import { startBrowser, exportPage } from './harness.mjs';

const [promyk, modules, lessons, work] = process.argv.slice(2);
rmSync(work, { recursive: true, force: true });
mkdirSync(work, { recursive: true });

const file = exportPage(promyk, work, 'page.html', ['--scene', join(lessons, 'scenes', 'everything.json'), '--w', '16']);
const { browser, failures, open } = await startBrowser(modules, work);
const page = await open(file, '#p=8,8');
await page.selectOption('#lesson-select', 'sphere');
await page.waitForSelector('#lesson-body section.lesson-step');
await page.evaluate(() => document.activeElement && document.activeElement.blur());

// The controls a reader can see and use: what Tab must reach. Each is
// numbered (data-kbd) so that two alike (the sliders) are told apart.
const controls = () => page.evaluate(() => {
  const selector = 'button, input, select, textarea, a[href], summary, [tabindex]:not([tabindex="-1"])';
  const name = (e) => e.id || e.getAttribute('aria-label') || (e.labels && e.labels[0] && e.labels[0].textContent.trim()) ||
    `${e.tagName.toLowerCase()}:${(e.textContent || e.name || '').trim().slice(0, 30)}`;
  // A group of radio buttons is one stop of Tab (its checked button); the
  // arrows move within it, checked below.
  const radioStop = (e) => e.type !== 'radio' || e.checked ||
    !document.querySelector(`input[type="radio"][name="${e.name}"]:checked`);
  return [...document.querySelectorAll(selector)]
    .filter((e) => !e.disabled && e.getClientRects().length > 0 && getComputedStyle(e).visibility !== 'hidden' &&
      !e.closest('[hidden], [inert]') && e.tabIndex >= 0 && radioStop(e))
    .map((e, k) => {
      e.dataset.kbd = String(k);
      return name(e);
    });
});

// The focused control's number, and whether its ring shows: an outline or
// a shadow while it has focus.
const focused = () => page.evaluate(() => {
  const e = document.activeElement;
  if (!e || e === document.body) return null;
  const s = getComputedStyle(e);
  const ring = (s.outlineStyle !== 'none' && parseFloat(s.outlineWidth) > 0) || (s.boxShadow && s.boxShadow !== 'none');
  return { kbd: e.dataset.kbd, id: e.id, ring };
});

const wanted = await controls();
assert.ok(wanted.length > 40, `only ${wanted.length} controls found: ${wanted}`);
const reached = [];
const noRing = [];
for (let k = 0; k < wanted.length * 2 + 10; ++k) {
  await page.keyboard.press('Tab');
  const at = await focused();
  if (!at) continue;
  if (reached.length && at.kbd === reached[0].kbd) break; // round the page once
  reached.push(at);
  if (!at.ring) noRing.push(at.kbd === undefined ? `unlisted #${at.id}` : wanted[Number(at.kbd)]);
  if (at.id === 'scene-copy') await page.screenshot({ path: join(work, 'focus.png') });
}
const got = new Set(reached.map((r) => r.kbd));
const missed = wanted.filter((_, k) => !got.has(String(k)));
assert.deepEqual(missed, [], `controls Tab never reaches: ${missed.join(', ')}`);
assert.deepEqual(noRing, [], `controls with no visible focus: ${noRing.join(', ')}`);

// Enter and Space press buttons; the arrows and Space work the rest.
{
  await page.focus('#step-next');
  const counter = () => page.textContent('#step-counter');
  const before = await counter();
  await page.keyboard.press('Enter');
  const afterEnter = await counter();
  assert.notEqual(afterEnter, before, 'Enter on "next" steps');
  await page.keyboard.press('Space');
  assert.notEqual(await counter(), afterEnter, 'Space on "next" steps');

  await page.focus('#atlas-toggle');
  const ticked = await page.isChecked('#atlas-toggle');
  await page.keyboard.press('Space');
  assert.equal(await page.isChecked('#atlas-toggle'), !ticked, 'Space ticks the atlas');

  await page.focus('#real');
  await page.keyboard.press('ArrowDown');
  assert.notEqual(await page.inputValue('#real'), 'double', 'the arrows choose another real type');

  await page.focus('#image');
  const pixel = async () => new URLSearchParams((await page.evaluate(() => location.hash)).slice(1)).get('p');
  const was = await pixel();
  await page.keyboard.press('ArrowRight');
  assert.notEqual(await pixel(), was, 'the arrow keys move the image\'s pixel');

  // The arrows move within a group of radio buttons (the lesson's modes).
  const radios = await page.$$eval('input[type="radio"]', (all) => all.filter((r) => r.getClientRects().length > 0).map((r) => r.name));
  assert.ok(radios.length >= 2, 'a group of radio buttons on the page');
  const group = radios[0];
  const checked = () => page.$eval(`input[type="radio"][name="${group}"]:checked`, (r) => r.id || r.value);
  await page.focus(`input[type="radio"][name="${group}"]:checked`);
  const first = await checked();
  await page.keyboard.press('ArrowRight');
  assert.notEqual(await checked(), first, `the arrows move within the radio group ${group}`);
  await page.keyboard.press('ArrowLeft');
  assert.equal(await checked(), first);

  const slider = await page.$('#scene-panel input[type="range"]');
  assert.ok(slider, 'a slider in the scene panel');
  const value = await slider.evaluate((s) => s.value);
  await slider.focus();
  await page.keyboard.press('ArrowRight');
  assert.notEqual(await slider.evaluate((s) => s.value), value, 'the arrow keys move a slider');
}

await browser.close();
assert.deepEqual(failures, [], 'console errors or requests');
console.log(`keyboard test: passed (${reached.length} controls in Tab order, ${wanted.length} listed)`);
