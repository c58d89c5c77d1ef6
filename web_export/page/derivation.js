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

// A value as the page shows it: 4 digits, or every digit with "full digits"
// (the full text is also the hover's title). Texts from the C++ formatter.
function valueSpan(full, shown, showFull, word = (text) => `= ${text}`) {
  const value = document.createElement('span');
  value.className = 'v';
  value.dataset.full = word(full);
  value.dataset.shown = word(shown);
  value.title = full;
  value.textContent = showFull ? value.dataset.full : value.dataset.shown;
  return value;
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
    const header = view.header || {};
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
      return details;
    };

    view.steps.forEach((step, index) => {
      const parent = blockOf(step.group);
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
        // The same formula with the pixel's numbers put in, made by the C++
        // view (trace/formula_numbers.hpp) from the formatter's texts.
        if (step.numbers_tex) {
          const filled = document.createElement('div');
          filled.className = 'numbers';
          typeset(filled, `{}= ${step.numbers_tex}`);
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
      result.append(valueSpan(step.value_full, step.value_shown, full));
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
    result.append(valueSpan(view.I_P_full, view.I_P_shown, full, (value) => t('page_result', { value })));
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
    row.append(symbol, valueSpan(item.value_full, item.value_shown, full, (text) => ` = ${text}`));
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
