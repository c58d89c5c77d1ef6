// The scene panel in a real browser (issue 17, "edit the scene live"):
// Debian's chromium, headless, driven by playwright-core.
//   node edit_test.mjs PROMYK NODE_MODULES LESSONS_DIR WORKDIR
// Edits fields of exported pages and checks the page's image, byte for byte,
// against `promyk render` of the scene and command line the page copies;
// adds and removes objects; an invalid value shows the loader's own message
// (the CLI's `scene check` words, both languages) by its field and keeps the
// last image; the URL reopens the edited scene; the selected pixel's trace
// follows the edit; the sliders work from the keyboard. Prints the re-render
// time at w = 256 and 512 and the page's size (figures, not checked), and
// leaves WORKDIR/edit.png (the panel) and edit_256.png (after edits at
// w = 256 with a pixel selected) to look at.
import { spawnSync } from 'node:child_process';
import { mkdirSync, rmSync, readFileSync, writeFileSync, statSync } from 'node:fs';
import { startBrowser, runPromyk, exportPage as exportTo, readNetpbm } from './harness.mjs';
import { join } from 'node:path';
import assert from 'node:assert/strict';

const [promyk, modules, lessons, work] = process.argv.slice(2);

rmSync(work, { recursive: true, force: true });
mkdirSync(work, { recursive: true });
const everything = join(lessons, 'scenes', 'everything.json');

const run = (args, cwd = work) => runPromyk(promyk, args, cwd);

const exportPage = (name, args) => exportTo(promyk, work, name, args);

// bypassCSP: axe-core is injected as a script the page's CSP would refuse.
const { browser, failures, open } = await startBrowser(modules, work, { acceptDownloads: true, bypassCSP: true });

const renders = (page) => page.evaluate(() => Number(document.body.dataset.renders || 0));

// Runs `change` and waits for the render it starts to be shown.
async function rendered(page, change) {
  const before = await renders(page);
  await change();
  await page.waitForFunction((n) => Number(document.body.dataset.renders || 0) > n, before, { timeout: 120000 });
  // Later edits may have started further renders: wait until none is under way.
  await page.waitForFunction(() => !/…/.test(document.getElementById('render-status').textContent), null, { timeout: 120000 });
}

const pageImage = async (page) => {
  const image = await page.evaluate(() => window.promykPage.image());
  return { w: image.w, channels: image.channels, bytes: Buffer.from(image.base64, 'base64'), map: Buffer.from(image.map, 'base64') };
};

// The scene and command line "Copy scene" gives; the command is run as the
// page wrote it (the scene saved under the name it says), into a PGM/PPM
// instead of a PNG, and its pixels must be the page's, byte for byte.
async function checkAgainstCli(page, what) {
  await page.click('#scene-copy');
  const copied = await page.inputValue('#scene-copied');
  const lines = copied.trimEnd().split('\n');
  const command = lines.pop();
  const sceneText = lines.join('\n').trimEnd() + '\n';
  const args = command.split(' ');
  assert.equal(args[0], 'promyk', `${what}: the command ${command}`);
  const file = args[args.indexOf('--scene') + 1];
  writeFileSync(join(work, file), sceneText);
  // The scene is one `promyk scene check` accepts.
  run(['scene', 'check', file]);
  const shown = await pageImage(page);
  const out = shown.channels === 3 ? 'cli.ppm' : 'cli.pgm';
  const renderArgs = args.slice(1);
  renderArgs[renderArgs.indexOf('-o') + 1] = out;
  run(renderArgs);
  const cli = readNetpbm(join(work, out));
  assert.equal(shown.w, cli.w, `${what}: w`);
  assert.equal(shown.channels, cli.channels, `${what}: channels`);
  assert.ok(shown.bytes.equals(cli.bytes), `${what}: the page's image differs from ${command}`);
  // The branch overlay follows: each pixel's category is the colour
  // `render --map branch` draws for it, with the same settings.
  const mapArgs = [...renderArgs];
  mapArgs[mapArgs.indexOf('-o') + 1] = 'map.ppm';
  run([...mapArgs, '--map', 'branch']);
  const map = readNetpbm(join(work, 'map.ppm'));
  const legend = await page.$$eval('#legend-list li', (items) => items.map((li) => [Number(li.dataset.index), li.dataset.rgb]));
  const categoryOf = new Map(legend.map(([index, rgb]) => [rgb, index]));
  for (let p = 0; p < shown.w * shown.w; ++p) {
    const rgb = `${map.bytes[3 * p]},${map.bytes[3 * p + 1]},${map.bytes[3 * p + 2]}`;
    if (categoryOf.get(rgb) !== shown.map[p])
      assert.fail(`${what}: pixel (${Math.floor(p / shown.w)}, ${p % shown.w}) is category ${shown.map[p]} in the page, ${rgb} in render --map branch`);
  }
  return { shown, sceneText, command };
}

// The loader's message for a scene, as `promyk scene check` words it
// ("promyk: FILE: /pointer: what"): the what.
function cliFault(sceneText, pointer, lang) {
  writeFileSync(join(work, 'bad.json'), sceneText);
  const result = spawnSync(promyk, ['--lang', lang, 'scene', 'check', 'bad.json'], { cwd: work, encoding: 'utf8', env: { ...process.env, LANG: 'C' } });
  assert.equal(result.status, 3, `scene check of the invalid scene: ${result.stderr}`);
  const line = result.stderr.split('\n').find((l) => l.includes(`${pointer}: `));
  assert.ok(line, `no message for ${pointer} in ${result.stderr}`);
  return line.slice(line.indexOf(`${pointer}: `) + pointer.length + 2).trim();
}

// The page's phases of the last edit (web_export/page/timing.js): ms per
// phase, summed over its measures, once the frames after the image are drawn.
async function phases(page) {
  return page.evaluate(async () => {
    for (let k = 0; k < 3; ++k) await new Promise((resolve) => requestAnimationFrame(resolve));
    const sums = {};
    for (const m of performance.getEntriesByType('measure'))
      if (m.name.startsWith('promyk:')) sums[m.name.slice(7)] = (sums[m.name.slice(7)] || 0) + m.duration;
    performance.clearMeasures();
    return sums;
  });
}

const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];

// Accessibility (the issue's Quality section): axe-core's serious and
// critical violations on the page as it is, as "id (impact): help: where".
const axeSource = readFileSync(join(modules, 'axe-core', 'axe.min.js'), 'utf8');
async function axeViolations(page) {
  await page.addScriptTag({ content: axeSource });
  return page.evaluate(async () => (await window.axe.run(document, { resultTypes: ['violations'] })).violations
    .filter((v) => v.impact === 'serious' || v.impact === 'critical')
    .map((v) => `${v.id} (${v.impact}): ${v.help}: ${v.nodes.slice(0, 4).map((n) => n.target.join(' ')).join('; ')}`));
}

const fieldError = (page, pointer) => page.$eval(`#error-${pointer.slice(1).replace(/[^A-Za-z0-9_]/g, '-')}`, (e) => (e.hidden ? '' : e.textContent));

try {
  // --- the article's scene: edit, add, remove, invalid values, the URL ---
  const article = exportPage('article.html', ['--w', '64']);
  let page = await open(article, '#p=20,40');
  const first = await pageImage(page);
  assert.equal(first.w, 64);

  // An edit re-renders the image: equal to promyk render of the copied scene.
  await rendered(page, () => page.fill('#field-spheres-0-r', '0.9'));
  const edited = await checkAgainstCli(page, 'r = 0.9');
  assert.ok(!edited.shown.bytes.equals(first.bytes), 'the edit changed the image');
  // The selected pixel was traced again in the edited scene: as promyk trace.
  const trace = await page.evaluate(() => window.promykPage.trace());
  assert.equal(trace, run(['trace', '--format', 'json', '--scene', 'scene.json', '--w', '64', '--pixel', '20,40']).trimEnd(),
    'the selected pixel\'s trace after the edit');
  // A decimal comma is read as a point (Polish pupils type one).
  await rendered(page, () => page.fill('#field-lights-0-L-0', '0,5'));
  await checkAgainstCli(page, 'x_L = 0,5');

  // Adding a plane and a light: both in the image, as the CLI renders it.
  await rendered(page, () => page.click('[data-add="planes"]'));
  const withPlane = await checkAgainstCli(page, 'a plane added');
  assert.match(withPlane.sceneText, /"planes": \[\n {4}\{"Q": \[0, -1, 0\], "n": \[0, 1, 0\]\}/);
  await rendered(page, () => page.click('[data-add="lights"]'));
  await checkAgainstCli(page, 'a light added');
  // The 3D view follows the scene.
  assert.deepEqual(await page.evaluate(() => window.promykPage.view3d()), { spheres: 1, planes: 1, lights: 2, zE: 2 });
  // ... and removing them gives the image before, byte for byte.
  await rendered(page, () => page.click('[data-remove="/lights/1"]'));
  await rendered(page, () => page.click('[data-remove="/planes/0"]'));
  const removed = await checkAgainstCli(page, 'the plane and the light removed');
  assert.ok(removed.shown.bytes.equals((await checkAgainstCli(page, 'again')).shown.bytes));
  await rendered(page, () => page.fill('#field-lights-0-L-0', '1.5'));
  const back = await pageImage(page);
  assert.ok(back.bytes.equals(edited.shown.bytes), 'after removing what was added, the image is the one before');

  // An invalid value: the loader's own message by its field, the last image kept.
  const rendersBefore = await renders(page);
  const sceneBefore = await page.evaluate(() => location.hash);
  await page.fill('#field-spheres-0-r', '-1');
  await page.waitForFunction(() => !document.getElementById('error-spheres-0-r').hidden);
  const badScene = edited.sceneText.replace('"r": 0.9', '"r": -1');
  assert.notEqual(badScene, edited.sceneText);
  assert.equal(await fieldError(page, '/spheres/0/r'), cliFault(badScene, '/spheres/0/r', 'en'));
  assert.equal(await page.getAttribute('#field-spheres-0-r', 'aria-invalid'), 'true');
  assert.equal(await page.isVisible('#scene-invalid'), true);
  await page.fill('#field-spheres-0-r', 'abc');
  await page.waitForFunction(() => /string/.test(document.getElementById('error-spheres-0-r').textContent));
  assert.equal(await fieldError(page, '/spheres/0/r'), cliFault(edited.sceneText.replace('"r": 0.9', '"r": "abc"'), '/spheres/0/r', 'en'));
  // A fault in a vector's component: by that component's field.
  await page.fill('#field-spheres-0-r', '0.9');
  await page.fill('#field-lights-0-I', '-2');
  await page.waitForFunction(() => !document.getElementById('error-lights-0-I').hidden);
  assert.equal(await fieldError(page, '/lights/0/I'), cliFault(edited.sceneText.replace('"I": 1', '"I": -2'), '/lights/0/I', 'en'));
  // The last light cannot go: the loader's message by the lights.
  await page.click('[data-remove="/lights/0"]');
  await page.waitForFunction(() => !document.getElementById('error-lights').hidden);
  await new Promise((resolve) => setTimeout(resolve, 300));
  assert.equal(await renders(page), rendersBefore, 'no render of an invalid scene');
  assert.ok((await pageImage(page)).bytes.equals(edited.shown.bytes), 'the last valid image stays');
  assert.equal(await page.evaluate(() => location.hash), sceneBefore, 'the URL keeps the last valid scene');
  await page.click('[data-add="lights"]');
  await page.fill('#field-lights-0-L-0', '1.5');
  await page.fill('#field-lights-0-L-1', '1');
  await page.fill('#field-lights-0-L-2', '1');
  await page.fill('#field-lights-0-I', '1');
  await page.waitForFunction(() => document.getElementById('error-lights').hidden && document.getElementById('error-lights-0-I').hidden);
  await page.waitForFunction((h) => location.hash === h, sceneBefore);
  // The light's fields were valid scenes on the way: a render of one may
  // still be under way (on a busy machine), and would count below.
  await page.waitForFunction(() => !/…/.test(document.getElementById('render-status').textContent), null, { timeout: 120000 });

  // In Polish: the panel's words and the loader's Polish message, for the
  // invalid value on screen when the language is switched (no edit since).
  const rendersValid = await renders(page);
  await page.fill('#field-spheres-0-r', '-1');
  await page.waitForFunction(() => !document.getElementById('error-spheres-0-r').hidden);
  assert.equal(await fieldError(page, '/spheres/0/r'), cliFault(badScene, '/spheres/0/r', 'en'));
  const statusEn = await page.textContent('#render-status');
  assert.match(statusEn, /^Rendered 64 × 64 in \d+ ms \(\d+ workers\)\.$/);
  await page.click('#lang-switch button[data-lang="pl"]');
  assert.equal(await page.textContent('#scene-heading'), 'Scena');
  // The last render's line, in Polish with the same figures.
  const [, ms, workers] = statusEn.match(/in (\d+) ms \((\d+) workers/);
  assert.equal(await page.textContent('#render-status'), `Wyrenderowano 64 × 64 w ${ms} ms (wątków roboczych: ${workers}).`);
  assert.equal(await page.inputValue('#field-spheres-0-r'), '-1');
  assert.equal(await fieldError(page, '/spheres/0/r'), cliFault(badScene, '/spheres/0/r', 'pl'));
  const polishNegative = await fieldError(page, '/spheres/0/r');
  await page.fill('#field-spheres-0-r', 'abc');
  await page.waitForFunction((before) => document.getElementById('error-spheres-0-r').textContent !== before, polishNegative);
  assert.equal(await fieldError(page, '/spheres/0/r'), cliFault(edited.sceneText.replace('"r": 0.9', '"r": "abc"'), '/spheres/0/r', 'pl'));
  // ... and back in English without an edit.
  await page.click('#lang-switch button[data-lang="en"]');
  assert.equal(await fieldError(page, '/spheres/0/r'), cliFault(edited.sceneText.replace('"r": 0.9', '"r": "abc"'), '/spheres/0/r', 'en'));
  assert.equal(await renders(page), rendersValid, 'no render of an invalid scene, in either language');
  await page.fill('#field-spheres-0-r', '0.9');
  await page.waitForFunction(() => document.getElementById('error-spheres-0-r').hidden);

  // The keyboard: a slider moves with the arrow keys and the image follows.
  await page.focus('[data-slider="/z_E"]');
  assert.equal(await page.evaluate(() => document.activeElement.getAttribute('aria-label')), 'z_E (the pane\'s distance from the eye) — slider');
  await rendered(page, () => page.keyboard.press('ArrowRight'));
  assert.equal(await page.inputValue('#field-z_E'), '2.01');
  assert.equal((await page.evaluate(() => window.promykPage.view3d())).zE, 2.01);
  const keyed = await checkAgainstCli(page, 'z_E moved by the keyboard');

  // Adding and removing from the keyboard: the new sphere's first field
  // takes the focus; after a removal, the list's add button has it.
  await page.focus('[data-add="spheres"]');
  await rendered(page, () => page.keyboard.press('Enter'));
  assert.equal(await page.evaluate(() => document.activeElement.id), 'field-spheres-1-S-0');
  assert.equal((await page.evaluate(() => window.promykPage.view3d())).spheres, 2);
  await page.focus('[data-remove="/spheres/1"]');
  await rendered(page, () => page.keyboard.press('Enter'));
  assert.equal(await page.evaluate(() => document.activeElement.dataset.add), 'spheres');
  assert.ok((await pageImage(page)).bytes.equals(keyed.shown.bytes), 'the sphere added and removed: the image before');

  // The URL reopens the edited scene (and w): the same image and fields.
  await rendered(page, () => page.fill('#field-w', '48'));
  const small = await checkAgainstCli(page, 'w = 48');
  assert.equal(small.shown.w, 48);
  assert.notEqual(keyed.command, small.command);
  const link = page.url();
  assert.match(link, /[#&]scene=/);
  assert.match(link, /[#&]w=48/);
  const reopened = await open(article, link.slice(link.indexOf('#')));
  await reopened.waitForFunction(() => Number(document.body.dataset.renders || 0) >= 1, null, { timeout: 120000 });
  assert.ok((await pageImage(reopened)).bytes.equals(small.shown.bytes), 'the link shows the edited image');
  assert.equal(await reopened.inputValue('#field-spheres-0-r'), '0.9');
  assert.equal(await reopened.inputValue('#field-z_E'), '2.01');
  page = reopened;
  // "Back to the exported scene": the exported image again.
  await rendered(page, () => page.click('#scene-reset'));
  assert.ok((await pageImage(page)).bytes.equals(first.bytes), 'the exported scene\'s image again');
  assert.doesNotMatch(page.url(), /scene=/);
  // The link pasted into the open page (hashchange, no reload): the edited
  // scene, w and fields, the same image.
  const pasted = link.slice(link.indexOf('#'));
  const loads = await page.evaluate(() => document.body.dataset.readyMs);
  await rendered(page, () => page.evaluate((h) => { location.hash = h; }, pasted));
  assert.equal(await page.evaluate(() => document.body.dataset.readyMs), loads, 'the page was not loaded again');
  assert.ok((await pageImage(page)).bytes.equals(small.shown.bytes), 'the pasted link shows the edited image');
  assert.equal(await page.inputValue('#field-spheres-0-r'), '0.9');
  assert.equal(await page.inputValue('#field-w'), '48');
  await checkAgainstCli(page, 'the pasted link');
  // A pasted link with an invalid scene: the loader's message, in the
  // page's language (and in the other one after a switch); the image stays.
  const rendersPasted = await renders(page);
  const invalidScene = small.sceneText.replace('"r": 0.9', '"r": -1');
  assert.notEqual(invalidScene, small.sceneText);
  const invalidLink = pasted.replace(/scene=[^&]*/, `scene=${Buffer.from(invalidScene).toString('base64url')}`);
  await page.evaluate((h) => { location.hash = h; }, invalidLink);
  await page.waitForFunction(() => document.getElementById('scene-link-status').textContent !== '');
  const linkStatus = () => page.textContent('#scene-link-status');
  assert.ok((await linkStatus()).includes(cliFault(invalidScene, '/spheres/0/r', 'en')), await linkStatus());
  assert.match(await linkStatus(), /^The link's scene is not valid \(.*\); the page keeps the scene it shows\.$/);
  await page.click('#lang-switch button[data-lang="pl"]');
  assert.ok((await linkStatus()).includes(cliFault(invalidScene, '/spheres/0/r', 'pl')), await linkStatus());
  assert.match(await linkStatus(), /^Scena z odnośnika jest niepoprawna \(.*\); strona pokazuje dotychczasową scenę\.$/);
  await page.click('#lang-switch button[data-lang="en"]');
  assert.equal(await page.inputValue('#field-spheres-0-r'), '0.9', 'the panel keeps the scene shown');
  assert.equal(await renders(page), rendersPasted, 'no render of the invalid link');
  assert.ok((await pageImage(page)).bytes.equals(small.shown.bytes), 'the image stays');
  await rendered(page, () => page.click('#scene-reset'));

  // --- a coloured scene with every kind of object: materials and colours ---
  const coloured = exportPage('everything.html', ['--scene', everything, '--w', '40']);
  page = await open(coloured);
  await rendered(page, () => page.fill('#field-materials-1-colour-0', '0.8'));
  await checkAgainstCli(page, 'a material\'s colour');
  await rendered(page, () => page.click('#edit-shadows'));
  await checkAgainstCli(page, 'shadows off');
  await rendered(page, () => page.click('[data-remove="/materials/0"]'));
  const noMaterial0 = await checkAgainstCli(page, 'material 0 removed');
  assert.match(noMaterial0.sceneText, /\{"S": \[-0\.6, -0\.3, 3\.4\], "r": 0\.8\}/, 'sphere 0 takes the article\'s material');
  assert.match(noMaterial0.sceneText, /"material": 0\}/, 'sphere 1 keeps its material, now 0');
  await rendered(page, () => page.click('[data-add="spheres"]'));
  await rendered(page, () => page.selectOption('#field-spheres-3-material', '1'));
  await checkAgainstCli(page, 'a sphere added with material 1');
  await rendered(page, () => page.fill('#field-background-2', '0.2'));
  await checkAgainstCli(page, 'the background');
  await rendered(page, () => page.fill('#field-planes-0-n-1', '2'));
  await checkAgainstCli(page, 'a plane\'s normal');
  await rendered(page, () => page.selectOption('#real', 'float'));
  await checkAgainstCli(page, 'float');
  await rendered(page, () => page.selectOption('#spp', '4'));
  await checkAgainstCli(page, 'float, spp 4');
  // Download gives the same scene text as Copy.
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#scene-download')]);
  assert.equal(download.suggestedFilename(), 'scene.json');
  const downloaded = readFileSync(await download.path(), 'utf8');
  run(['scene', 'check', await download.path()]);
  assert.equal(downloaded, (await page.inputValue('#scene-copied')).split('\npromyk render')[0]);
  await page.screenshot({ path: join(work, 'edit.png'), fullPage: true });
  // axe-core on the page with the scene panel (every kind of object), a
  // selected pixel's derivation and 3D view, and an invalid value's message.
  await page.click('#image', { position: { x: 150, y: 150 } });
  await page.waitForFunction(() => document.querySelectorAll('#steps .step').length > 0);
  await page.fill('#field-spheres-0-r', '-1');
  await page.waitForFunction(() => !document.getElementById('error-spheres-0-r').hidden);
  assert.deepEqual(await axeViolations(page), [], 'axe-core: serious or critical violations');
  await page.fill('#field-spheres-0-r', '0.8');

  // --- figures: the re-render time at w = 256 and 512, the page's size ---
  for (const w of [256, 512]) {
    const big = exportPage(`article_${w}.html`, ['--w', String(w)]);
    page = await open(big, `#p=${w / 2 - 20},${w / 2}`); // a pixel selected: its derivation and 3D marks follow each edit
    const times = [];
    const workerMs = [];
    const measured = [];
    await phases(page);
    for (const value of ['2.1', '2.2', '2.3', '2.4', '2.5']) {
      await rendered(page, () => page.fill('#field-z_E', value));
      times.push(Number(await page.evaluate(() => document.body.dataset.renderMs)));
      workerMs.push(Number(await page.evaluate(() => document.body.dataset.renderWorkMs)));
      measured.push(await phases(page));
    }
    const names = [...new Set(measured.flatMap((m) => Object.keys(m)))];
    console.log(`figure: w = ${w}, the page's phases per edit (median ms): ${names.map((n) => `${n} ${median(measured.map((m) => m[n] || 0)).toFixed(1)}`).join(', ')}`);
    if (w === 256) {
      await checkAgainstCli(page, 'w = 256');
      // The derivation and 3D view drawn after the image: the edited pixel's.
      assert.equal(await page.textContent('#derivation-heading'), `Derivation of pixel (${w / 2 - 20}, ${w / 2})`);
      assert.ok((await page.$$eval('#steps .step', (rows) => rows.length)) > 5, 'the derivation is drawn');
      assert.ok((await page.$$eval('#view-list li', (items) => items.length)) > 2, 'the 3D view draws the pixel\'s ray');
      await page.screenshot({ path: join(work, 'edit_256.png') });
    }
    if (w === 512) {
      // Edits faster than renders: each supersedes the one under way, and
      // the image shown is the last edit's.
      const before = await renders(page);
      await rendered(page, async () => {
        for (const value of ['3', '3.1', '3.2', '3.3', '3.4']) await page.fill('#field-z_E', value);
      });
      await checkAgainstCli(page, 'the last of five quick edits');
      console.log(`figure: five quick edits at w = 512 showed ${(await renders(page)) - before} render(s)`);
    }
    times.sort((a, b) => a - b);
    workerMs.sort((a, b) => a - b);
    const workers = await page.evaluate(() => document.getElementById('render-status').textContent);
    console.log(`figure: re-render of the article's scene at w = ${w}: median ${times[2]} ms from the edit to the image shown (${times.join(', ')} ms), median ${workerMs[2]} ms of it in the workers (${workerMs.join(', ')} ms); ${workers}; page ${(statSync(big).size / 1e6).toFixed(2)} MB`);
  }
  assert.deepEqual(failures, []);
} finally {
  await browser.close();
}
if (failures.length) {
  console.error(failures.join('\n'));
  process.exit(1);
}
console.log('web.edit: ok');
