// The precision lab (issue 17): the error and digits-lost maps of
// `promyk render --map` as overlays on the image, and the bench plot of
// `promyk export --bench`.
//
// One definition of the maps: each pixel's value is computed by the C++ map
// kernels (natively by `promyk export` for the exported image, by the render
// workers' wasm after the scene or the settings change), and coloured, with
// its legend and range, by the same C++ as `render --map` (promyk_map_colour,
// render/map_overlay.hpp). Nothing here knows a colour or a scale.
import { t } from './words.js';
import { drawBenchPlots } from './bench_plot.js';

const $ = (id) => document.getElementById(id);

// The message that names each overlay in the select and the hover.
const overlayWords = { '': 'lab_overlay_none', error: 'lab_overlay_error', 'digits-lost': 'lab_overlay_digits' };

function element(tag, attributes = {}, text = '') {
  const e = document.createElement(tag);
  for (const [name, value] of Object.entries(attributes)) e.setAttribute(name, value);
  if (text) e.textContent = text;
  return e;
}

function float64s(bytes) {
  // A fresh copy: a Float64Array needs its offset aligned to 8.
  return new Float64Array(bytes.slice().buffer);
}

export class PrecisionLab {
  // M: the page's module; data: export's data; image: the ImageView;
  // pool(): the render workers (started on demand); redraw(): the page's
  // redraw; setSettings(real, formula): as the settings selects do;
  // command(kind): the command line that draws the map.
  constructor({ M, data, image, pool, redraw, setSettings, command, exportedKey }) {
    this.M = M;
    this.image = image;
    this.pool = pool;
    this.redraw = redraw;
    this.setSettings = setSettings;
    this.command = command;
    this.lang = 'en';
    this.kind = ''; // the overlay shown: '', 'error', 'digits-lost'
    this.fixed = false; // "fix the range": the error map's range kept
    this.fixedRange = null; // [low, high] while fixed
    this.current = null; // the image shown: {key, text, file, w, settings, sceneName}; null while one renders
    this.shown = null; // the overlay drawn: {kind, key, values, info, rgb, source}
    this.cache = new Map(); // `${kind}|${key}` → {values, source}
    this.job = 0;
    this.maxW = data.maps ? data.maps.max_w : 0;
    if (data.maps && data.maps.error) {
      this.cache.set(`error|${exportedKey}`, { values: float64s(Uint8Array.from(atob(data.maps.error), (c) => c.charCodeAt(0))), source: 'export' });
      this.cache.set(`digits-lost|${exportedKey}`, { values: float64s(Uint8Array.from(atob(data.maps.digits_lost), (c) => c.charCodeAt(0))), source: 'export' });
    }
    this.bench = data.bench || null;
    this.benchFile = data.bench_file || '';
    this.build();
    window.promykLab = this.testView();
  }

  build() {
    // The overlay's controls and legend: under the image, by the branch atlas's.
    const box = element('div', { id: 'lab-overlay-box' });
    const row = element('div', { class: 'row' });
    const label = element('label');
    label.append(element('span', { id: 'lab-overlay-label' }), ' ');
    this.select = element('select', { id: 'lab-overlay' });
    label.append(this.select);
    const fix = element('label', { id: 'lab-fix-row' });
    this.fixBox = element('input', { type: 'checkbox', id: 'lab-fix-range' });
    fix.append(this.fixBox, ' ', element('span', { id: 'lab-fix-label' }));
    row.append(label, fix);
    const legend = element('div', { id: 'lab-legend', hidden: '' });
    legend.append(element('p', { id: 'lab-legend-title', class: 'lab-legend-title' }));
    const bar = element('div', { class: 'lab-bar' });
    bar.append(element('canvas', { id: 'lab-bar', width: '256', height: '14', role: 'img' }), element('div', { id: 'lab-ticks', class: 'lab-ticks' }));
    legend.append(bar, element('p', { id: 'lab-range' }), element('ul', { id: 'lab-swatches' }));
    box.append(row, element('p', { id: 'lab-intro', class: 'note', hidden: '' }), element('p', { id: 'lab-source', class: 'note' }), element('p', { id: 'lab-status', class: 'note', role: 'status' }), legend);
    const far = element('div', { id: 'lab-far', hidden: '' });
    far.append(element('p', { id: 'lab-far-text', class: 'note' }));
    const tries = element('div', { class: 'row' });
    for (const [real, formula] of [['float', 'article'], ['float', 'geometric'], ['double', 'article']]) {
      const button = element('button', { type: 'button', 'data-real': real, 'data-formula': formula });
      button.addEventListener('click', () => this.setSettings(real, formula));
      tries.append(button);
    }
    far.append(tries);
    box.append(far);
    $('hover').after(box);

    // The bench plot: a section of its own, the page's width.
    const section = element('section', { id: 'lab-panel', 'aria-labelledby': 'lab-bench-heading' });
    section.append(element('h2', { id: 'lab-bench-heading' }), element('p', { id: 'lab-bench-intro', class: 'note' }),
      element('p', { id: 'lab-bench-readout', 'aria-live': 'polite' }), element('div', { id: 'lab-bench-plots' }));
    $('lessons-panel').before(section);

    this.select.addEventListener('change', () => {
      this.kind = this.select.value;
      this.refresh();
    });
    this.fixBox.addEventListener('change', () => {
      this.fixed = this.fixBox.checked;
      this.fixedRange = this.fixed && this.shown && this.shown.kind === 'error' ? this.shown.info.range : null;
      if (this.shown) this.show(this.shown.kind, this.shown.key, this.shown.values, this.shown.source);
      else this.refresh();
    });
  }

  setLanguage(lang) {
    this.lang = lang;
    $('lab-overlay-label').textContent = t('lab_overlay');
    this.select.replaceChildren(...['', 'error', 'digits-lost'].map((kind) => {
      const option = element('option', { value: kind }, t(overlayWords[kind]));
      return option;
    }));
    this.select.value = this.kind;
    $('lab-fix-label').textContent = t('lab_fix_range');
    $('lab-intro').textContent = t('lab_intro');
    $('lab-far-text').textContent = t('lab_far_sphere');
    for (const button of document.querySelectorAll('#lab-far button'))
      button.textContent = t('lab_try', { real: button.dataset.real, formula: button.dataset.formula });
    $('lab-bench-heading').textContent = t('lab_bench_heading');
    this.drawBench();
    // The legend's words and numbers in the new language (the same values).
    if (this.shown) this.show(this.shown.kind, this.shown.key, this.shown.values, this.shown.source);
    else this.refresh();
  }

  // A new image is being rendered: the overlay waits for it.
  imageWanted() {
    this.current = null;
    ++this.job;
    this.refresh();
  }

  // The image shown now (key: main.js's imageKey of it).
  imageShown(current) {
    const changed = !this.current || this.current.key !== current.key;
    this.current = current;
    $('lab-far').hidden = current.sceneName !== 'far_sphere';
    if (changed) this.refresh();
  }

  // The overlay of the image shown: from the cache, or computed by the workers.
  async refresh() {
    const kind = this.kind;
    this.fixBox.disabled = kind !== 'error';
    $('lab-intro').hidden = !kind;
    const current = this.current;
    if (!kind || !current) {
      this.hide(kind && !current ? t('lab_computing', { percent: 0 }) : '');
      return;
    }
    const cacheKey = `${kind}|${current.key}`;
    const cached = this.cache.get(cacheKey);
    if (cached) {
      this.show(kind, current.key, cached.values, cached.source);
      return;
    }
    // The page computes maps of up to max_w² samples (w² · spp): at
    // w = 256 a float error map takes about a second in four workers.
    const samples = current.w * current.w * current.settings.spp;
    if (samples > this.maxW * this.maxW) {
      this.hide(t('lab_too_large', { w: current.w, spp: current.settings.spp, samples, max: this.maxW * this.maxW, command: this.command(kind) }));
      return;
    }
    const job = ++this.job;
    this.hide(t('lab_computing', { percent: 0 }));
    let result;
    try {
      result = await this.pool().render({ scene: current.text, file: current.file, w: current.w, settings: current.settings, mapKind: kind }, (done, w) => {
        if (job === this.job) $('lab-status').textContent = t('lab_computing', { percent: Math.floor((100 * done) / w) });
      });
    } catch (error) {
      if (job === this.job) this.hide(String(error && error.message ? error.message : error));
      return;
    }
    if (!result || job !== this.job) return; // superseded (a new image, another overlay)
    for (const key of [...this.cache.keys()]) if (this.cache.get(key).source === 'page') this.cache.delete(key); // one at a time
    this.cache.set(cacheKey, { values: result.values, source: 'page' });
    if (this.kind === kind && this.current === current) this.show(kind, current.key, result.values, 'page');
  }

  hide(status) {
    this.shown = null;
    this.image.setOverlay(null);
    $('lab-legend').hidden = true;
    $('lab-source').textContent = '';
    $('lab-status').textContent = status;
    this.redraw();
  }

  // Colours the values with promyk_map_colour (the range fixed or the run's
  // own) and draws the overlay and its legend.
  show(kind, key, values, source) {
    const settings = this.current ? this.current.settings : { real: 'double', formula: 'article', spp: 1 };
    const range = kind === 'error' && this.fixed ? this.fixedRange : null;
    const { info, rgb } = this.colour(kind, settings, values, range);
    if (kind === 'error' && this.fixed && !this.fixedRange) this.fixedRange = info.range;
    this.shown = { kind, key, values, info, rgb, source };
    this.image.setOverlay(rgb);
    $('lab-status').textContent = '';
    $('lab-source').textContent = t(kind === 'error' ? 'lab_map_of' : 'lab_map_of_digits', {
      real: settings.real, formula: settings.formula, spp: settings.spp, source: t(source === 'export' ? 'lab_source_export' : 'lab_source_page'),
    });
    this.drawLegend(info);
    this.redraw();
  }

  colour(kind, settings, values, range) {
    const M = this.M;
    const bytes = values.length * 8;
    const at = M._malloc(Math.max(8, bytes));
    try {
      M.HEAPU8.set(new Uint8Array(values.buffer, values.byteOffset, bytes), at);
      const info = JSON.parse(M.ccall('promyk_map_colour', 'string', ['string', 'string', 'number', 'number', 'string'],
        [kind, JSON.stringify(settings), at, values.length, JSON.stringify({ lang: this.lang, range })]));
      if (info.error) throw new Error(info.error);
      return { info, rgb: M.HEAPU8.slice(info.rgb, info.rgb + info.rgb_bytes) };
    } finally {
      M._free(at);
    }
  }

  drawLegend(info) {
    $('lab-legend').hidden = false;
    $('lab-legend-title').textContent = info.title;
    const canvas = $('lab-bar');
    const ctx = canvas.getContext('2d');
    info.ramp.forEach((hex, k) => {
      ctx.fillStyle = hex;
      ctx.fillRect(k, 0, 1, canvas.height);
    });
    canvas.setAttribute('aria-label', `${info.title}: ${info.range_text[0]} … ${info.range_text[1]}`);
    // The bar's numbers (render --legend's ticks); one too close to the last
    // one shown is kept for screen readers but not drawn.
    const ticks = $('lab-ticks');
    ticks.replaceChildren();
    let last = -1;
    info.ticks.forEach((tick, k) => {
      const span = element('span', { class: 'lab-tick' }, tick.text);
      span.style.left = `${(100 * tick.t).toFixed(3)}%`;
      const end = k === info.ticks.length - 1;
      if (last >= 0 && tick.t - last < 0.12 && !end) span.classList.add('lab-tick-skipped');
      else last = tick.t;
      ticks.append(span);
    });
    $('lab-range').textContent = t('lab_range', {
      low: info.range_text[0], high: info.range_text[1],
      how: info.range_how || t(info.kind === 'error' ? 'map_range_of_run' : 'lab_overlay_digits'),
    });
    $('lab-range').hidden = info.kind !== 'error';
    $('lab-swatches').replaceChildren(...info.swatches.map((swatch) => {
      const item = element('li');
      const box = element('span', { class: 'lab-swatch', 'aria-hidden': 'true' });
      box.style.background = swatch.hex;
      item.dataset.hex = swatch.hex;
      item.append(box, ' ', element('span', {}, swatch.name));
      return item;
    }));
  }

  // What hovering (i, j) says of the overlay: its name and the pixel's value
  // (the project's number formatter, or the special case's legend name).
  hoverText(i, j) {
    if (!this.shown || !this.current || i >= this.current.w || j >= this.current.w) return '';
    const stored = this.shown.values[i * this.current.w + j];
    const r = JSON.parse(this.M.ccall('promyk_map_value_text', 'string', ['string', 'number', 'string'], [this.shown.kind, stored, this.lang]));
    return r.error ? '' : t('lab_hover', { map: t(overlayWords[this.shown.kind]), value: r.text });
  }

  // A number as the project's formatter writes it (3 significant digits).
  number(value) {
    const r = JSON.parse(this.M.ccall('promyk_map_value_text', 'string', ['string', 'number', 'string'], ['error', value, this.lang]));
    return r.error ? String(value) : r.text;
  }

  drawBench() {
    const intro = $('lab-bench-intro');
    const plots = $('lab-bench-plots');
    $('lab-bench-readout').textContent = '';
    if (!this.bench) {
      intro.textContent = t('lab_bench_none');
      plots.replaceChildren();
      return;
    }
    intro.textContent = t('lab_bench_intro', { file: this.benchFile });
    drawBenchPlots(plots, this.bench, {
      t,
      number: (v) => this.number(v),
      readout: (text) => { $('lab-bench-readout').textContent = text; },
    });
  }

  // For the browser tests (tests/web/precision_test.mjs).
  testView() {
    const base64 = (bytes) => {
      let binary = '';
      for (let k = 0; k < bytes.length; k += 0x8000) binary += String.fromCharCode(...bytes.subarray(k, k + 0x8000));
      return btoa(binary);
    };
    return {
      overlay: () => (this.shown ? { kind: this.shown.kind, source: this.shown.source, w: this.current.w, rgb: base64(this.shown.rgb), range: this.shown.info.range, range_text: this.shown.info.range_text } : null),
    };
  }
}
