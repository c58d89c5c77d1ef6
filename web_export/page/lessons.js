// The lessons section: every lesson in the page's language, run by the
// project's own lesson runner in the wasm (promyk_lesson, API.md), which
// gives HTML with every text of a lesson or scene escaped and its formulas
// as TeX; KaTeX typesets them here (trust: false). Step mode shows one step
// and its answers' reveals at a time. The lesson runs on its own example
// scene; "use this pixel" runs it on the page's scene at the page's w for
// the selected pixel (on another scene than its own, as `promyk lesson NAME
// --scene FILE` does: the runner says what that scene lacks). Worksheet
// mode shows the runner's worksheet instead (worksheet.js). The lesson, its
// pixel, its step and the mode are kept in the page's URL (state.js).
import katex from 'katex';
import { t } from './words.js';
import { WorksheetPanel } from './worksheet.js';

const katexOptions = { throwOnError: false, trust: false, strict: 'ignore', output: 'htmlAndMathml' };

export class Lessons {
  // page: { tracer, pixel() → [i, j] | null, scene() → {hash, name, w}, onShow(),
  //        state (the page's, state.js: lesson, lessonPixel, lessonStep, worksheet), save() }
  constructor(root, page) {
    this.root = root;
    this.page = page;
    this.lang = 'en';
    this.list = [];
    this.name = null; // the lesson shown
    this.pixel = null; // null: the lesson's own scene and pixels; [i, j]: the page's scene
    this.stepMode = false;
    this.step = 1;
    this.shown = null; // promyk_lesson's answer
    const $ = (id) => root.querySelector(`#${id}`);
    this.select = $('lesson-select');
    this.body = $('lesson-body');
    this.note = $('lesson-note');
    this.usePixel = $('lesson-use-pixel');
    this.ownPixels = $('lesson-own-pixels');
    this.stepToggle = $('lesson-step-mode');
    this.stepper = $('lesson-stepper');
    this.counter = $('lesson-step-counter');
    this.prev = $('lesson-prev');
    this.next = $('lesson-next');
    this.mode = 'lesson'; // or 'worksheet'
    // Lesson or worksheet: a radio group (the arrows move between them).
    const modes = document.createElement('fieldset');
    modes.id = 'lesson-mode';
    const legend = document.createElement('legend');
    legend.id = 'lesson-mode-legend';
    modes.append(legend);
    this.modeInputs = {};
    for (const mode of ['lesson', 'worksheet']) {
      const label = document.createElement('label');
      const input = document.createElement('input');
      input.type = 'radio';
      input.name = 'lesson-mode';
      input.value = mode;
      input.id = `lesson-mode-${mode}`;
      const words = document.createElement('span');
      words.id = `lesson-mode-${mode}-label`;
      label.append(input, ' ', words);
      modes.append(label);
      this.modeInputs[mode] = input;
      input.addEventListener('change', () => {
        if (!input.checked) return;
        this.mode = mode;
        this.open(this.name, this.pixel, true);
        this.remember();
      });
    }
    $('lesson-controls').append(modes);
    const bar = document.createElement('div');
    bar.id = 'worksheet-bar';
    bar.hidden = true;
    this.body.after(bar); // after the fields: Tab goes from the last field to Check
    this.worksheet = new WorksheetPanel(bar, this);
    this.select.addEventListener('change', () => {
      this.open(this.select.value, null);
      this.remember();
    });
    this.usePixel.addEventListener('click', () => {
      const pixel = this.page.pixel();
      if (pixel) this.open(this.name, pixel);
      this.remember();
    });
    this.ownPixels.addEventListener('click', () => {
      this.open(this.name, null);
      this.remember();
    });
    this.stepToggle.addEventListener('change', () => {
      this.stepMode = this.stepToggle.checked;
      this.step = 1;
      this.showStep();
      this.remember();
    });
    this.prev.addEventListener('click', () => this.go(this.step - 1));
    this.next.addEventListener('click', () => this.go(this.step + 1));
    // In step mode, ← and → (focus in the section, not in a field) walk the steps.
    root.addEventListener('keydown', (event) => {
      if (!this.stepMode || event.altKey || event.ctrlKey || event.metaKey) return;
      if (/^(INPUT|SELECT|TEXTAREA)$/.test(event.target.tagName)) return;
      const by = { ArrowLeft: -1, ArrowRight: 1 }[event.key];
      if (!by) return;
      event.preventDefault();
      this.go(this.step + by);
    });
    for (const [id, answers] of [['lesson-print', false], ['lesson-print-key', true]])
      $(id).addEventListener('click', () => this.print(answers));
  }

  // The interface's words and the list in `lang`; the lesson shown again in it.
  setLanguage(lang) {
    this.lang = lang;
    const words = {
      'lessons-heading': 'lessons_page_heading', 'lessons-intro': 'lessons_page_intro', 'lesson-select-label': 'lessons_page_choose',
      'lesson-own-pixels': 'lessons_page_own_pixels', 'lesson-step-mode-label': 'lessons_page_step_mode',
      'lesson-prev': 'lessons_page_prev', 'lesson-next': 'lessons_page_next', 'lesson-print': 'lessons_page_print',
      'lesson-print-key': 'lessons_page_print_key', 'lesson-mode-legend': 'worksheet_page_mode',
      'lesson-mode-lesson-label': 'worksheet_page_mode_lesson', 'lesson-mode-worksheet-label': 'worksheet_page_mode_worksheet',
    };
    for (const [id, word] of Object.entries(words)) this.root.querySelector(`#${id}`).textContent = t(word);
    this.list = this.page.tracer.lessons(lang).lessons;
    this.select.replaceChildren(...this.list.map((lesson) => {
      const option = document.createElement('option');
      option.value = lesson.name;
      option.textContent = lesson.title;
      return option;
    }));
    // The lesson, its pixel, step and mode as the page's state (a link) says.
    const state = this.page.state;
    if (state && state.lesson) {
      this.name = state.lesson;
      this.pixel = state.lessonPixel;
      this.stepMode = state.lessonStep > 0;
      this.step = state.lessonStep || 1;
      this.mode = state.worksheet ? 'worksheet' : 'lesson';
    }
    if (!this.list.some((lesson) => lesson.name === this.name)) this.name = this.list.length ? this.list[0].name : null;
    this.select.value = this.name || '';
    this.stepToggle.checked = this.stepMode;
    this.open(this.name, this.pixel, true);
  }

  // The section's state into the page's (its URL): a link reopens it.
  remember() {
    const state = this.page.state;
    if (!state) return;
    state.lesson = this.name;
    state.lessonPixel = this.pixel;
    state.lessonStep = this.stepMode ? this.step : 0;
    state.worksheet = this.mode === 'worksheet';
    if (this.page.save) this.page.save();
  }

  // The selected pixel changed: "use this pixel" says whether there is one.
  refresh() {
    const pixel = this.page.pixel();
    this.usePixel.disabled = !pixel;
    this.usePixel.textContent = pixel ? `${t('lessons_page_use_pixel')} (${pixel[0]}, ${pixel[1]})` : t('lessons_page_use_pixel_none');
  }

  // Runs lesson `name` on its own scene (pixel null) or on the page's scene
  // for `pixel`, as a lesson or a worksheet; `keepStep` keeps the step.
  open(name, pixel, keepStep = false) {
    this.refresh();
    if (!name) return;
    const lesson = this.list.find((l) => l.name === name);
    const scene = this.page.scene();
    if (pixel && (pixel[0] >= scene.w || pixel[1] >= scene.w)) pixel = null;
    const changed = name !== this.name;
    this.name = name;
    this.pixel = pixel;
    if (changed && !keepStep) this.step = 1;
    for (const [mode, input] of Object.entries(this.modeInputs)) input.checked = mode === this.mode;
    const options = { lang: this.lang, digits: 4, scene: pixel ? 'open' : 'own' };
    try {
      if (pixel) options.pixels = [pixel];
      if (this.mode === 'worksheet') options.worksheet = true;
      this.shown = this.page.tracer.lesson(name, options);
    } catch (error) {
      this.shown = null;
      this.worksheet.attach(this.body, null, null);
      this.body.replaceChildren();
      this.note.textContent = t('lessons_page_error', { text: error.message });
      return;
    }
    const s = this.shown;
    const pixels = s.pixels.map(([i, j]) => `(${i}, ${j})`).join(', ');
    const pixelArgs = s.pixels.map(([i, j]) => `--pixel ${i},${j}`).join(' ');
    const command = `promyk lesson ${s.name} ${pixelArgs}${pixel ? ` --w ${s.w}` : ''} --lang ${s.lang}`;
    if (!pixel) this.note.textContent = t('lessons_page_own', { scene: lesson.scene_name, w: s.w, pixels, command });
    else if (s.own_scene) this.note.textContent = t('lessons_page_same_scene', { scene: s.scene, w: s.w, pixels, command });
    else this.note.textContent = t('lessons_page_other_scene', { scene: scene.name, own: lesson.scene_name, name: s.name, pixels, w: s.w });
    this.body.dataset.lesson = s.name;
    this.body.dataset.pixels = JSON.stringify(s.pixels);
    this.body.dataset.w = String(s.w);
    this.body.lang = s.lang;
    // The runner's HTML: every text in it escaped by the C++ (lesson_html.hpp).
    this.body.innerHTML = s.html;
    for (const math of this.body.querySelectorAll('span.math')) {
      const tex = math.textContent;
      math.dataset.tex = tex;
      try {
        katex.render(tex, math, katexOptions);
      } catch {
        math.textContent = tex;
      }
    }
    this.body.dataset.mode = this.mode;
    this.worksheet.attach(this.body, this.mode === 'worksheet' ? s : null, options);
    this.ownPixels.disabled = !pixel;
    this.showStep();
    if (this.page.onShow) this.page.onShow();
  }

  go(step) {
    if (!this.shown) return;
    this.step = Math.max(1, Math.min(step, this.shown.steps));
    this.showStep();
    this.remember();
    const section = this.body.querySelector(`section[data-step="${this.step}"] h2`);
    if (section) {
      section.tabIndex = -1;
      section.focus({ preventScroll: false });
    }
  }

  // Step mode: the current step and its answers' reveals alone; else all.
  showStep() {
    const n = this.shown ? this.shown.steps : 0;
    this.step = Math.max(1, Math.min(this.step, n || 1));
    this.stepper.hidden = !this.stepMode;
    for (const part of this.body.querySelectorAll('[data-step]'))
      part.hidden = this.stepMode && Number(part.dataset.step) !== this.step;
    this.counter.textContent = t('lessons_page_step_of', { k: this.step, n });
    this.prev.disabled = this.step <= 1;
    this.next.disabled = this.step >= n;
  }

  // Prints the lesson (every step; with the answers open for a key) with no interface around it.
  print(answers) {
    const hidden = [...this.body.querySelectorAll('[data-step]')].filter((part) => part.hidden);
    for (const part of hidden) part.hidden = false;
    const reveals = [...this.body.querySelectorAll('details.answer')];
    const open = reveals.map((d) => d.open);
    for (const d of reveals) d.open = answers;
    document.body.dataset.printing = answers ? 'key' : 'lesson';
    window.print();
    delete document.body.dataset.printing;
    reveals.forEach((d, k) => { d.open = open[k]; });
    for (const part of hidden) part.hidden = true;
  }
}
