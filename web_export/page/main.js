// The page: reads the data `promyk export` embedded, starts the tracer
// (promyk's C++ in WebAssembly), and redraws every view from one state on
// any change: the image, the derivation, the 3D view, the URL fragment.
import { makeTracer, TracerError } from './tracer.js';
import { setMessages, t } from './words.js';
import { defaultState, readFragment, writeFragment, rememberedLanguage, rememberLanguage, reals, formulas, spps } from './state.js';
import { ImageView, patterns, drawSwatch } from './image_view.js';
import { Derivation } from './derivation.js';
import { View3D } from './view3d.js';
import { RenderPool } from './render_pool.js';
import { SceneEditor, modelOf, sceneText, maxW } from './scene_editor.js';
import { timed, measureSince } from './timing.js';
import { Lessons } from './lessons.js';
import { PrecisionLab } from './precision_lab.js';

const $ = (id) => document.getElementById(id);

function bytesOf(base64) {
  const text = atob(base64 || '');
  const bytes = new Uint8Array(text.length);
  for (let k = 0; k < text.length; ++k) bytes[k] = text.charCodeAt(k);
  return bytes;
}

const utf8 = (bytes) => new TextDecoder().decode(bytes);

async function gunzip(bytes) {
  const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('gzip'));
  return new Uint8Array(await new Response(stream).arrayBuffer());
}

function showError(error) {
  const text = error && error.message ? error.message : String(error);
  // Before the tracer has given the page its words, the error alone.
  const worded = t('page_error', { text });
  $('status').textContent = worded === 'page_error' ? text : worded;
  $('status').className = 'error';
}

async function start() {
  const data = JSON.parse($('promyk-data').textContent);
  data.image = bytesOf(data.image);
  data.branchMap = bytesOf(data.branch_map);
  // The wasm's bytes from their data block (gzip, build_page.mjs): nothing
  // fetched. Compiled once: the page's instance and the render workers' share it.
  const wasmModule = await WebAssembly.compile(await gunzip(bytesOf($('promyk-wasm').textContent)));
  const instantiateWasm = (imports, done) => {
    WebAssembly.instantiate(wasmModule, imports).then((instance) => done(instance, wasmModule));
    return {};
  };
  const M = await createPromyk({ instantiateWasm }); // eslint-disable-line no-undef
  const tracer = makeTracer(M);
  const version = tracer.version();
  // The exported scene: its text, the file name its traces carry, its w.
  const exported = { text: utf8(bytesOf(data.scene_text)), file: data.scene_file || '', w: data.w };
  let opened = tracer.openScene(exported.text, exported.file, exported.w);
  const exportedContent = opened.scene_content;
  // The scene the page shows (the exported one, or as edited) and its w.
  let scene = { ...exported, edited: false };
  const editedFile = 'scene.json'; // what Download names it, and the command line reads

  const state = readFragment(defaultState(rememberedLanguage() || data.lang || 'en'), location.hash, data.w);
  let messages = null;
  let legend = null;
  let traces = null; // the open trace file: {info, pixels: Set, name}
  let current = null; // {text, view, geometry, fromFile}
  let comparison = null;

  const image = new ImageView($('image'), $('image-frame'), data, {
    onSelect: (pixel) => {
      // (an image of another w may still show while the new one renders)
      if (pixel[0] >= scene.w || pixel[1] >= scene.w) return;
      state.pixel = pixel;
      state.step = 0;
      retrace();
    },
    onHover: (pixel) => {
      if (!pixel) {
        $('hover').textContent = '';
        return;
      }
      const category = legend.categories.find((c) => c.index === image.category(pixel[0], pixel[1]));
      const overlay = lab.hoverText(pixel[0], pixel[1]); // the precision lab's map's value, if shown
      $('hover').textContent = t('page_hover', {
        i: pixel[0], j: pixel[1], value: image.grey(pixel[0], pixel[1]), branch: category ? category.name : '',
      }) + (overlay ? ` · ${overlay}` : '');
    },
  });
  const derivation = new Derivation($('steps'), $('outcome'));
  const view3d = new View3D($('view3d'), $('view-labels'), $('view-list'));
  view3d.setScene(opened.scene_content);
  const lessons = new Lessons($('lessons-panel'), {
    tracer,
    pixel: () => state.pixel,
    scene: () => ({ hash: opened.scene_hash, name: opened.scene, w: scene.w }),
    state, // the lesson, its pixel, step and mode in the URL (state.js)
    save: () => writeFragment(state),
  });
  const editor = new SceneEditor($('scene-fields'), { onChange: () => sceneEdited() });
  // The image shown: which scene, w and settings it was rendered with.
  const imageKey = (text, w, real, formula, spp) => JSON.stringify([text, w, real, formula, spp]);
  let shownImage = imageKey(exported.text, exported.w, 'double', 'article', 1);
  let wantedImage = shownImage;
  let pool = null;
  let renders = 0;
  // The precision lab: the error and digits-lost overlays, the bench plot.
  const lab = new PrecisionLab({
    M, data, image, exportedKey: shownImage,
    pool: () => { startPool(); return pool; },
    redraw: () => redraw(),
    setSettings: (real, formula) => {
      state.real = real;
      state.formula = formula;
      settingsChanged();
    },
    command: (kind) => {
      const file = scene.edited ? editedFile : exported.file; // '': the built-in scene
      return `promyk render${file ? ` --scene ${file}` : ''} --w ${scene.w} --real ${state.real} --formula ${state.formula} --spp ${state.spp} --map ${kind} --legend -o ${kind}.png`;
    },
  });
  const labImage = () => {
    const [, , real, formula, spp] = JSON.parse(shownImage);
    lab.imageShown({ key: shownImage, text: scene.text, file: scene.file, w: scene.w, sceneName: opened.scene, settings: { real, formula, spp } });
  };

  // --- the scene panel ---

  // The trace file's pixels show the file's values only while the page
  // shows the file's scene at its w.
  function tracesMatch() {
    return traces && traces.info.w === scene.w && traces.info.scene_hash === opened.scene_hash;
  }

  let sceneFaults = [];
  let editStarted = null; // when the edit being rendered was made (performance.now())
  function showSceneErrors() {
    const left = editor.showErrors(sceneFaults);
    const box = $('scene-errors');
    box.replaceChildren(...left.map((fault) => {
      const item = document.createElement('li');
      item.textContent = fault.where ? `${fault.where}: ${fault.what}` : fault.what;
      return item;
    }));
    $('scene-invalid').hidden = sceneFaults.length === 0;
  }

  // An edit in the panel: the loader reads the scene's text; a valid scene
  // is opened (traces follow it) and rendered, an invalid one leaves the
  // last valid image and shows the loader's messages by their fields.
  function sceneEdited() {
    editStarted = performance.now();
    readEdited();
  }

  // The panel's scene read by the loader (and rendered when valid).
  function readEdited() {
    const text = sceneText(editor.model);
    const wText = editor.w.trim();
    const w = /^\d+$/.test(wText) ? Number(wText) : NaN;
    if (!(w >= 1 && w <= maxW)) {
      sceneFaults = [{ where: '/w', what: t('edit_w_range', { max: maxW, value: wText }) }];
      showSceneErrors();
      return;
    }
    openScene({ text, file: editedFile, w, edited: true });
  }

  // Opens a scene in the page's tracer; false (and its faults shown) when the loader refuses it.
  function openScene(next) {
    tracer.useLanguage(state.lang);
    try {
      opened = timed('open', () => tracer.openScene(next.text, next.file, next.w));
    } catch (error) {
      if (!(error instanceof TracerError) || error.code !== 3) throw error;
      sceneFaults = error.faults();
      showSceneErrors();
      return false;
    }
    sceneFaults = [];
    showSceneErrors();
    scene = next;
    state.scene = scene.edited ? scene.text : null;
    state.w = scene.w !== exported.w ? scene.w : null;
    if (state.pixel && (state.pixel[0] >= scene.w || state.pixel[1] >= scene.w)) state.pixel = null;
    renderImage(); // first: the workers start while the rest is drawn
    timed('after-dispatch', () => {
      const content = opened.scene_content;
      drawAfterImage('scene3d', () => view3d.setScene(content));
      image.traced = tracesMatch() ? traces.pixels : null;
      describeScene();
      drawCommand();
      retrace({ afterImage: true });
    });
    return true;
  }

  // Drawing that waits for the image. While a render is under way the
  // derivation and the 3D view are not redrawn: on this one thread they
  // would keep the workers' rows waiting (their KaTeX and three.js cost more
  // than the tracer at w = 256). They are drawn once, in the frame after the
  // image is shown (or at once in the next frame when no render is under way).
  const waiting = new Map(); // name → draw, in the order last asked
  let frameAsked = false;
  function drawAfterImage(name, draw) {
    waiting.delete(name);
    waiting.set(name, draw);
    if (wantedImage === shownImage) askFrame();
  }
  function askFrame() {
    if (!waiting.size || frameAsked) return;
    frameAsked = true;
    requestAnimationFrame(drawWaiting);
  }
  function drawWaiting() {
    frameAsked = false;
    const draws = [...waiting.values()];
    waiting.clear();
    for (const draw of draws) draw();
    view3d.flush();
  }

  // The render workers, started on the first render, or as soon as the
  // scene panel is touched (their instances take a moment to start).
  function startPool() {
    if (pool) return;
    const count = Math.max(2, Math.min(4, navigator.hardwareConcurrency || 2));
    pool = new RenderPool($('promyk-glue').textContent, wasmModule, count);
  }
  for (const event of ['focusin', 'pointerdown'])
    $('scene-panel').addEventListener(event, startPool, { once: true });

  // The render's status line (its message id and arguments kept, so that a
  // language switch words it again); no id: none.
  let statusLine = null;
  function renderStatus(id, args) {
    statusLine = id ? [id, args] : null;
    $('render-status').textContent = id ? t(id, args) : '';
  }

  // The image in the scene, w and settings shown, rendered by the workers.
  async function renderImage() {
    const settings = { real: state.real, formula: state.formula, spp: state.spp };
    const key = imageKey(scene.text, scene.w, settings.real, settings.formula, settings.spp);
    if (key === wantedImage) return;
    wantedImage = key;
    if (key === shownImage) {
      if (pool) pool.cancel(); // the image shown is wanted again: the render under way is not
      renderStatus();
      askFrame();
      labImage();
      return;
    }
    lab.imageWanted();
    const started = performance.now();
    const edited = editStarted ?? started;
    editStarted = null;
    renderStatus('edit_rendering', { percent: 0 });
    try {
      startPool();
      const w = scene.w;
      const result = await pool.render({ scene: scene.text, file: scene.file, w, settings }, (done) => {
        if (wantedImage === key) renderStatus('edit_rendering', { percent: Math.floor((100 * done) / w) });
      });
      if (!result || wantedImage !== key) return; // a later edit took over
      const workMs = Math.round(performance.now() - started);
      measureSince('workers', started);
      performance.measure('promyk:tracer-in-workers', { start: started, duration: result.tracerMs });
      shownImage = key;
      timed('show', () => {
        timed('show-image', () => image.setImage(result));
        labImage(); // the overlay of this image (after it: the overlay has its w)
        drawAfterImage('legend', () => timed('legend', drawLegend)); // its counts: after the image
        timed('show-redraw', redraw);
      });
      measureSince('edit-to-image', edited);
      const ms = Math.round(performance.now() - edited);
      renderStatus('edit_rendered', { w, ms, workers: pool.count });
      document.body.dataset.renderMs = String(ms);
      document.body.dataset.renderWorkMs = String(workMs); // the workers' part of it
      document.body.dataset.renders = String(++renders);
      askFrame();
    } catch (error) {
      if (wantedImage === key) {
        showError(error);
        wantedImage = shownImage; // no render under way: what waits is drawn
        askFrame();
      }
    }
  }

  // The command line that renders the image shown, bit for bit.
  function commandLine() {
    return `promyk render --scene ${editedFile} --w ${scene.w} --real ${state.real} --formula ${state.formula} --spp ${state.spp} -o image.png`;
  }

  function drawCommand() {
    $('scene-command-intro').textContent = t('edit_command', { file: editedFile });
    $('scene-command').textContent = commandLine();
  }

  // What Copy and Download give: the panel's scene as the loader read it.
  const sceneForFile = () => sceneText(editor.model);

  // A trace's or export's scene file (a string from a file: only ever set as
  // text); the article's built-in scene in the page's words.
  function sceneFileText(file) {
    return !file || file === 'built-in' ? t('trace_builtin') : file;
  }

  function fillSelect(select, options) {
    select.replaceChildren(...options.map(([value, label]) => {
      const option = document.createElement('option');
      option.value = value;
      option.textContent = label;
      return option;
    }));
  }

  function drawLegend() {
    const { first, count } = image.tally();
    const list = $('legend-list');
    list.replaceChildren();
    for (const category of legend.categories) {
      const item = document.createElement('li');
      // The colour and the pattern the atlas draws, and the pattern in words.
      const swatch = document.createElement('canvas');
      swatch.width = swatch.height = 24;
      swatch.className = 'swatch';
      drawSwatch(swatch.getContext('2d'), category, 24);
      const name = document.createElement('span');
      name.textContent = `${category.name} (${count.get(category.index) || 0})`;
      const pattern = document.createElement('span');
      pattern.className = 'pattern-name';
      pattern.dataset.pattern = patterns[category.index];
      pattern.textContent = t(`page_pattern_${patterns[category.index]}`);
      const go = document.createElement('button');
      go.type = 'button';
      go.dataset.category = category.id;
      go.title = t('page_goto_first_title');
      const at = first.get(category.index);
      go.textContent = at ? `${t('page_goto_first')} (${at[0]}, ${at[1]})` : t('page_none_of_kind');
      go.disabled = !at;
      go.addEventListener('click', () => {
        state.pixel = at;
        state.step = 0;
        retrace();
      });
      item.dataset.index = String(category.index);
      item.dataset.rgb = category.rgb.join(',');
      item.append(swatch, ' ', name, ' ', pattern, ' ', go);
      list.append(item);
    }
  }

  function describeTraces() {
    const info = traces.info;
    $('traces-status').textContent = t('page_traces_loaded', {
      file: traces.name, scene: info.scene, scene_file: sceneFileText(info.scene_file), count: info.count, real: info.real, formula: info.formula, spp: info.spp,
    });
    $('use-file-row').hidden = false;
  }

  // A trace file (embedded by export, picked or dropped): read by the C++
  // trace reader in the wasm; refused when of another scene or w.
  function openTraces(bytes, name) {
    try {
      const info = tracer.openTraces(bytes);
      if (info.w !== scene.w) throw new Error(t('page_traces_other_w', { file_w: info.w, w: scene.w }));
      if (info.scene_hash !== opened.scene_hash)
        throw new Error(t('page_traces_other_scene', { file_scene: info.scene, scene: opened.scene }));
      traces = { info, name, pixels: new Set(info.pixels.map(([i, j]) => `${i},${j}`)) };
      image.traced = tracesMatch() ? traces.pixels : null;
      describeTraces();
      $('status').textContent = '';
      retrace();
    } catch (error) {
      showError(error);
    }
  }

  // The selected pixel's trace: the trace file's line when the file has the
  // pixel (and its values are wanted), else computed live. After an edit its
  // drawing waits for the image (drawAfterImage); the trace is at once.
  function retrace({ afterImage = false } = {}) {
    current = null;
    comparison = null;
    if (state.pixel) {
      const [i, j] = state.pixel;
      try {
        const fromFile = traces && state.useFile && traces.pixels.has(`${i},${j}`) && tracesMatch();
        const text = timed('trace', () => (fromFile ? tracer.traceFromFile(i, j) : tracer.trace(i, j, { real: state.real, formula: state.formula, spp: state.spp })));
        current = { text, fromFile };
        if (state.compare && !fromFile) {
          const [real, formula] = state.compare.split(',');
          const other = tracer.trace(i, j, { real, formula, spp: state.spp });
          comparison = { other, real, formula };
        }
        $('status').textContent = '';
        $('status').className = '';
      } catch (error) {
        showError(error);
      }
    }
    if (afterImage) drawAfterImage('trace', redrawTrace);
    else {
      waiting.delete('trace');
      redrawTrace();
    }
  }

  // Everything that depends on the trace and the language.
  function redrawTrace() {
    $('pick-hint').hidden = Boolean(current);
    $('stepper').hidden = !current;
    if (!current) {
      derivation.container.replaceChildren();
      derivation.outcome.replaceChildren();
      $('comparison').replaceChildren();
      $('source-note').textContent = '';
      view3d.setPixel(null);
      redraw();
      return;
    }
    let view;
    try {
      view = tracer.view(current.text, { lang: state.lang, digits: 4 });
      current.view = view;
      current.geometry = tracer.view(current.text, { lang: 'en', digits: 0 });
    } catch (error) {
      current = null;
      showError(error);
      return redrawTrace();
    }
    const h = view.header;
    $('derivation-heading').textContent = t('page_derivation', { i: h.i, j: h.j });
    $('source-note').textContent = current.fromFile
      ? t('page_from_file', { real: h.real, formula: h.formula, spp: h.spp, scene_file: sceneFileText(h.scene_file) })
      : t('page_settings_live', { real: h.real, formula: h.formula, spp: h.spp });
    timed('derivation', () => derivation.show(view, state.full));
    timed('view3d-pixel', () => view3d.setPixel(current.geometry, scene.w, view));
    drawComparison();
    state.step = Math.min(state.step, view.steps.length - 1);
    redraw();
  }

  function drawComparison() {
    const box = $('comparison');
    box.replaceChildren();
    if (!comparison || !current) return;
    const result = tracer.compare(current.text, comparison.other, { lang: state.lang, digits: 4 });
    const heading = document.createElement('h3');
    const name = (s) => `${s.real}, ${s.formula}, spp ${s.spp}`;
    heading.textContent = t('page_compare_heading', { a: name(result.a), b: name(result.b) });
    const table = document.createElement('table');
    for (const step of result.steps) {
      const row = table.insertRow();
      row.insertCell().textContent = step.symbol;
      const marked = (text) => {
        const cell = row.insertCell();
        cell.className = 'number';
        const bar = text.indexOf('|');
        if (bar < 0) {
          cell.textContent = text;
          return;
        }
        const agree = document.createElement('mark');
        agree.textContent = text.slice(0, bar);
        cell.append(agree, text.slice(bar + 1));
      };
      marked(step.a_marked || step.a_full || '');
      marked(step.b_marked || step.b_full || '');
      row.insertCell().textContent = step.agree === -1 ? t('page_compare_equal') : step.agree === null ? '—' : t('page_compare_agree', { agree: step.agree });
    }
    box.append(heading, table);
  }

  // The views that depend on the state only (cheap): redrawn on any change.
  function redraw() {
    lessons.refresh();
    image.selected = state.pixel;
    image.atlas = state.atlas;
    image.draw();
    $('zoom-label').textContent = `${t('page_zoom')} ${image.zoom}×`;
    $('zoom-in').disabled = !image.canZoomIn();
    $('zoom-out').disabled = !image.canZoomOut();
    $('legend').hidden = !state.atlas;
    $('atlas-toggle').checked = state.atlas;
    $('full-digits').checked = state.full;
    $('real').value = state.real;
    $('formula').value = state.formula;
    $('spp').value = String(state.spp);
    $('compare').value = state.compare;
    $('use-file').checked = state.useFile;
    if (current && current.view) {
      const n = current.view.steps.length;
      state.step = Math.max(0, Math.min(state.step, n - 1));
      $('step-counter').textContent = t('page_step_of', { k: state.step + 1, n });
      $('step-first').disabled = $('step-prev').disabled = state.step === 0;
      $('step-last').disabled = $('step-next').disabled = state.step === n - 1;
      derivation.setStep(state.step);
      view3d.setStep(current.geometry.steps[state.step], current.geometry);
    }
    writeFragment(state);
  }

  // The interface's words in the chosen language.
  function applyLanguage() {
    messages = tracer.messages(state.lang);
    setMessages(messages.messages);
    legend = tracer.legend(state.lang);
    image.setLegend(legend.categories);
    document.documentElement.lang = state.lang;
    document.title = t('page_title');
    const words = {
      title: 'page_title', 'image-heading': 'page_image', 'atlas-label': 'page_atlas', 'legend-title': 'page_legend_title',
      'traces-open': 'page_traces_open', 'traces-drop': 'page_traces_drop', 'use-file-label': 'page_traces_use_file',
      'derivation-heading': 'page_derivation', 'pick-hint': 'page_pick_pixel', 'real-label': 'page_real',
      'formula-label': 'page_formula', 'spp-label': 'page_spp', 'compare-label': 'page_compare',
      'full-digits-label': 'page_full_digits', 'step-first': 'page_first', 'step-prev': 'page_prev',
      'step-next': 'page_next', 'step-last': 'page_last', 'keys-hint': 'page_keys_hint', 'view-heading': 'page_view3d',
      'view-hint': view3d.available ? 'page_view3d_hint' : 'page_view3d_no_webgl', 'view-list-title': 'page_view_list_title', notices: 'page_notices',
      'scene-heading': 'edit_heading', 'scene-intro': 'edit_intro', 'scene-copy': 'edit_copy',
      'scene-download': 'edit_download', 'scene-reset': 'edit_reset', 'scene-invalid': 'edit_invalid',
    };
    for (const [id, word] of Object.entries(words)) $(id).textContent = t(word, { i: '·', j: '·' });
    describeScene();
    if (statusLine) renderStatus(...statusLine);
    // A refused link's message in the new language: the link read again.
    if (linkRefused) openLink(linkRefused);
    $('full-digits').parentElement.title = t('page_digits_hint');
    $('lang-switch').setAttribute('aria-label', t('page_language'));
    // Why the page has no long double, in the page's language when the
    // tracer's messages word it (wasm_no_long_double), else as it says.
    const why = t('wasm_no_long_double');
    $('long-double-note').textContent = version.long_double ? '' : why !== 'wasm_no_long_double' ? why : version.long_double_why || '';
    for (const button of document.querySelectorAll('#lang-switch button'))
      button.setAttribute('aria-pressed', String(button.dataset.lang === state.lang));
    fillSelect($('compare'), [['', t('page_compare_none')], ...reals.flatMap((r) => formulas.map((f) => [`${r},${f}`, `${r}, ${f}`]))]);
    drawLegend();
    if (traces) describeTraces();
    editor.build();
    // The loader's messages by the fields in the new language: the panel's
    // scene (invalid, so nothing renders) read again.
    if (sceneFaults.length) readEdited();
    else showSceneErrors();
    drawCommand();
    redrawTrace();
    lessons.setLanguage(state.lang);
    lab.setLanguage(state.lang);
  }

  function describeScene() {
    $('scene-line').textContent = t('page_scene', { scene: opened.scene, file: sceneFileText(scene.edited ? editedFile : exported.file), w: scene.w });
  }

  // --- controls ---
  fillSelect($('real'), reals.map((r) => [r, r]));
  fillSelect($('formula'), formulas.map((f) => [f, f]));
  fillSelect($('spp'), spps.map((s) => [String(s), String(s)]));
  $('real').addEventListener('change', (e) => { state.real = e.target.value; settingsChanged(); });
  $('formula').addEventListener('change', (e) => { state.formula = e.target.value; settingsChanged(); });
  $('spp').addEventListener('change', (e) => { state.spp = Number(e.target.value); settingsChanged(); });
  // The image is rendered in the settings shown, as the command line says.
  function settingsChanged() {
    drawCommand();
    renderImage();
    retrace();
  }
  $('scene-copy').addEventListener('click', async () => {
    const text = `${sceneForFile()}\n${commandLine()}\n`;
    // Shown at once (the clipboard may take its time, or refuse).
    $('scene-copied').value = text;
    $('scene-copied').hidden = false;
    $('scene-copy-status').textContent = '';
    try {
      await navigator.clipboard.writeText(text);
      $('scene-copy-status').textContent = t('edit_copied');
    } catch {
      $('scene-copy-status').textContent = t('edit_copy_failed');
    }
  });
  $('scene-download').addEventListener('click', () => {
    const url = URL.createObjectURL(new Blob([sceneForFile()], { type: 'application/json' }));
    const link = document.createElement('a');
    link.href = url;
    link.download = editedFile;
    document.body.append(link);
    link.click();
    link.remove();
    setTimeout(() => URL.revokeObjectURL(url), 1000);
  });
  $('scene-reset').addEventListener('click', () => {
    editor.set(modelOf(exportedContent), exported.w);
    openScene({ ...exported, edited: false });
  });
  $('compare').addEventListener('change', (e) => { state.compare = e.target.value; retrace(); });
  $('use-file').addEventListener('change', (e) => { state.useFile = e.target.checked; retrace(); });
  $('full-digits').addEventListener('change', (e) => {
    state.full = e.target.checked;
    derivation.setFull(state.full);
    redraw();
  });
  $('atlas-toggle').addEventListener('change', (e) => { state.atlas = e.target.checked; redraw(); });
  $('zoom-in').addEventListener('click', () => { image.zoomIn(); redraw(); });
  $('zoom-out').addEventListener('click', () => { image.zoomOut(); redraw(); });
  // A narrower window offers smaller zooms: the image always fits its box.
  new ResizeObserver(() => redraw()).observe($('image-panel'));
  for (const button of document.querySelectorAll('#lang-switch button'))
    button.addEventListener('click', () => {
      state.lang = button.dataset.lang;
      rememberLanguage(state.lang);
      applyLanguage();
    });
  const step = (to) => {
    if (!current || !current.view) return;
    state.step = Math.max(0, Math.min(to, current.view.steps.length - 1));
    redraw();
  };
  $('step-first').addEventListener('click', () => step(0));
  $('step-prev').addEventListener('click', () => step(state.step - 1));
  $('step-next').addEventListener('click', () => step(state.step + 1));
  $('step-last').addEventListener('click', () => step(Infinity));
  document.addEventListener('keydown', (event) => {
    const focus = document.activeElement;
    // The focused image and 3D view take the arrows themselves (and stop
    // them); Home and End still walk the steps there.
    if (focus && /^(INPUT|SELECT|TEXTAREA)$/.test(focus.tagName)) return;
    // In the lessons section the arrows walk the lesson's steps (lessons.js).
    if (focus && focus.closest && focus.closest('#lessons-panel')) return;
    if (event.altKey || event.ctrlKey || event.metaKey) return;
    const keys = { ArrowLeft: () => step(state.step - 1), ArrowRight: () => step(state.step + 1), Home: () => step(0), End: () => step(Infinity) };
    if (!keys[event.key]) return;
    event.preventDefault();
    keys[event.key]();
  });
  $('traces-input').addEventListener('change', async (event) => {
    const file = event.target.files[0];
    if (file) openTraces(new Uint8Array(await file.arrayBuffer()), file.name);
  });
  const frame = $('image-frame');
  frame.addEventListener('dragover', (event) => event.preventDefault());
  frame.addEventListener('drop', async (event) => {
    event.preventDefault();
    const file = event.dataTransfer.files[0];
    if (file) openTraces(new Uint8Array(await file.arrayBuffer()), file.name);
  });
  window.addEventListener('hashchange', () => {
    const before = JSON.stringify(state);
    readFragment(state, location.hash, data.w);
    if (JSON.stringify(state) === before) return;
    openFragmentScene();
    applyLanguage();
    renderImage();
    retrace(); // a link to another pixel or other settings: its trace
  });

  // A link's scene the loader refused (its message shown by the panel), or null.
  let linkRefused = null;
  // Opens a link's scene; false when the loader refuses it, with the
  // loader's message in the page's language.
  function openLink(next) {
    tracer.useLanguage(state.lang);
    try {
      opened = tracer.openScene(next.text, next.file, next.w);
    } catch (error) {
      linkRefused = next;
      $('scene-link-status').textContent = t('edit_link_invalid', { text: error.message });
      return false;
    }
    $('scene-link-status').textContent = '';
    return true;
  }

  // A link's edited scene (or w): opened by the same loader; refused, the one shown stays.
  function openFragmentScene() {
    const next = { text: state.scene ?? exported.text, file: state.scene !== null ? editedFile : exported.file, w: state.w || exported.w, edited: state.scene !== null };
    if (next.text === scene.text && next.w === scene.w && next.edited === scene.edited) return;
    linkRefused = null;
    if (!openLink(next)) {
      // (a failed open leaves the page's scene open)
      state.scene = scene.edited ? scene.text : null;
      state.w = scene.w !== exported.w ? scene.w : null;
      return;
    }
    editor.set(modelOf(opened.scene_content), next.w);
    openScene(next);
  }

  $('status').textContent = '';
  editor.set(modelOf(exportedContent), exported.w);
  applyLanguage();
  labImage();
  openFragmentScene();
  renderImage();
  if (data.traces) openTraces(bytesOf(data.traces), data.traces_file);
  else retrace();
  // For the browser tests (tests/web/edit_test.mjs): the image's bytes and
  // the selected pixel's trace, as the page holds them.
  window.promykPage = {
    image() {
      const base64 = (bytes) => {
        let binary = '';
        for (let k = 0; k < bytes.length; k += 0x8000) binary += String.fromCharCode(...bytes.subarray(k, k + 0x8000));
        return btoa(binary);
      };
      return { w: image.w, channels: image.channels, base64: base64(image.image), map: base64(image.map) };
    },
    trace: () => (current ? current.text : null),
    // What the 3D view draws of the scene (with what waits for the image drawn).
    view3d: () => (wantedImage === shownImage && drawWaiting(), { spheres: view3d.objects.sphere.length, planes: view3d.objects.plane.length, lights: view3d.lights.length, zE: view3d.zE }),
  };
  document.body.dataset.readyMs = String(performance.now());
  document.body.dataset.ready = 'true';
}

start().catch(showError);
