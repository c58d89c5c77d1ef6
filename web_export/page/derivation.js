// The selected pixel's derivation (a view of promyk_view), step by step in
// the trace's order: the formula typeset, the same formula with the pixel's
// numbers put in, the result; groups (sphere, plane, light, shadow ray,
// sample) as nested foldable blocks. Every text from a trace or a scene is
// set as text; KaTeX typesets only the vocabulary's formulas and the
// formatter's numbers, never with `trust`.
import katex from 'katex';
import { t } from './words.js';
import { quantityColour } from './colours.js';

const katexOptions = { throwOnError: false, trust: false, strict: 'ignore', output: 'htmlAndMathml' };

function typeset(element, tex) {
  try {
    katex.render(tex, element, katexOptions);
  } catch {
    element.textContent = tex;
  }
}

// A number as TeX text: the formatter's characters, TeX's specials escaped.
function texNumber(text) {
  const safe = text.replace(/[\\{}$%#&_^~]/g, (c) => `\\${c === '\\' ? 'backslash ' : c}`);
  return /^[\d.,]+$/.test(text) || /^[([]/.test(text) ? `\\text{${safe}}` : `\\left(\\text{${safe}}\\right)`;
}

// The components of a shown vector "(a; b; c)" or "(a, b, c)".
function componentsOf(text, lang) {
  const inner = text.replace(/^[([]|[)\]]$/g, '');
  const parts = inner.split(lang === 'pl' ? '; ' : ', ');
  return parts.length === 3 ? parts : null;
}

// The right-hand side of `tex` (after its last '=' outside braces) with the
// known quantities replaced by their numbers; null when nothing is known.
// Other spellings of a symbol in the vocabulary's formulas.
const aliases = { '\\tfrac{\\Delta}{4}': ['\\Delta/4'] };

export function withNumbers(tex, known) {
  for (const [symbol, others] of Object.entries(aliases))
    if (known.has(symbol)) for (const other of others) known.set(other, known.get(symbol));
  let depth = 0;
  let last = -1;
  for (let k = 0; k < tex.length; ++k) {
    const c = tex[k];
    if (c === '{') ++depth;
    else if (c === '}') --depth;
    else if (c === '=' && depth === 0) last = k;
  }
  if (last < 0) return null;
  const rhs = tex.slice(last + 1);
  // A minimum over a set or a sum over samples has no single number per symbol.
  if (/\\min\\\{|\\sum/.test(rhs)) return null;
  const literals = [...known.keys()].sort((a, b) => b.length - a.length);
  let out = '';
  let replaced = 0;
  let previousWasNumber = false;
  const isLetter = (c) => c !== undefined && /[A-Za-z]/.test(c);
  for (let k = 0; k < rhs.length;) {
    const component = /^([xyz])_(?:\{([A-Za-z])\}|([A-Za-z]))/.exec(rhs.slice(k));
    let value = null;
    let length = 0;
    if (component && !isLetter(rhs[k - 1])) {
      const name = component[2] || component[3];
      const entry = known.get(name) || known.get(`\\vec{${name}}`);
      if (entry && entry.components) {
        value = entry.components['xyz'.indexOf(component[1])];
        length = component[0].length;
      }
    }
    if (value === null) {
      for (const literal of literals) {
        if (!rhs.startsWith(literal, k)) continue;
        const before = rhs[k - 1];
        const after = rhs[k + literal.length];
        const wordLike = isLetter(literal[0]);
        if (wordLike && (isLetter(before) || before === '\\')) continue;
        if (isLetter(literal[literal.length - 1]) && (isLetter(after) || after === '_')) continue;
        value = known.get(literal).text;
        length = literal.length;
        break;
      }
    }
    if (value !== null) {
      // a product written by juxtaposition (2j, 4|E|², C·C) keeps its dot
      if (previousWasNumber || /[\d})]\s*$/.test(out)) out += '\\cdot ';
      out += texNumber(value);
      k += length;
      ++replaced;
      previousWasNumber = true;
      continue;
    }
    const control = /^\\[A-Za-z]+/.exec(rhs.slice(k));
    const piece = control ? control[0] : rhs[k];
    out += piece;
    k += piece.length;
    if (!/^\s$/.test(piece)) previousWasNumber = false;
  }
  return replaced > 0 ? out : null;
}

export class Derivation {
  constructor(container, outcome) {
    this.container = container;
    this.outcome = outcome;
    this.rows = [];
  }

  // Builds the blocks of a view (promyk_view); `full`: every digit shown.
  show(view, full) {
    this.view = view;
    this.container.replaceChildren();
    this.outcome.replaceChildren();
    this.rows = [];
    const lang = view.lang;
    const header = view.header || {};
    const known = new Map();
    const learn = (tex, text, components) => {
      if (tex) known.set(tex, { text, components });
    };
    learn('i', String(header.i));
    learn('j', String(header.j));
    learn('w', String(header.w));
    const learnGiven = (given) => {
      learn(given.symbol_tex, given.value_shown, componentsOf(given.value_shown, lang));
      if (/^[A-Z]$/.test(given.symbol_tex)) learn(`\\vec{${given.symbol_tex}}`, given.value_shown, componentsOf(given.value_shown, lang));
    };
    for (const given of header.given || []) learnGiven(given);
    const givenGroups = header.given_groups || [];

    // The given values, as a first block.
    const given = document.createElement('details');
    given.className = 'group given';
    const givenTitle = document.createElement('summary');
    givenTitle.textContent = t('page_given');
    given.append(givenTitle);
    for (const item of header.given || []) given.append(this.givenRow(item, full));
    for (const group of givenGroups) {
      const line = document.createElement('div');
      line.className = 'given-group';
      const name = document.createElement('span');
      name.textContent = `${group.title}: `;
      line.append(name);
      for (const item of group.values || []) line.append(this.givenRow(item, full));
      given.append(line);
    }
    this.container.append(given);

    // One block per group, nested as the trace nests them.
    const blocks = new Map();
    const groups = view.groups || [];
    const blockOf = (index) => {
      if (index < 0 || index >= groups.length) return this.container;
      if (blocks.has(index)) return blocks.get(index);
      const group = groups[index];
      const details = document.createElement('details');
      details.open = true;
      details.className = `group group-${group.kind}`;
      const summary = document.createElement('summary');
      summary.textContent = group.title;
      details.append(summary);
      blockOf(group.parent).append(details);
      blocks.set(index, details);
      for (const g of givenGroups)
        if (g.kind === group.kind && g.index === group.index)
          for (const item of g.values || []) learnGiven(item);
      return details;
    };

    // Inside an object's block, S, r, Q, n are that object's (learned as the
    // block opens); after the objects, the hit object's again.
    const hit = /^(sphere|plane) (\d+)$/.exec(view.hit_object || '');
    const hitGiven = hit ? givenGroups.find((g) => g.kind === hit[1] && g.index === Number(hit[2])) : null;
    const inObject = (group) => {
      for (let g = group; g >= 0 && g < groups.length; g = groups[g].parent)
        if (groups[g].kind === 'sphere' || groups[g].kind === 'plane') return true;
      return false;
    };
    let objectsLearned = false;
    view.steps.forEach((step, index) => {
      if (inObject(step.group)) objectsLearned = true;
      else if (objectsLearned && hitGiven) {
        for (const item of hitGiven.values || []) learnGiven(item);
        objectsLearned = false;
      }
      const parent = blockOf(step.group); // opens the block, learning its givens
      const row = document.createElement('div');
      row.className = 'step';
      row.dataset.index = String(index);
      row.dataset.key = step.key;
      row.dataset.kind = step.kind;
      row.style.setProperty('--quantity', quantityColour(step.key));
      const number = document.createElement('span');
      number.className = 'n';
      number.textContent = String(step.n);
      const symbol = document.createElement('span');
      symbol.className = 'sym';
      if (step.symbol_tex) typeset(symbol, step.symbol_tex);
      else symbol.textContent = step.symbol || step.key;
      const body = document.createElement('div');
      body.className = 'body';
      if (step.formula_tex) {
        const formula = document.createElement('div');
        formula.className = 'formula';
        typeset(formula, step.formula_tex);
        body.append(formula);
        const numbers = withNumbers(step.formula_tex, known);
        if (numbers) {
          const filled = document.createElement('div');
          filled.className = 'numbers';
          typeset(filled, `{}= ${numbers}`);
          body.append(filled);
        }
      } else if (step.formula_text) {
        const formula = document.createElement('div');
        formula.className = 'formula';
        formula.textContent = step.formula_text;
        body.append(formula);
      }
      const result = document.createElement('div');
      result.className = 'value';
      const value = document.createElement('span');
      value.className = 'v';
      value.dataset.full = `= ${step.value_full}`;
      value.dataset.shown = `= ${step.value_shown}`;
      value.title = step.value_full;
      value.textContent = full ? value.dataset.full : value.dataset.shown;
      result.append(value);
      if (step.digits_lost_text) {
        const lost = document.createElement('span');
        lost.className = step.alarm ? 'lost alarm' : 'lost';
        lost.textContent = step.digits_lost_text;
        result.append(' ', lost);
      }
      body.append(result);
      if (step.description) {
        const description = document.createElement('div');
        description.className = 'desc';
        description.textContent = step.description;
        body.append(description);
      }
      row.append(number, symbol, body);
      parent.append(row);
      this.rows.push(row);
      if (step.symbol_tex) {
        const components = step.components_shown || null;
        learn(step.symbol_tex, step.value_shown, components);
        // The program's name on the formula's left (C for E·S, D for N·K).
        const name = step.formula_tex ? /^\s*([A-Za-z])\s*=/.exec(step.formula_tex) : null;
        if (name && name[1] !== step.symbol_tex) learn(name[1], step.value_shown, components);
        if (/^[A-Z](_P)?$/.test(step.symbol_tex)) learn(`\\vec{${step.symbol_tex}}`, step.value_shown, components);
      }
    });

    // The branch taken and why, and the result.
    const branch = document.createElement('p');
    branch.className = `branch branch-${view.branch}`;
    branch.textContent = t('page_branch', { branch: view.branch_name });
    const reason = document.createElement('p');
    reason.className = 'reason';
    reason.textContent = t('page_reason', { reason: view.reason });
    const result = document.createElement('p');
    result.className = 'result';
    const value = document.createElement('span');
    value.className = 'v';
    value.dataset.full = t('page_result', { value: view.I_P_full });
    value.dataset.shown = t('page_result', { value: view.I_P_shown });
    value.title = view.I_P_full;
    value.textContent = full ? value.dataset.full : value.dataset.shown;
    result.append(value);
    this.outcome.append(branch, reason, result);
    for (const note of view.notes || []) {
      const line = document.createElement('p');
      line.className = 'note';
      line.textContent = note;
      this.outcome.append(line);
    }
  }

  givenRow(item, full) {
    const row = document.createElement('span');
    row.className = 'given-item';
    const symbol = document.createElement('span');
    typeset(symbol, item.symbol_tex || item.key);
    const value = document.createElement('span');
    value.className = 'v';
    value.dataset.full = ` = ${item.value_full}`;
    value.dataset.shown = ` = ${item.value_shown}`;
    value.title = item.value_full;
    value.textContent = full ? value.dataset.full : value.dataset.shown;
    row.append(symbol, value);
    return row;
  }

  setFull(full) {
    for (const root of [this.container, this.outcome])
      for (const value of root.querySelectorAll('.v[data-full]'))
        value.textContent = full ? value.dataset.full : value.dataset.shown;
  }

  // Marks step k (0-based) current, those before it done.
  setStep(k) {
    this.rows.forEach((row, index) => {
      row.classList.toggle('current', index === k);
      row.classList.toggle('done', index < k);
      row.classList.toggle('future', index > k);
    });
    const row = this.rows[k];
    if (!row) return;
    for (let block = row.parentElement; block && block !== this.container; block = block.parentElement)
      if (block.tagName === 'DETAILS') block.open = true;
    // Scroll the steps' box only, never the page (the header stays in view).
    const box = this.container;
    const top = row.getBoundingClientRect().top - box.getBoundingClientRect().top + box.scrollTop;
    if (top < box.scrollTop || top + row.offsetHeight > box.scrollTop + box.clientHeight)
      box.scrollTop = Math.max(0, top - box.clientHeight / 3);
  }
}
