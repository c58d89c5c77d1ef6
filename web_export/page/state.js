// The page's state, kept in the URL fragment (#p=3,4&s=16&lang=pl&...) so a
// link reopens the same view; the language is also remembered in the
// browser. Every view is redrawn from this one state.
export const reals = ['float', 'double', 'quad'];
export const formulas = ['article', 'stable', 'fma', 'geometric'];
export const spps = [1, 4, 9, 16, 64];

export function defaultState(lang) {
  return {
    pixel: null, // [i, j]
    step: 0, // 0-based index into the derivation's steps
    lang,
    atlas: false,
    real: 'double',
    formula: 'article',
    spp: 1,
    compare: '', // "quad,geometric" or ""
    full: false,
    useFile: true,
    scene: null, // an edited scene's text (the scene panel), null: the exported one
    w: null, // the pane's size when not the exported one
    // The lessons section (lessons.js): the lesson shown, the pixel it follows
    // (null: its own), its step in step mode (0: not in step mode), worksheet mode.
    lesson: null,
    lessonPixel: null,
    lessonStep: 0,
    worksheet: false,
  };
}

// Reads the fragment over `state`; values that make no sense are ignored.
export function readFragment(state, hash, exportedW) {
  const params = new URLSearchParams(hash.replace(/^#/, ''));
  const fragmentW = params.get('w');
  state.w = fragmentW && /^\d+$/.test(fragmentW) && Number(fragmentW) >= 1 ? Number(fragmentW) : null;
  const w = state.w || exportedW;
  // An edited scene: its text as base64url of its UTF-8 bytes (the loader
  // checks it when the page opens it).
  const scene = params.get('scene');
  state.scene = null;
  if (scene) {
    try {
      state.scene = fromBase64Url(scene);
    } catch {
      state.scene = null;
    }
  }
  const p = params.get('p');
  if (p && /^\d+,\d+$/.test(p)) {
    const [i, j] = p.split(',').map(Number);
    if (i < w && j < w) state.pixel = [i, j];
  }
  const s = params.get('s');
  if (s && /^\d+$/.test(s)) state.step = Number(s);
  const lang = params.get('lang');
  if (lang === 'pl' || lang === 'en') state.lang = lang;
  if (params.get('atlas') === '1') state.atlas = true;
  const real = params.get('real');
  if (reals.includes(real)) state.real = real;
  const formula = params.get('formula');
  if (formulas.includes(formula)) state.formula = formula;
  const spp = Number(params.get('spp'));
  if (spps.includes(spp)) state.spp = spp;
  const compare = params.get('cmp');
  if (compare) {
    const [r, f] = compare.split(',');
    if (reals.includes(r) && formulas.includes(f)) state.compare = `${r},${f}`;
  }
  if (params.get('full') === '1') state.full = true;
  if (params.get('file') === '0') state.useFile = false;
  // The lessons section: l=NAME (the section checks it against its list),
  // lp=I,J (the page's pixel it follows), ls=K (step mode at step K), lw=1.
  const lesson = params.get('l');
  state.lesson = lesson && /^[\w.-]{1,100}$/.test(lesson) ? lesson : null;
  const lp = params.get('lp');
  state.lessonPixel = lp && /^\d+,\d+$/.test(lp) ? lp.split(',').map(Number) : null;
  const ls = params.get('ls');
  state.lessonStep = ls && /^\d{1,6}$/.test(ls) ? Number(ls) : 0;
  state.worksheet = params.get('lw') === '1';
  return state;
}

export function writeFragment(state) {
  const params = new URLSearchParams();
  if (state.pixel) {
    params.set('p', state.pixel.join(','));
    params.set('s', String(state.step));
  }
  params.set('lang', state.lang);
  if (state.atlas) params.set('atlas', '1');
  if (state.real !== 'double') params.set('real', state.real);
  if (state.formula !== 'article') params.set('formula', state.formula);
  if (state.spp !== 1) params.set('spp', String(state.spp));
  if (state.compare) params.set('cmp', state.compare);
  if (state.full) params.set('full', '1');
  if (!state.useFile) params.set('file', '0');
  if (state.w) params.set('w', String(state.w));
  if (state.lesson) {
    params.set('l', state.lesson);
    if (state.lessonPixel) params.set('lp', state.lessonPixel.join(','));
    if (state.lessonStep > 0) params.set('ls', String(state.lessonStep));
    if (state.worksheet) params.set('lw', '1');
  }
  if (state.scene !== null) params.set('scene', toBase64Url(state.scene));
  const hash = '#' + params.toString().replace(/%2C/g, ',');
  if (location.hash !== hash) history.replaceState(null, '', hash);
}

export function rememberedLanguage() {
  try {
    const lang = localStorage.getItem('promyk.lang');
    return lang === 'pl' || lang === 'en' ? lang : null;
  } catch {
    return null; // storage refused (a private window, a strict setting)
  }
}

export function rememberLanguage(lang) {
  try {
    localStorage.setItem('promyk.lang', lang);
  } catch {
    // not remembered: the fragment still carries it
  }
}

// base64url (RFC 4648 §5, no padding) of a text's UTF-8 bytes, and back.
export function toBase64Url(text) {
  const bytes = new TextEncoder().encode(text);
  let binary = '';
  for (let k = 0; k < bytes.length; k += 0x8000) binary += String.fromCharCode(...bytes.subarray(k, k + 0x8000));
  return btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

export function fromBase64Url(text) {
  const binary = atob(text.replace(/-/g, '+').replace(/_/g, '/'));
  const bytes = new Uint8Array(binary.length);
  for (let k = 0; k < binary.length; ++k) bytes[k] = binary.charCodeAt(k);
  return new TextDecoder('utf-8', { fatal: true }).decode(bytes);
}
