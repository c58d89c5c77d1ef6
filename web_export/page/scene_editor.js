// The scene panel: every field of the scene (docs: the scene file's keys,
// src/scene/scene.hpp) as a number field with a slider, spheres, planes,
// lights and materials added and removed. The page validates nothing here:
// the scene's text goes to the C++ loader (promyk_open_scene), and its
// messages come back with a JSON pointer that names the field they are shown
// next to.
import { t } from './words.js';

// A number as the person typed it: a decimal comma or the minus sign U+2212
// accepted; a text that is no number goes to the loader as a string, so its
// own message ("must be a number") says so.
export function numberToken(value) {
  if (typeof value === 'number') return String(value);
  let text = String(value).trim().replace(/\u2212/g, '-');
  if (/^[-+]?\d*,\d*([eE][-+]?\d+)?$/.test(text)) text = text.replace(',', '.');
  if (/^-?(0|[1-9]\d*)(\.\d+)?([eE][-+]?\d+)?$/.test(text)) return text;
  const number = Number(text);
  if (text !== '' && /^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/.test(text) && Number.isFinite(number)) return String(number);
  return JSON.stringify(String(value));
}

const vectorKeys = { S: 1, Q: 1, n: 1, L: 1, colour: 1, background: 1 };

// The scene's text, as `promyk scene check` reads it: one key a line, one
// object a line in the arrays.
export function sceneText(model) {
  const emit = (value, key) => {
    if (typeof value === 'boolean') return String(value);
    if (Array.isArray(value)) return `[${value.map((v) => emit(v, '')).join(', ')}]`;
    if (value && typeof value === 'object')
      return `{${Object.entries(value).filter(([, v]) => v !== undefined).map(([k, v]) => `${JSON.stringify(k)}: ${emit(v, k)}`).join(', ')}}`;
    if (key === 'name') return JSON.stringify(String(value));
    return numberToken(value);
  };
  const lines = [];
  for (const key of ['name', 'z_E', 'background', 'shadows']) lines.push(`  ${JSON.stringify(key)}: ${emit(model[key], key)}`);
  for (const key of ['spheres', 'planes', 'lights', 'materials']) {
    const items = model[key];
    lines.push(items.length ? `  ${JSON.stringify(key)}: [\n${items.map((item) => `    ${emit(item, '')}`).join(',\n')}\n  ]` : `  ${JSON.stringify(key)}: []`);
  }
  return `{\n${lines.join(',\n')}\n}\n`;
}

// The editor's model from the loader's scene (scene_content: every default
// written); numbers are kept as the texts shown in the fields.
export function modelOf(content) {
  const text = (x) => String(x);
  const vector = (v) => v.map(text);
  const colour = (c) => (Array.isArray(c) ? vector(c) : [text(c), text(c), text(c)]);
  const material = (m) => (typeof m === 'number' && m >= 0 ? m : undefined);
  return {
    name: content.name ?? 'untitled',
    z_E: text(content.z_E ?? 2),
    background: colour(content.background ?? 0.5),
    shadows: Boolean(content.shadows),
    spheres: (content.spheres || []).map((s) => ({ S: vector(s.S), r: text(s.r), material: material(s.material) })),
    planes: (content.planes || []).map((p) => ({ Q: vector(p.Q), n: vector(p.n), material: material(p.material) })),
    lights: (content.lights || []).map((l) => ({ L: vector(l.L), I: text(l.I), colour: colour(l.colour ?? 1) })),
    materials: (content.materials || []).map((m) => ({
      ambient: text(m.ambient ?? 0), diffuse: text(m.diffuse ?? 1), specular: text(m.specular ?? 0),
      exponent: text(m.exponent ?? 10), colour: colour(m.colour ?? 1),
    })),
  };
}

// What a new object starts as.
const fresh = {
  spheres: () => ({ S: ['0', '0', '4'], r: '0.5', material: undefined }),
  planes: () => ({ Q: ['0', '-1', '0'], n: ['0', '1', '0'], material: undefined }),
  lights: () => ({ L: ['2', '2', '0'], I: '0.5', colour: ['1', '1', '1'] }),
  materials: () => ({ ambient: '0', diffuse: '1', specular: '0', exponent: '10', colour: ['1', '1', '1'] }),
};

// The sliders' ranges per field (the number field takes any value).
const ranges = {
  z_E: [0.1, 10, 0.01], position: [-10, 10, 0.01], r: [0.01, 5, 0.01], n: [-1, 1, 0.01], I: [0, 2, 0.01],
  channel: [0, 1, 0.01], coefficient: [0, 1, 0.01], exponent: [1, 200, 1], w: [1, 1024, 1],
};

export const maxW = 2048; // as promyk export's largest pane

export class SceneEditor {
  // onChange() after every edit; the model and w are read from the editor.
  constructor(box, { onChange }) {
    this.box = box;
    this.onChange = onChange;
    this.model = null;
    this.w = '1';
    this.fields = new Map(); // pointer -> {input, slider, error}
    this.groups = new Map(); // pointer -> error element (a vector's, a list's)
  }

  set(model, w) {
    this.model = model;
    this.w = String(w);
    this.build();
  }

  // The panel from the model (on a new scene, an added or removed object, a language).
  build(focusPointer = null) {
    const box = this.box;
    box.replaceChildren();
    this.fields.clear();
    this.groups.clear();
    const m = this.model;
    if (!m) return;
    const top = document.createElement('div');
    top.className = 'edit-top';
    top.append(this.textField('/name', t('edit_name'), m.name, (v) => { m.name = v; }));
    top.append(this.numberField('/w', t('edit_w'), this.w, ranges.w, (v) => { this.w = v; }, 'numeric'));
    top.append(this.numberField('/z_E', t('edit_z_E'), m.z_E, ranges.z_E, (v) => { m.z_E = v; }));
    top.append(this.vectorField('/background', t('edit_background'), m.background, 'colour'));
    const shadows = document.createElement('label');
    shadows.className = 'edit-check';
    const box2 = document.createElement('input');
    box2.type = 'checkbox';
    box2.id = 'edit-shadows';
    box2.checked = m.shadows;
    box2.dataset.pointer = '/shadows';
    box2.addEventListener('change', () => { m.shadows = box2.checked; this.onChange(); });
    shadows.append(box2, ' ', t('edit_shadows'));
    top.append(shadows);
    box.append(top);
    const lists = [
      ['spheres', 'edit_spheres', 'edit_sphere', 'edit_add_sphere', (item, p) => [
        this.vectorField(`${p}/S`, t('edit_S'), item.S, 'position'),
        this.numberField(`${p}/r`, t('edit_r'), item.r, ranges.r, (v) => { item.r = v; }),
        this.materialField(`${p}/material`, item)]],
      ['planes', 'edit_planes', 'edit_plane', 'edit_add_plane', (item, p) => [
        this.vectorField(`${p}/Q`, t('edit_Q'), item.Q, 'position'),
        this.vectorField(`${p}/n`, t('edit_n'), item.n, 'n'),
        this.materialField(`${p}/material`, item)]],
      ['lights', 'edit_lights', 'edit_light', 'edit_add_light', (item, p) => [
        this.vectorField(`${p}/L`, t('edit_L'), item.L, 'position'),
        this.numberField(`${p}/I`, t('edit_I'), item.I, ranges.I, (v) => { item.I = v; }),
        this.vectorField(`${p}/colour`, t('edit_colour'), item.colour, 'colour')]],
      ['materials', 'edit_materials', 'edit_material', 'edit_add_material', (item, p) => [
        this.numberField(`${p}/ambient`, t('edit_ambient'), item.ambient, ranges.coefficient, (v) => { item.ambient = v; }),
        this.numberField(`${p}/diffuse`, t('edit_diffuse'), item.diffuse, ranges.coefficient, (v) => { item.diffuse = v; }),
        this.numberField(`${p}/specular`, t('edit_specular'), item.specular, ranges.coefficient, (v) => { item.specular = v; }),
        this.numberField(`${p}/exponent`, t('edit_exponent'), item.exponent, ranges.exponent, (v) => { item.exponent = v; }, 'numeric'),
        this.vectorField(`${p}/colour`, t('edit_colour'), item.colour, 'colour')]],
    ];
    for (const [key, heading, itemWord, addWord, fieldsOf] of lists) {
      const section = document.createElement('section');
      section.className = 'edit-list';
      section.dataset.list = key;
      const h = document.createElement('h3');
      h.textContent = t(heading);
      const error = this.errorElement(`/${key}`);
      section.append(h, error);
      m[key].forEach((item, k) => {
        const pointer = `/${key}/${k}`;
        const item_ = document.createElement('fieldset');
        item_.className = 'edit-item';
        item_.dataset.pointer = pointer;
        const legend = document.createElement('legend');
        const title = t(itemWord, { k });
        legend.textContent = title;
        const remove = document.createElement('button');
        remove.type = 'button';
        remove.className = 'edit-remove';
        remove.dataset.remove = pointer;
        remove.textContent = t('edit_remove', { what: title });
        remove.addEventListener('click', () => this.remove(key, k));
        item_.append(legend, this.errorElement(pointer), ...fieldsOf(item, pointer), remove);
        section.append(item_);
      });
      const add = document.createElement('button');
      add.type = 'button';
      add.className = 'edit-add';
      add.dataset.add = key;
      add.textContent = t(addWord);
      add.addEventListener('click', () => {
        m[key].push(fresh[key]());
        this.build(`/${key}/${m[key].length - 1}`);
        this.onChange();
      });
      section.append(add);
      box.append(section);
    }
    if (focusPointer) {
      const first = box.querySelector(`input[data-pointer^="${focusPointer}/"], [data-add="${focusPointer}"]`);
      if (first) first.focus();
    }
  }

  remove(key, k) {
    const m = this.model;
    m[key].splice(k, 1);
    if (key === 'materials')
      for (const item of [...m.spheres, ...m.planes]) {
        // Objects keep their own material: a removed one's objects take the article's.
        if (item.material === k) item.material = undefined;
        else if (item.material > k) item.material -= 1;
      }
    this.build(key);
    this.onChange();
  }

  errorElement(pointer) {
    const error = document.createElement('p');
    error.className = 'field-error';
    error.id = `error-${idOf(pointer)}`;
    error.hidden = true;
    this.groups.set(pointer, error);
    return error;
  }

  textField(pointer, label, value, set) {
    const row = document.createElement('div');
    row.className = 'edit-field';
    const id = `field-${idOf(pointer)}`;
    const name = document.createElement('label');
    name.htmlFor = id;
    name.textContent = label;
    const input = document.createElement('input');
    input.type = 'text';
    input.id = id;
    input.value = value;
    input.dataset.pointer = pointer;
    const error = this.errorElement(pointer);
    input.setAttribute('aria-describedby', error.id);
    input.addEventListener('input', () => { set(input.value); this.onChange(); });
    row.append(name, input, error);
    this.fields.set(pointer, { input, error });
    return row;
  }

  // A number: a text field (what is typed goes to the loader) and a slider.
  numberField(pointer, label, value, [min, max, step], set, mode = 'decimal') {
    const row = this.textField(pointer, label, value, set);
    const { input } = this.fields.get(pointer);
    input.inputMode = mode;
    input.className = 'edit-number';
    const slider = document.createElement('input');
    slider.type = 'range';
    slider.min = String(min);
    slider.max = String(max);
    slider.step = String(step);
    slider.value = String(Number(numberToken(value)) || 0);
    slider.setAttribute('aria-label', t('edit_slider', { what: label }));
    slider.dataset.slider = pointer;
    slider.addEventListener('input', () => {
      input.value = slider.value;
      set(slider.value);
      this.onChange();
    });
    input.addEventListener('input', () => {
      const number = Number(JSON.parse(numberToken(input.value)));
      if (Number.isFinite(number)) slider.value = String(number);
    });
    row.insertBefore(slider, row.lastChild);
    return row;
  }

  vectorField(pointer, label, values, kind) {
    const group = document.createElement('fieldset');
    group.className = 'edit-vector';
    group.dataset.pointer = pointer;
    const legend = document.createElement('legend');
    legend.textContent = label;
    group.append(legend, this.errorElement(pointer));
    const names = kind === 'colour' ? [t('edit_red'), t('edit_green'), t('edit_blue')] : ['x', 'y', 'z'];
    const range = kind === 'colour' ? ranges.channel : kind === 'n' ? ranges.n : ranges.position;
    values.forEach((value, c) => {
      // Shown as "x" (the group's legend names the vector); read out in full.
      const row = this.numberField(`${pointer}/${c}`, `${label}: ${names[c]}`, value, range, (v) => { values[c] = v; });
      row.querySelector('label').textContent = names[c];
      row.querySelector('input[type="text"]').setAttribute('aria-label', `${label}: ${names[c]}`);
      group.append(row);
    });
    return group;
  }

  materialField(pointer, item) {
    const row = document.createElement('div');
    row.className = 'edit-field';
    const id = `field-${idOf(pointer)}`;
    const name = document.createElement('label');
    name.htmlFor = id;
    name.textContent = t('edit_material_of');
    const select = document.createElement('select');
    select.id = id;
    select.dataset.pointer = pointer;
    const options = [['', t('edit_material_none')], ...this.model.materials.map((_, k) => [String(k), t('edit_material', { k })])];
    for (const [value, text] of options) {
      const option = document.createElement('option');
      option.value = value;
      option.textContent = text;
      select.append(option);
    }
    select.value = item.material === undefined ? '' : String(item.material);
    const error = this.errorElement(pointer);
    select.setAttribute('aria-describedby', error.id);
    select.addEventListener('change', () => {
      item.material = select.value === '' ? undefined : Number(select.value);
      this.onChange();
    });
    row.append(name, select, error);
    return row;
  }

  // The loader's faults [{where, what}] next to their fields: each goes to
  // the field or group whose pointer is the longest prefix of its own.
  // Returns the faults no field took.
  showErrors(faults) {
    for (const error of this.groups.values()) {
      error.hidden = true;
      error.textContent = '';
    }
    for (const input of this.box.querySelectorAll('[aria-invalid]')) input.removeAttribute('aria-invalid');
    const left = [];
    for (const fault of faults) {
      let best = null;
      for (const pointer of this.groups.keys())
        if ((fault.where === pointer || fault.where.startsWith(`${pointer}/`)) && (!best || pointer.length > best.length)) best = pointer;
      if (!best) {
        left.push(fault);
        continue;
      }
      const error = this.groups.get(best);
      error.textContent = error.textContent ? `${error.textContent} ${fault.what}` : fault.what;
      error.hidden = false;
      for (const input of this.box.querySelectorAll(`[data-pointer="${best}"], [data-pointer^="${best}/"]`))
        if (input.tagName !== 'FIELDSET') input.setAttribute('aria-invalid', 'true');
    }
    return left;
  }
}

function idOf(pointer) {
  return pointer.replace(/^\//, '').replace(/[^A-Za-z0-9_]/g, '-');
}
