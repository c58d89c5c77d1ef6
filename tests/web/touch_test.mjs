// The page on a classroom tablet and a phone (issue 17, "Quality"): Debian's
// chromium, headless, with touch emulated (playwright-core's hasTouch, and
// the DevTools protocol's Input.dispatchTouchEvent for drags and pinches,
// which playwright has no call for).
//   node touch_test.mjs PROMYK NODE_MODULES LESSONS_DIR WORKDIR
// At 1024 × 768 with touch, every feature by touch alone: tap a pixel to
// select it, tap through the derivation's and a lesson's steps, turn the 3D
// view with one finger and pinch it nearer and farther with two (the page
// must not scroll instead), tap a scene field and type a value (the image is
// rendered again). At 375 × 667 (a phone) the image and the derivation are
// shown and nothing reaches past the window's right edge. Leaves
// WORKDIR/tablet.png and phone.png to look at.
import { mkdirSync, rmSync } from 'node:fs';
import { join } from 'node:path';
import assert from 'node:assert/strict';
import { startBrowser, exportPage, canvasPixels } from './harness.mjs';

const [promyk, modules, lessons, work] = process.argv.slice(2);
rmSync(work, { recursive: true, force: true });
mkdirSync(work, { recursive: true });

const file = exportPage(promyk, work, 'touch.html', ['--scene', join(lessons, 'scenes', 'floor.json'), '--w', '32']);
const { browser, failures, open } = await startBrowser(modules, work, {
  viewport: { width: 1024, height: 768 },
  hasTouch: true,
});
const page = await open(file);
const cdp = await browser.newCDPSession(page);

// The centre of an element in the viewport (scrolled into view first).
async function centre(selector) {
  await page.locator(selector).scrollIntoViewIfNeeded();
  const box = await page.locator(selector).boundingBox();
  assert.ok(box && box.width > 0 && box.height > 0, `${selector} is not shown`);
  return { x: box.x + box.width / 2, y: box.y + box.height / 2, box };
}

// Fingers: a list of paths, each a list of points, all the same length; the
// fingers go down at their first points, move together, and lift.
async function touch(paths) {
  const at = (k) => paths.map((path, id) => ({ x: path[k].x, y: path[k].y, id }));
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at(0) });
  for (let k = 1; k < paths[0].length; ++k)
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: at(k) });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
}
const line = (from, to, steps = 8) =>
  Array.from({ length: steps + 1 }, (_, k) => ({ x: from.x + ((to.x - from.x) * k) / steps, y: from.y + ((to.y - from.y) * k) / steps }));

const hashParam = async (name) => new URLSearchParams((await page.evaluate(() => location.hash)).slice(1)).get(name);
const scrolled = () => page.evaluate(() => [window.scrollX, window.scrollY]);

const view3dPixels = () => canvasPixels(page);

// --- Select a pixel with a tap ------------------------------------------
{
  const { box } = await centre('#image');
  const w = 32;
  for (const [i, j] of [[20, 9], [3, 27]]) {
    await page.touchscreen.tap(box.x + ((j + 0.5) / w) * box.width, box.y + ((i + 0.5) / w) * box.height);
    await page.waitForFunction((p) => new URLSearchParams(location.hash.slice(1)).get('p') === p, `${i},${j}`);
    assert.match(await page.textContent('#derivation-heading'), new RegExp(`\\(${i}, ${j}\\)`), `tapped pixel (${i}, ${j})`);
  }
}

// --- Step through the derivation with taps --------------------------------
{
  const first = await centre('#step-first');
  await page.touchscreen.tap(first.x, first.y);
  assert.match(await page.textContent('#step-counter'), /^step 1 of \d+$/);
  const next = await centre('#step-next');
  await page.touchscreen.tap(next.x, next.y);
  await page.touchscreen.tap(next.x, next.y);
  assert.match(await page.textContent('#step-counter'), /^step 3 of \d+$/, 'two taps on "next"');
  assert.equal(await hashParam('s'), '2'); // the URL counts steps from 0
}

// --- Turn the 3D view with one finger, pinch it with two ------------------
{
  const { x, y, box } = await centre('#view3d');
  const before = await view3dPixels();
  const page0 = await scrolled();
  await touch([line({ x: x - box.width / 4, y }, { x: x + box.width / 4, y: y + 20 })]);
  const turned = await view3dPixels();
  assert.notEqual(turned.hash, before.hash, 'a one-finger drag turns the 3D view');
  assert.deepEqual(await scrolled(), page0, 'a drag on the 3D view scrolls the page');

  // Fingers apart: nearer, so more of the canvas is drawn; together again by
  // as much: back where it was, not turned (a pinch only zooms).
  const gap = Math.min(box.width, box.height) / 8;
  const left = [{ x: x - gap, y }, { x: x - 3 * gap, y }];
  const right = [{ x: x + gap, y }, { x: x + 3 * gap, y }];
  await touch([line(left[0], left[1]), line(right[0], right[1])]);
  const nearer = await view3dPixels();
  assert.ok(nearer.drawn > turned.drawn, `pinch out draws more (${turned.drawn} → ${nearer.drawn} pixels)`);
  await touch([line(left[1], left[0]), line(right[1], right[0])]);
  const back = await view3dPixels();
  assert.equal(back.hash, turned.hash, `a pinch in by as much is back to the view before (${back.drawn} pixels drawn, ${turned.drawn} before)`);
  assert.deepEqual(await scrolled(), page0, 'a pinch on the 3D view scrolls or zooms the page');
}

// --- Edit a scene field by touch -----------------------------------------
{
  const renders = () => page.evaluate(() => Number(document.body.dataset.renders || 0));
  const before = await renders();
  const field = await centre('#field-spheres-0-r');
  await page.touchscreen.tap(field.x, field.y);
  assert.equal(await page.evaluate(() => document.activeElement.id), 'field-spheres-0-r', 'a tap focuses the field');
  await page.keyboard.press('Control+A');
  await page.keyboard.type('0.8');
  await page.waitForFunction((n) => Number(document.body.dataset.renders || 0) > n, before, { timeout: 120000 });
  assert.equal(await page.inputValue('#field-spheres-0-r'), '0.8');
  assert.match(await page.evaluate(() => location.hash), /scene=/, 'the edited scene is in the URL');
}

// --- A lesson, stepped by taps -------------------------------------------
{
  await page.selectOption('#lesson-select', 'sphere');
  await page.waitForSelector('#lesson-body section.lesson-step');
  const mode = await centre('#lesson-step-mode');
  await page.touchscreen.tap(mode.x, mode.y);
  assert.ok(await page.isChecked('#lesson-step-mode'), 'a tap turns step mode on');
  const shown = () => page.$$eval('#lesson-body section.lesson-step', (s) => s.filter((x) => !x.hidden).map((x) => x.dataset.step));
  const firstStep = await shown();
  assert.equal(firstStep.length, 1);
  const next = await centre('#lesson-next');
  await page.touchscreen.tap(next.x, next.y);
  const secondStep = await shown();
  assert.equal(secondStep.length, 1);
  assert.notDeepEqual(secondStep, firstStep, 'a tap on the lesson\'s "next" shows the next step');
}
await page.screenshot({ path: join(work, 'tablet.png') });

// --- A phone: the image and the derivation, nothing past the right edge ----
{
  await page.setViewportSize({ width: 375, height: 667 });
  await page.evaluate(() => window.scrollTo(0, 0));
  for (const selector of ['#image', '#steps']) {
    const { box } = await centre(selector);
    assert.ok(box.width >= 100 && box.height >= 50, `${selector} on a phone: ${box.width} × ${box.height}`);
    assert.ok(box.x >= 0 && box.x + box.width <= 375 + 0.5, `${selector} reaches past the phone's edge (${box.x}, ${box.width})`);
  }
  const wide = await page.evaluate(() => document.documentElement.scrollWidth);
  assert.ok(wide <= 375, `the page scrolls sideways on a phone (${wide} px wide)`);
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.screenshot({ path: join(work, 'phone.png'), fullPage: false });
}

await browser.close();
assert.deepEqual(failures, [], 'console errors or requests');
console.log('touch test: passed');
