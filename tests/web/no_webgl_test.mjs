// The page in a browser without WebGL (switched off by a school's policy, no
// graphics driver; Firefox headless here): Debian's chromium with WebGL
// disabled. The page still opens with no console error, says why there is
// no 3D view, hides its empty frame, and lists in words what the view would
// draw for the selected pixel; the image, the derivation and a re-render
// work.
//   node no_webgl_test.mjs PROMYK NODE_MODULES LESSONS_DIR WORKDIR
import { mkdirSync, rmSync } from 'node:fs';
import { join } from 'node:path';
import assert from 'node:assert/strict';
import { startBrowser, exportPage } from './harness.mjs';

const [promyk, modules, lessons, work] = process.argv.slice(2);
rmSync(work, { recursive: true, force: true });
mkdirSync(work, { recursive: true });

const file = exportPage(promyk, work, 'page.html', ['--scene', join(lessons, 'scenes', 'floor.json'), '--w', '16']);
const { browser, failures, open } = await startBrowser(modules, work, {
  args: ['--no-sandbox', '--disable-gpu', '--disable-webgl', '--disable-3d-apis', '--disable-background-networking',
    '--disable-component-update', '--disable-sync', '--no-first-run'],
});
for (const lang of ['en', 'pl']) {
  const page = await open(file, `#p=10,4&lang=${lang}`);
  assert.equal(await page.evaluate(() => !!document.createElement('canvas').getContext('webgl2')), false,
    'WebGL is still on: the test does not test what it says');
  const hint = await page.textContent('#view-hint');
  assert.match(hint, lang === 'en' ? /no WebGL, so there is no 3D view/ : /nie udostępnia WebGL/, `the hint (${lang}): ${hint}`);
  assert.equal(await page.isVisible('#view-frame'), false, 'the empty 3D frame is shown');
  const list = await page.$$eval('#view-list li', (items) => items.map((li) => li.textContent));
  assert.ok(list.some((item) => /hit point P/.test(item) || /punkt trafienia P/.test(item)), `the list in words (${lang}): ${list}`);
  assert.match(await page.textContent('#derivation-heading'), /\(10, 4\)/);
  assert.ok((await page.$$('#steps .step')).length > 10, 'the derivation is shown');
  if (lang === 'en') {
    // A re-render through the workers.
    const before = await page.evaluate(() => Number(document.body.dataset.renders || 0));
    await page.fill('#field-spheres-0-r', '0.8');
    await page.waitForFunction((n) => Number(document.body.dataset.renders || 0) > n, before, { timeout: 120000 });
    await page.screenshot({ path: join(work, 'no_webgl.png') });
  }
}
await browser.close();
assert.deepEqual(failures, [], 'console errors or requests');
console.log('no-WebGL test: passed');
