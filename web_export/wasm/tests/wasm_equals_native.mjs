// The web page's tracer (promyk's C++ compiled to wasm) traces every pixel
// exactly as the CLI does: for the article's scene and
// lessons/scenes/everything.json (planes, shadows, Phong, colour), a sample
// of pixels of every branch and every object hit, in float, double and
// quad, with every formula, at 1 and 4 samples per pixel, promyk_trace's
// text equals `promyk trace --format json` of the native binary byte for
// byte (every field: real_text, digits_lost, ...). Also: a trace file of
// `render --traces` read by the wasm's trace reader gives back its lines,
// long double is refused, the view model formats numbers as the CLI, and
// promyk_render_rows gives `promyk render`'s image and `render --map
// branch`'s categories, byte for byte, for every example scene.
//
//   node wasm_equals_native.mjs --module build/.../promyk.js --promyk build/release/promyk
//   (run from the source root; --tamper changes one wasm result on purpose,
//   to see the comparison fail)
import { createRequire } from 'node:module';
import { execFileSync } from 'node:child_process';
import { statSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { gunzipSync } from 'node:zlib';
import { performance } from 'node:perf_hooks';

const args = process.argv.slice(2);
const option = (name) => {
  const k = args.indexOf(name);
  return k >= 0 ? args[k + 1] : undefined;
};
const modulePath = option('--module') && resolve(option('--module'));
const promyk = option('--promyk');
const tamper = args.includes('--tamper');
if (!modulePath || !promyk) {
  console.error('usage: node wasm_equals_native.mjs --module PROMYK_JS --promyk PROMYK [--gz WASM_GZ --glue GLUE_JS] [--tamper]');
  process.exit(2);
}

let failures = 0;
const fail = (what) => {
  failures += 1;
  if (failures <= 10) console.error('FAIL: ' + what);
};

// ---- the module -----------------------------------------------------------
const require = createRequire(import.meta.url);
const started = performance.now();
const createPromyk = require(modulePath);
const M = await createPromyk();
const instantiated = performance.now() - started;
const call = (name, types, values) => M.ccall(name, 'string', types, values);
const json = (name, types, values) => JSON.parse(call(name, types, values));

const native = (cliArgs) =>
  execFileSync(promyk, cliArgs, { encoding: 'utf8', maxBuffer: 1 << 26, stdio: ['ignore', 'pipe', 'pipe'] });

// ---- the cases ------------------------------------------------------------
const scenes = [
  { text: '', file: '', cli: [], w: 8 },
  { text: '', file: '', cli: [], w: 33 },  // odd: a centre column and row (zeros, -0)
  { text: readFileSync('lessons/scenes/everything.json', 'utf8'), file: 'lessons/scenes/everything.json',
    cli: ['--scene', 'lessons/scenes/everything.json'], w: 24 },
];
const reals = ['float', 'double', 'quad'];
const formulas = ['article', 'stable', 'fma', 'geometric'];
const spps = [1, 4];

let compared = 0;
let firstTraceMs = null;
for (const scene of scenes) {
  const opened = json('promyk_open_scene', ['string', 'string', 'number'], [scene.text, scene.file, scene.w]);
  if (opened.error) {
    fail(`open_scene ${scene.file || 'article'}: ${opened.error}`);
    continue;
  }
  // Every pixel in double: the sample takes up to two pixels of each
  // branch and of each object hit (the first and the last in row order).
  const kinds = new Map();
  for (let i = 0; i < scene.w; ++i)
    for (let j = 0; j < scene.w; ++j) {
      const t0 = performance.now();
      const trace = JSON.parse(call('promyk_trace', ['number', 'number', 'string'], [i, j, '{}']));
      if (firstTraceMs === null) firstTraceMs = performance.now() - t0;
      for (const kind of [`branch ${trace.branch}`, `hit ${trace.hit ?? 'none'}`]) {
        if (!kinds.has(kind)) kinds.set(kind, []);
        kinds.get(kind).push([i, j]);
      }
    }
  const sample = new Map();
  for (const pixels of kinds.values())
    for (const p of [pixels[0], pixels[pixels.length - 1]]) sample.set(p.join(','), p);
  const branches = [...kinds.keys()].filter((k) => k.startsWith('branch')).join(', ');
  console.log(`${scene.file || 'article'} w=${scene.w}: ${sample.size} pixels (${branches})`);
  for (const [i, j] of sample.values())
    for (const real of reals)
      for (const formula of formulas)
        for (const spp of spps) {
          const settings = JSON.stringify({ real, formula, spp });
          let mine = call('promyk_trace', ['number', 'number', 'string'], [i, j, settings]);
          if (tamper && compared === 7) mine = mine.replace(/\d(?=")/, (d) => String((Number(d) + 1) % 10));
          const theirs = native(['trace', '--format', 'json', '--pixel', `${i},${j}`, '--w', String(scene.w),
                                 '--real', real, '--formula', formula, '--spp', String(spp), ...scene.cli]);
          compared += 1;
          if (mine + '\n' !== theirs) {
            let k = 0;
            while (k < mine.length && mine[k] === theirs[k]) ++k;
            fail(`${scene.file || 'article'} w=${scene.w} (${i},${j}) ${settings}: differs at byte ${k}:\n` +
                 `  wasm:   …${mine.slice(Math.max(0, k - 60), k + 60)}\n` +
                 `  native: …${theirs.slice(Math.max(0, k - 60), k + 60)}`);
          }
        }
}
console.log(`${compared} traces compared`);
if (compared < 300) fail(`only ${compared} traces compared`);

// ---- long double is refused, with the reason ------------------------------
json('promyk_open_scene', ['string', 'string', 'number'], ['', '', 8]);
const refused = json('promyk_trace', ['number', 'number', 'string'], [3, 4, '{"real":"long-double"}']);
if (refused.code !== 2 || !/long double/.test(refused.error)) fail('long double not refused: ' + JSON.stringify(refused));
const outside = json('promyk_trace', ['number', 'number', 'string'], [8, 0, '{}']);
if (outside.code !== 2) fail('a pixel outside the pane not refused: ' + JSON.stringify(outside));
const badScene = json('promyk_open_scene', ['string', 'string', 'number'], ['{"spheres": 3}', 'bad.json', 8]);
if (badScene.code !== 3 || !badScene.error.startsWith('bad.json: ')) fail('a bad scene not refused: ' + JSON.stringify(badScene));

// ---- a trace file read by the wasm's trace reader -------------------------
const dir = mkdtempSync(join(tmpdir(), 'promyk-wasm-'));
try {
  const tracesPath = join(dir, 'traces.jsonl');
  native(['render', '--scene', 'lessons/scenes/everything.json', '--w', '12', '--real', 'quad', '--spp', '4',
          '--trace-region', '2,3,5,7', '--traces', tracesPath, '-o', join(dir, 'image.png')]);
  const bytes = readFileSync(tracesPath);
  const lines = bytes.toString('utf8').split('\n').filter((line) => line.length > 0);
  const pointer = M._malloc(bytes.length);
  M.HEAPU8.set(bytes, pointer);
  const file = json('promyk_open_traces', ['number', 'number'], [pointer, bytes.length]);
  M._free(pointer);
  if (file.error) fail('open_traces: ' + file.error);
  else {
    if (file.count !== lines.length || file.w !== 12 || file.real !== 'quad' || file.spp !== 4)
      fail('open_traces summary: ' + JSON.stringify({ ...file, pixels: undefined }));
    lines.forEach((line, k) => {
      const [i, j] = file.pixels[k];
      if (call('promyk_trace_from_file', ['number', 'number'], [i, j]) !== line) fail(`trace_from_file (${i},${j})`);
    });
    // The reader reads what the writer writes: viewing a line of the file works.
    const view = json('promyk_view', ['string', 'string'], [lines[0], '{"lang":"pl","digits":4}']);
    if (view.error || view.steps.length === 0) fail('view of a file line: ' + (view.error ?? 'no steps'));
  }
  const broken = json('promyk_open_traces', ['string', 'number'], ['{"schema":1}\n', 13]);
  if (broken.code !== 3) fail('a broken trace file not refused: ' + JSON.stringify(broken));
} finally {
  rmSync(dir, { recursive: true, force: true });
}

// ---- the view model: numbers as the CLI's formatter writes them -----------
json('promyk_open_scene', ['string', 'string', 'number'], ['', '', 8]);
const quadTrace = call('promyk_trace', ['number', 'number', 'string'], [3, 4, '{"real":"quad"}']);
const view = json('promyk_view', ['string', 'string'], [quadTrace, '{"lang":"pl","digits":4}']);
// The CLI's text trace with its wrapped lines joined (a vector breaks after "; ").
const unwrap = (text) => text.replace(/;\n +/g, '; ');
const text = unwrap(native(['--lang', 'pl', 'trace', '--pixel', '3,4', '--w', '8', '--real', 'quad']));
for (const step of view.steps)
  if (!text.includes('= ' + step.value_full)) fail(`view: step ${step.path} = ${step.value_full} is not in the CLI's text trace`);
const text4 = unwrap(native(['--lang', 'pl', '--digits', '4', 'trace', '--pixel', '3,4', '--w', '8', '--real', 'quad']));
for (const step of view.steps)
  if (!text4.includes('= ' + step.value_shown)) fail(`view: step ${step.path} = ${step.value_shown} is not in the CLI's --digits 4 trace`);
if (!text4.includes('= ' + view.I_P_shown + '\n') || !/^0,\d{4}$/.test(view.I_P_shown)) fail('view: I_P_shown ' + view.I_P_shown);
// compare: A's texts marked where they stop agreeing with B, as `trace --compare`.
const floatTrace = call('promyk_trace', ['number', 'number', 'string'], [3, 4, '{"real":"float"}']);
const comparison = json('promyk_compare', ['string', 'string', 'string'], [floatTrace, quadTrace, '{"lang":"en"}']);
const table = native(['trace', '--compare', 'float,quad', '--pixel', '3,4', '--w', '8']).replace(/\u2212/g, '-');
let marks = 0;
for (const step of comparison.steps ?? []) {
  if (step.kind !== 'scalar' || step.agree === null) continue;
  const marked = step.a_marked.replace(/\u2212/g, '-');
  if (!table.includes(`float  ${marked}  `)) fail(`compare: ${step.path} ${marked} is not in trace --compare`);
  if (marked.includes('|')) marks += 1;
}
if (marks < 3) fail(`compare: only ${marks} marked steps`);
// messages: every id in both languages, the page's words from the CLI's files.
const pl = json('promyk_messages', ['string'], ['pl']), en = json('promyk_messages', ['string'], ['en']);
const ids = (m) => Object.keys(m.messages ?? {}).sort().join(',');
if (ids(pl) !== ids(en) || Object.keys(pl.messages).length < 300) fail('messages: ids differ or too few');
if (pl.messages.branch_name_lit !== 'strona oświetlona' || pl.vocabulary?.delta?.symbol !== 'Δ/4') fail('messages: words');
const legend = json('promyk_legend', ['string'], ['en']);
if (legend.categories?.length !== 7 || legend.categories[0].id !== 'miss') fail('legend: ' + JSON.stringify(legend));

// ---- the split module (wasm gzip-compressed + glue) traces the same -------
const gz = option('--gz'), glue = option('--glue');
if (gz && glue) {
  const createFromParts = require(resolve(glue));
  const P = await createFromParts({ wasmBinary: gunzipSync(readFileSync(gz)) });
  const none = P.ccall('promyk_trace', 'string', ['number', 'number', 'string'], [3, 4, '{}']);
  if (none !== '{"error":"No scene is open yet.","code":2}') fail('the split module, no scene: ' + none);
  P.ccall('promyk_open_scene', 'string', ['string', 'string', 'number'], ['', '', 8]);
  for (const settings of ['{}', '{"real":"quad","formula":"fma","spp":4}']) {
    const one = M.ccall('promyk_trace', 'string', ['number', 'number', 'string'], [3, 4, settings]);
    const other = P.ccall('promyk_trace', 'string', ['number', 'number', 'string'], [3, 4, settings]);
    if (other !== one) fail('the split module: ' + settings);
  }
  console.log(`split module: wasm.gz ${statSync(gz).size} bytes, glue ${statSync(glue).size} bytes`);
}

// ---- promyk_render_rows: the image and the branch map as render's --------
// Every example scene in double with the article's formula, and two scenes
// in every real type, formula and 1 or 4 samples: the rows (asked for a few
// at a time, as the page's workers do) equal `promyk render` (a PGM/PPM)
// byte for byte, and the categories are the colours `render --map branch`
// draws.
{
  const work = mkdtempSync(join(tmpdir(), 'promyk-rows-'));
  const netpbm = (file) => {
    const data = readFileSync(file);
    const header = data.subarray(0, 64).toString('latin1').match(/^(P[56])\s+(\d+)\s+(\d+)\s+(\d+)\s/);
    return { channels: header[1] === 'P6' ? 3 : 1, bytes: data.subarray(header[0].length) };
  };
  const legend = json('promyk_legend', ['string'], ['en']).categories;
  const categoryOf = new Map(legend.map((c) => [c.rgb.join(','), c.index]));
  const cases = [];
  const sceneFiles = ['', ...['article', 'colour', 'everything', 'far_sphere', 'floor', 'floor_wall', 'phong', 'shadows',
    'two_lights', 'two_spheres'].map((name) => `lessons/scenes/${name}.json`)];
  for (const file of sceneFiles) cases.push({ file, w: 13, settings: { real: 'double', formula: 'article', spp: 1 } });
  for (const file of ['lessons/scenes/everything.json', 'lessons/scenes/far_sphere.json'])
    for (const real of reals)
      for (const formula of ['article', 'stable', 'fma', 'geometric'])
        for (const spp of [1, 4]) cases.push({ file, w: 9, settings: { real, formula, spp } });
  let rowsCompared = 0;
  for (const { file, w, settings } of cases) {
    const what = `render rows ${file || 'article'} w=${w} ${JSON.stringify(settings)}`;
    const opened = json('promyk_open_scene', ['string', 'string', 'number'], [file ? readFileSync(file, 'utf8') : '', file, w]);
    if (!opened.ok) {
      fail(`${what}: ${JSON.stringify(opened)}`);
      continue;
    }
    const image = [], branch = [];
    for (let first = 0; first < w; first += 4) {
      const r = json('promyk_render_rows', ['number', 'number', 'string'], [first, Math.min(4, w - first), JSON.stringify(settings)]);
      if (r.error) {
        fail(`${what}: ${r.error}`);
        break;
      }
      image.push(...M.HEAPU8.subarray(r.image, r.image + r.image_bytes));
      branch.push(...M.HEAPU8.subarray(r.branch, r.branch + r.branch_bytes));
    }
    const cliArgs = [...(file ? ['--scene', file] : []), '--w', String(w), '--real', settings.real, '--formula', settings.formula,
      '--spp', String(settings.spp)];
    const out = join(work, opened.effects.includes('colour') ? 'image.ppm' : 'image.pgm');
    native(['render', ...cliArgs, '-o', out]);
    const cli = netpbm(out);
    if (tamper && rowsCompared === 0) image[0] ^= 1;
    if (!Buffer.from(image).equals(cli.bytes)) fail(`${what}: the image differs from promyk render`);
    native(['render', ...cliArgs, '--map', 'branch', '-o', join(work, 'map.ppm')]);
    const map = netpbm(join(work, 'map.ppm')).bytes;
    for (let p = 0; p < w * w; ++p)
      if (categoryOf.get(`${map[3 * p]},${map[3 * p + 1]},${map[3 * p + 2]}`) !== branch[p]) {
        fail(`${what}: pixel ${p}'s category ${branch[p]} is not render --map branch's`);
        break;
      }
    rowsCompared += 1;
  }
  const refused = json('promyk_render_rows', ['number', 'number', 'string'], [8, 2, '{}']);
  if (refused.code !== 2) fail('rows outside the pane: ' + JSON.stringify(refused));
  rmSync(work, { recursive: true, force: true });
  console.log(`${rowsCompared} renders compared (image and branch map)`);
  // The figures below trace the article's scene at w = 8.
  json('promyk_open_scene', ['string', 'string', 'number'], ['', '', 8]);
}

// ---- figures ---------------------------------------------------------------
const t0 = performance.now();
const N = 20;
for (let k = 0; k < N; ++k) call('promyk_trace', ['number', 'number', 'string'], [3, 4, '{"real":"quad"}']);
const quadMs = (performance.now() - t0) / N;
const t1 = performance.now();
for (let k = 0; k < N; ++k) call('promyk_trace', ['number', 'number', 'string'], [3, 4, '{}']);
const doubleMs = (performance.now() - t1) / N;
console.log(`module ${statSync(modulePath).size} bytes; instantiated in ${instantiated.toFixed(0)} ms; ` +
            `first trace ${firstTraceMs.toFixed(1)} ms; one pixel (article, w=8): double ${doubleMs.toFixed(2)} ms, ` +
            `quad ${quadMs.toFixed(2)} ms`);

if (failures > 0) {
  console.error(`${failures} failure(s)`);
  process.exit(1);
}
console.log('ok');
