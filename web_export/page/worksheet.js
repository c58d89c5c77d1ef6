// The worksheet mode of the lessons section: the lesson runner's worksheet
// HTML (`promyk lesson NAME --worksheet --format html`, one <input> a blank,
// each with its <label>), checked by the project's own answer checker in the
// wasm (promyk_check_answers: the marks and reasons `promyk lesson --answers`
// prints), and saved as the answer file that command reads
// (promyk_worksheet_file). The page never judges a number itself: what is
// checked is the very text that is saved.
import { t } from './words.js';

export class WorksheetPanel {
  // bar: the element under the lesson's controls that holds Check and Save;
  // lessons: the Lessons section (its tracer, lesson name and options).
  constructor(bar, lessons) {
    this.bar = bar;
    this.lessons = lessons;
    this.body = null;
    this.shown = null; // promyk_lesson's worksheet answer
    this.options = null;
    // What was typed, by lesson and pixels: kept while the lesson is shown
    // again (another mode, step mode, language) in this page.
    this.kept = new Map();
    this.hint = el('p', { id: 'worksheet-hint', className: 'note' });
    this.check = el('button', { type: 'button', id: 'worksheet-check' });
    this.save = el('button', { type: 'button', id: 'worksheet-save' });
    this.result = el('p', { id: 'worksheet-result', role: 'status' });
    this.other = el('ul', { id: 'worksheet-other' });
    const row = el('div', { className: 'row', id: 'worksheet-buttons' });
    row.append(this.check, this.save);
    bar.append(this.hint, row, this.result, this.other);
    this.check.addEventListener('click', () => this.checkAnswers());
    this.save.addEventListener('click', () => this.saveAnswers());
  }

  setWords() {
    this.hint.textContent = t('worksheet_page_hint');
    this.check.textContent = t('worksheet_page_check');
    this.save.textContent = t('worksheet_page_save');
  }

  // A worksheet shown in `body` (null: none); its fields mirrored into the
  // places that show the same blank again.
  attach(body, shown, options) {
    this.body = body;
    this.shown = shown;
    this.options = options;
    this.bar.hidden = !shown;
    this.result.textContent = '';
    this.other.replaceChildren();
    if (!shown) return;
    this.setWords();
    const place = `${shown.name}|${JSON.stringify(shown.pixels)}|${shown.w}|${shown.scene}`;
    if (!this.kept.has(place)) this.kept.set(place, {});
    const kept = this.kept.get(place);
    const mirror = (input) => {
      for (const copy of body.querySelectorAll(`.blank-copy[data-blank="${input.dataset.blank}"]`)) {
        if (copy.dataset.empty === undefined) copy.dataset.empty = copy.textContent;
        copy.textContent = input.value.trim() ? `${input.value.trim()} (${input.dataset.blank})` : copy.dataset.empty;
      }
    };
    for (const input of body.querySelectorAll('input.blank-field')) {
      if (kept[input.dataset.blank]) {
        input.value = kept[input.dataset.blank];
        mirror(input);
      }
      input.addEventListener('input', () => {
        kept[input.dataset.blank] = input.value;
        this.unmark(input.dataset.blank);
        mirror(input);
      });
    }
  }

  // What the pupil typed: {blank number: text}.
  typed() {
    const typed = {};
    for (const input of this.body.querySelectorAll('input.blank-field')) typed[input.dataset.blank] = input.value;
    return typed;
  }

  // The answer file, made by the C++ from the worksheet's own form.
  file() {
    return this.lessons.page.tracer.worksheetFile(this.shown.name, this.options, this.typed());
  }

  unmark(n) {
    const input = this.body.querySelector(`#blank-${n}`);
    if (!input) return;
    const mark = this.body.querySelector(`#mark-${n}`);
    if (mark) mark.remove();
    input.removeAttribute('aria-invalid');
    input.removeAttribute('aria-describedby');
    input.closest('.blank').classList.remove('right', 'wrong', 'unanswered');
  }

  checkAnswers() {
    let checked;
    try {
      const file = this.file();
      checked = this.lessons.page.tracer.checkAnswers(this.shown.name, this.options, file.text);
    } catch (error) {
      this.result.textContent = t('worksheet_page_error', { text: error.message });
      return;
    }
    for (const input of this.body.querySelectorAll('input.blank-field')) this.unmark(input.dataset.blank);
    const other = [];
    for (const mark of checked.marks) {
      const input = mark.blank !== null ? this.body.querySelector(`#blank-${mark.blank}`) : null;
      if (!input) {
        other.push(mark.text);
        continue;
      }
      const right = /^right/.test(mark.verdict);
      const box = input.closest('.blank');
      box.classList.add(mark.verdict === 'blank' ? 'unanswered' : right ? 'right' : 'wrong');
      // The checker's own words beside the field, and read with it.
      const note = el('span', { id: `mark-${mark.blank}`, className: 'mark' });
      note.dataset.verdict = mark.verdict;
      note.textContent = mark.text;
      box.append(note);
      input.setAttribute('aria-describedby', note.id);
      if (!right && mark.verdict !== 'blank') input.setAttribute('aria-invalid', 'true');
    }
    this.other.replaceChildren(...other.map((text) => el('li', { textContent: text })));
    // Lines of the file that are no blank's (none from the page's own form, as a rule).
    if (other.length) this.other.setAttribute('aria-label', t('worksheet_page_other'));
    else this.other.removeAttribute('aria-label');
    this.result.textContent = checked.summary;
    this.result.dataset.allRight = String(checked.all_right);
  }

  saveAnswers() {
    let file;
    try {
      file = this.file();
    } catch (error) {
      this.result.textContent = t('worksheet_page_error', { text: error.message });
      return;
    }
    const url = URL.createObjectURL(new Blob([file.text], { type: 'text/plain;charset=utf-8' }));
    const link = document.createElement('a');
    link.href = url;
    link.download = file.file;
    document.body.append(link);
    link.click();
    link.remove();
    setTimeout(() => URL.revokeObjectURL(url), 1000);
    this.result.textContent = t('worksheet_page_saved', { file: file.file, command: file.command });
  }
}

function el(tag, properties) {
  const element = document.createElement(tag);
  for (const [key, value] of Object.entries(properties)) {
    if (key === 'textContent' || key === 'className' || key === 'id') element[key] = value;
    else element.setAttribute(key, value);
  }
  return element;
}
